#include "forces/hydro/rankine_td_method.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>

#include "forces/hydro/emp_scheme.hpp"
#include "forces/hydro/rankine_td_provider.hpp"
#include "forces/hydro/surface_growth.hpp"
#include "forces/hydro/td_checks.hpp"
#include "forces/hydro/wetted_surface.hpp"

namespace yardsim::forces::hydro {
namespace {

const std::set<std::string> kSettings = {
    "truncation_radius", "first_spacing",    "max_spacing",     "growth",          "longest_period",
    "damping_width",     "damping_strength", "surface_damping", "cutoff",          "band_start",
    "band_end",          "froude_krylov",    "panel_step",      "azimuth_spacing", "beach_spacing"};

// (request, name, default; NaN: required) => the setting
double setting(const HydrodynamicsRequest& q, const std::string& name, double fallback) {
  const auto it = q.settings.find(name);
  if (it != q.settings.end()) return it->second;
  if (std::isnan(fallback))
    throw std::invalid_argument("rankine_td: missing setting '" + name +
                                "' (settings: truncation_radius, first_spacing, max_spacing in m)");
  return fallback;
}

// (request) => the hull in the world at its mean pose, the still-water level at z = 0
PanelMesh hullWorld(const HydrodynamicsRequest& q) {
  PanelMesh hull = panelMesh(*q.hull);
  for (Vector3& v : hull.vertices) {
    v = q.X_WB.R * v + q.X_WB.p;
    v.z() -= q.water.level;
  }
  return hull;
}

}  // namespace

ImpulseResponseSettings rankineTdSettings(const HydrodynamicsRequest& q) {
  for (const auto& [name, value] : q.settings)
    if (!kSettings.count(name)) throw std::invalid_argument("rankine_td: unknown setting '" + name + "'");
  if (!q.hull) throw std::invalid_argument("rankine_td: needs the hull mesh ('hull')");
  ImpulseResponseSettings s;
  FreeSurfaceSettings& fs = s.solver.freeSurface;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  fs.truncationRadius = setting(q, "truncation_radius", nan);
  fs.firstSpacing = setting(q, "first_spacing", nan);
  fs.maxSpacing = setting(q, "max_spacing", nan);
  fs.growth = setting(q, "growth", fs.growth);
  if (q.settings.count("longest_period")) {
    fs = defaultBeach(fs, setting(q, "longest_period", nan), q.water.gravity);
  } else {
    fs.dampingWidth = setting(q, "damping_width", 0.0);
    fs.dampingStrength = setting(q, "damping_strength", 0.0);
  }
  fs.surfaceDamping = setting(q, "surface_damping", 0.0);
  fs.azimuthSpacing = setting(q, "azimuth_spacing", 0.0);
  fs.beachSpacing = setting(q, "beach_spacing", 0.0);
  if (!(fs.truncationRadius > 0 && fs.firstSpacing > 0 && fs.maxSpacing >= fs.firstSpacing &&
        fs.growth >= 1 && fs.dampingWidth >= 0 && fs.dampingWidth < fs.truncationRadius &&
        fs.dampingStrength >= 0 && fs.surfaceDamping >= 0 && fs.azimuthSpacing >= 0 &&
        fs.beachSpacing >= 0))
    throw std::invalid_argument(
        "rankine_td: expected truncation_radius > 0, 0 < first_spacing <= max_spacing, growth >= "
        "1, "
        "0 <= damping_width < truncation_radius, damping_strength >= 0, surface_damping >= 0, "
        "azimuth_spacing >= 0, beach_spacing >= 0");
  s.solver.rho = q.water.density;
  s.solver.g = q.water.gravity;
  s.solver.depth = q.water.depth;
  s.solver.waterLevel = 0.0;  // (hull placed relative to the level)
  s.dt = q.dt;
  s.memory = q.memory;
  s.headings = q.headings;
  s.cutoff = setting(q, "cutoff", 0.0);
  s.bandStart = setting(q, "band_start", 0.0);
  s.bandEnd = setting(q, "band_end", 0.0);
  s.froudeKrylov = setting(q, "froude_krylov", 0.0) != 0.0;
  return s;
}

std::shared_ptr<const RankineTdModel> rankineTdModel(const HydrodynamicsRequest& q) {
  // (one model per request key) => kept for the door, the added mass and the build
  static std::mutex lock;
  static std::map<std::string, std::shared_ptr<const RankineTdModel>> built;
  const ImpulseResponseSettings s = rankineTdSettings(q);
  const PanelMesh hull_B = panelMesh(*q.hull);
  dynamics::Transform X_WB = q.X_WB;
  X_WB.p.z() -= q.water.level;
  const std::string key = impulseResponseKey(hull_B, X_WB, s);
  const std::lock_guard<std::mutex> guard(lock);
  auto& model = built[key];
  if (!model) model = std::make_shared<const RankineTdModel>(hull_B, X_WB, s.solver);
  return model;
}

EmpLimit rankineTdEmpLimit(const RankineTdModel& model) {
  // (one limit per model: the models live as long as the program) => kept for the door and guard
  static std::mutex lock;
  static std::map<const RankineTdModel*, EmpLimit> known;
  {
    const std::lock_guard<std::mutex> guard(lock);
    if (const auto it = known.find(&model); it != known.end()) return it->second;
  }
  const EmpLimit limit = empLimit(model);
  const std::lock_guard<std::mutex> guard(lock);
  return known.emplace(&model, limit).first->second;
}

MarchingStep rankineTdMarchingStep(const HydrodynamicsRequest& q) {
  const auto model = rankineTdModel(q);
  const EmpLimit limit = rankineTdEmpLimit(*model);
  return {"emp", setting(q, "panel_step", q.dt), limit.dtMax, limit.lambdaMax, model->settings().g};
}

namespace {
// (request, its settings, its model, sea) => a problem when a wave component lies above the
// excitation window's cutoff (the given one, or what the free-surface mesh resolves): the
// response's resolved frequency (checkResolvedSea, impulse_response_force.hpp, on the scene's sea)
std::optional<std::string> checkExcitationWindow(const HydrodynamicsRequest& q,
                                                 const ImpulseResponseSettings& s,
                                                 const RankineTdModel& model, const AiryWaves& sea) {
  if (q.headings.empty() || sea.size() == 0) return std::nullopt;
  const double wc = s.cutoff > 0 ? s.cutoff : resolvedFrequency(model);
  double highest = 0.0;
  for (std::size_t i = 0; i < sea.size(); ++i) highest = std::max(highest, sea.frequency(i));
  if (!(highest > wc)) return std::nullopt;
  return "rankine_td: the sea's highest component (" + std::to_string(highest) +
         " rad/s) lies above the excitation window's cutoff (" + std::to_string(wc) +
         " rad/s, " + (s.cutoff > 0 ? "given" : "what the free-surface mesh resolves") +
         "), the response's resolved frequency; set cutoff to at least " + std::to_string(highest) +
         " rad/s with a free-surface mesh that resolves it (smaller max_spacing), or leave the "
         "shorter waves out of the sea";
}

// (request, sea, whether the path convolves an excitation response) => the door's problems
std::vector<std::string> checkRankineTdPath(const HydrodynamicsRequest& q, const AiryWaves& sea,
                                            bool windowed) {
  std::vector<std::string> problems;
  ImpulseResponseSettings s;
  try {
    s = rankineTdSettings(q);
  } catch (const std::invalid_argument& e) {
    return {e.what()};
  }
  const PanelMesh hull_W = hullWorld(q);
  if (auto m = checkTruncation(hull_W, s.solver.freeSurface)) return {*m};
  try {
    double shortest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < sea.size(); ++i) shortest = std::min(shortest, sea.component(i).period);
    if (std::isfinite(shortest)) {
      const FreeSurfaceMesh surface = buildFreeSurface(wettedSurface(hull_W), s.solver.freeSurface);
      if (auto m = checkPanelSize(surface, s.solver.freeSurface, shortest, q.water.gravity))
        problems.push_back(*m);
    }
    const auto model = rankineTdModel(q);
    const double step = setting(q, "panel_step", q.dt);
    if (auto m = checkEmpStep(rankineTdEmpLimit(*model), step)) problems.push_back(*m);
    if (windowed)
      if (auto m = checkExcitationWindow(q, s, *model, sea)) problems.push_back(*m);
  } catch (const std::exception& e) {
    problems.push_back(std::string("rankine_td: ") + e.what());
  }
  return problems;
}
}  // namespace

