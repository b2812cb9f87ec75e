#pragma once
// Door checks of the events of a scene's mechanical systems (each system built once here, with
// its providers, only when a check needs it).
//
// Actors' `stop_on` lists (docs/scenes.md, docs/collision.md): each name
// `<element>.<kind>` (or a trailing part of one) must be an event some mechanical system of the
// scene can raise — a drive's `reached`, a rope's or equalizer's `taut`, `slack`, `over_mbl`,
// `done`, a watch's `crossed`, a provider's events (a collision set's `contact` / `release`, a
// clearance watch's `clearance_below` / `touched`). A name that matches none is refused at the
// list (file:line:col), with its key path and the valid names.
#include <string>
#include <vector>

#include "models/diagnostics.hpp"
#include "scene/scene.hpp"

namespace yardsim::scene {

// (mechanical system) => the full names `<element>.<kind>` of every event it can raise
std::vector<std::string> systemEventNames(const MechanicalSystem& system);

// (scene with its mechanical systems) => an error for each stop_on name no system can raise
void checkStopOn(const Scene& scene, models::Diagnostics& diags);

// Provider events that count one way only (a clearance watch's `clearance_below`, `touched`) and
// are already past at the initial state as given: they are located on crossings only, so they
// would stay silent until the quantity comes back and crosses again (a rope lying on a block face
// from the start). (scene) => a warning for each, with the value and the event's detail (the
// pair and witness points)
void checkEventsAtStart(const Scene& scene, models::Diagnostics& diags);

}  // namespace yardsim::scene
