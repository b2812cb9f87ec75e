#pragma once
// Checks of a time-domain Rankine set-up before a run, for the scene door to refuse or warn
// with: each returns nothing when the set-up is fine, else one sentence with the numbers.
// Lengths m, periods and steps s; the hull in the world frame at its mean position with the
// still-water level at z = 0 (as RankineTdModel places it).
#include <optional>
#include <string>

#include "forces/hydro/emp_scheme.hpp"
#include "forces/hydro/free_surface_mesh.hpp"
#include "forces/hydro/surface_growth.hpp"

namespace yardsim::forces::hydro {

/// (hull, free-surface settings) => a message when the hull reaches the damping zone or the
/// truncation radius: its farthest point from the waterline centre (horizontally) against
/// R - dampingWidth.
std::optional<std::string> checkTruncation(const PanelMesh& hull_W,
                                           const FreeSurfaceSettings& settings);

/// (free-surface mesh, settings, shortest wave period in the sea T_min, g) => a message when a
/// free-surface panel inside the damping zone's inner edge is larger (diameter) than a tenth of
/// the shortest deep-water wave g T_min^2 / (2 pi).
std::optional<std::string> checkPanelSize(const FreeSurfaceMesh& surface,
                                          const FreeSurfaceSettings& settings,
                                          double shortestPeriod, double g = 9.80665);

/// (emp limit of the mesh, step) => a message when dt exceeds the limit 2 / sqrt(g lambda_max).
std::optional<std::string> checkEmpStep(const EmpLimit& limit, double dt);

/// The largest growth rate x run length a marched free surface may have: its free short waves grow
/// by at most e^2 = 7.4 over the run (from the start's transients, some e^-5 of the physical
/// surface on the box barge: they reach the physical level after some 5 / rate).
inline constexpr double kSurfaceGrowthLimit = 2.0;

/// (growth of the mesh's free solutions with its uniform damping nu0 (1/s) included, nu0, the run's
/// end time T s) => a message when rate T > kSurfaceGrowthLimit, with the rate, its frequency, the
/// growth factor and the uniform damping (surface_damping) that stops it.
std::optional<std::string> checkSurfaceGrowth(const SurfaceGrowth& growth, double surfaceDamping,
                                              double until);

}  // namespace yardsim::forces::hydro