std::vector<std::string> checkRankineTd(const HydrodynamicsRequest& q, const AiryWaves& sea) {
  return checkRankineTdPath(q, sea, false);
}

std::vector<std::string> checkRunLength(const HydrodynamicsRequest& q, double until) {
  if (!(until > 0) || !std::isfinite(until)) return {};
  try {
    const auto model = rankineTdModel(q);
    const double step = setting(q, "panel_step", q.dt);
    if (auto m = checkSurfaceGrowth(surfaceGrowth(*model, step),
                                    model->settings().freeSurface.surfaceDamping, until))
      return {"rankine_td: " + *m};
  } catch (const std::exception& e) {
    return {std::string("rankine_td: ") + e.what()};
  }
  return {};
}

namespace {
// (added mass from the panels) => its symmetric part: the discrete A_ij = -rho int psi_j N_i dS
// is symmetric only to the panel error, and the multibody model takes a symmetric one
ImpulseResponse::Matrix6 symmetric(const ImpulseResponse::Matrix6& a) { return 0.5 * (a + a.transpose()); }

// (load) => rankine_td registered as an impulse-response solver and as a time-domain method
const bool registered = [] {
  registerImpulseResponseSolver(
      {"rankine_td",
       [](const HydrodynamicsRequest& q) {
         ImpulseResponseSettings s = rankineTdSettings(q);
         const auto model = rankineTdModel(q);
         if (!s.headings.empty() && !(s.cutoff > 0)) s.cutoff = resolvedFrequency(*model);
         ImpulseResponse ir = computeImpulseResponse(*model, s);
         ir.aInf = symmetric(ir.aInf);
         return ir;
       },
       [](const HydrodynamicsRequest& q, const AiryWaves& sea) {
         return checkRankineTdPath(q, sea, true);
       }});
  registerTimeDomainMethod(
      {"rankine_td",
       [](const std::string& name, const dynamics::Model& model, int body,
          const HydrodynamicsRequest& q,
          std::shared_ptr<const AiryWaves> sea) -> std::unique_ptr<ForceProvider> {
         // (the scene's sea) => radiation + diffraction (+ Froude-Krylov with froude_krylov: 1)
         return std::make_unique<RankineTdProvider>(name, model, body, rankineTdModel(q),
                                                    setting(q, "panel_step", q.dt), std::move(sea),
                                                    rankineTdSettings(q).froudeKrylov);
       },
       checkRankineTd,
       [](const HydrodynamicsRequest& q) {
         const auto model = rankineTdModel(q);
         return symmetric(toBodyAxes(model->aInf(), model->rotation()));
       },
       checkRunLength,
       rankineTdMarchingStep});
  return true;
}();
}  // namespace

}  // namespace yardsim::forces::hydro
