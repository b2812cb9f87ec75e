#pragma once
// OUTDIR/replay.glb: a replay as a glTF 2.0 binary. One node per body (named by its path, a
// mesh of its shape in the body frame; a marker, a point that lines pass through, has no mesh and
// only a translation channel), children of a root node that turns yardsim's z-up
// world into glTF's y-up; one animation "replay" with, per body, a translation and a rotation
// channel (LINEAR; time in s; rotations as unit quaternions x, y, z, w). Every accessor has min
// and max, every buffer view and chunk is 4-byte aligned. The ropes travel in the scene's
// extras: {"yardsim_ropes": [{"name", "points": [{"node": i or -1, "p": [x, y, z]}]}]}, node i
// being the i-th body.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "models/replay.hpp"

namespace yardsim::output {

using models::Replay;

// (replay) => the .glb bytes
std::vector<std::uint8_t> glbBytes(const Replay& replay);
// (replay, file) => written; throws std::runtime_error naming the file when it cannot be
void writeGlb(const Replay& replay, const std::filesystem::path& file);

}  // namespace yardsim::output
