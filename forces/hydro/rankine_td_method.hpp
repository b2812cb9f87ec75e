#pragma once
// The time-domain Rankine-panel solver plugged into scenes (docs/hydrodynamics.md, "Scene keys"):
// registered at load as the impulse-response solver `rankine_td` (impulse responses computed by
// the solver itself, then the Cummins convolution) and as the time-domain method `rankine_td`
// (the panel solution marched with the run). The YAML `settings:` of a `hydrodynamics:` entry:
//   truncation_radius (m, required), first_spacing (m, required), max_spacing (m, required),
//   growth (1.15), longest_period (s: a damping zone one deep-water wavelength wide, nu = 2 pi/T)
//   or damping_width (m) and damping_strength (1/s), cutoff (rad/s, excitation window w_c;
//   default: the frequency the free-surface mesh resolves), band_start and band_end (rad/s, K's
//   band limit; 0: none), froude_krylov (0: diffraction only, the default, since the body's
//   hydrostatics integrates the incident pressure; 1: Froude-Krylov + diffraction), panel_step
//   (s, the rankine_td method's own step; default: the request's dt), azimuth_spacing (m, the
//   widest panel edge along a ring inside the damping zone's inner edge; 0, the default: the
//   rays through the waterline vertices only), beach_spacing (m, ring width and azimuthal edge
//   inside the damping zone; 0, the default: max_spacing and azimuth_spacing there too).
// Units SI; the hull in the body frame, the mean pose the body's initial one.
#include <memory>

#include "forces/hydro/emp_scheme.hpp"
#include "forces/hydro/hydrodynamics_methods.hpp"
#include "forces/hydro/td_impulse_response.hpp"

namespace yardsim::forces::hydro {

// (request) => the solver's settings from its `settings:` numbers; throws std::invalid_argument
// naming a missing or unknown setting or a value out of range
ImpulseResponseSettings rankineTdSettings(const HydrodynamicsRequest& request);

// (request) => the panel model at the body's mean pose (built once per request and kept)
std::shared_ptr<const RankineTdModel> rankineTdModel(const HydrodynamicsRequest& request);

// (request, sea) => the problems found before a run: the hull through the damping zone, a
// free-surface panel longer than a tenth of the sea's shortest wave, a step above the emp limit
std::vector<std::string> checkRankineTd(const HydrodynamicsRequest& request, const AiryWaves& sea);

// (panel model) => its emp limit (emp_scheme.hpp: empLimit, 200 iterations), computed once per
// model (rankineTdModel keeps the models for the program's life)
EmpLimit rankineTdEmpLimit(const RankineTdModel& model);

// (request) => the panel step (settings.panel_step, default the request's dt) against the emp
// limit of the request's free surface: what the stiffness guard and run.json report
MarchingStep rankineTdMarchingStep(const HydrodynamicsRequest& request);

// (request, the run's end time s) => a problem when the marched free surface's short-wave modes
// grow by more than e^2 over the run (surface_growth.hpp, td_checks.hpp: checkSurfaceGrowth)
std::vector<std::string> checkRunLength(const HydrodynamicsRequest& request, double until);

}  // namespace yardsim::forces::hydro
