#pragma once
#include "scene/scene.hpp"
