#pragma once
// The hooks through which the panel solvers plug into scenes (docs/hydrodynamics.md, "Scene
// keys"): a scene's `hydrodynamics:` block names a method per floating body,
//   impulse_response: the Cummins convolution (ImpulseResponseForce) of a response read from a
//     file, from the disk cache by key, or else computed by a registered ImpulseResponseSolver
//     and written to the cache;
//   rankine_td (and any other name): a registered TimeDomainMethod that builds the provider.
// Each may register a check run at the door on the request and the sea (a free-surface panel
// longer than a tenth of the shortest wave, a hull through the truncation radius, ...); its
// problems are reported at the scene's key with the numbers.
// Units: SI; the hull in the body frame B, headings in B (rad, the way the waves travel).
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "forces/airy_waves.hpp"
#include "forces/force_provider.hpp"
#include "forces/geometry/triangle_mesh.hpp"
#include "forces/hydro/impulse_response.hpp"
#include "forces/hydro/marching_step.hpp"

namespace yardsim::forces::hydro {

// What a hull's hydrodynamics is computed for, as the scene gives it
struct HydrodynamicsRequest {
  std::shared_ptr<const TriangleMesh> hull;  // body frame (nullptr: none given)
  dynamics::Transform X_WB =
      dynamics::Transform::identity();     // the body's initial pose, as its file gives it
  WaterProperties water;                   // density, gravity, depth, level
  std::vector<double> headings;            // rad, excitation headings in B
  double dt = 0.05;                        // s, response sample spacing
  double memory = 60.0;                    // s, length of the radiation memory
  std::map<std::string, double> settings;  // the method's own numbers (YAML `settings:`)
};

// (request, the scene's sea) => problems, one sentence each with its numbers; empty: fine
using HydrodynamicsCheck =
    std::function<std::vector<std::string>(const HydrodynamicsRequest&, const AiryWaves&)>;

struct ImpulseResponseSolver {
  std::string name;
  std::function<ImpulseResponse(const HydrodynamicsRequest&)> solve;
  HydrodynamicsCheck check;  // may be empty
};

struct TimeDomainMethod {
  std::string name;
  std::function<std::unique_ptr<ForceProvider>(
      const std::string& name, const dynamics::Model& model, int body,
      const HydrodynamicsRequest& request, std::shared_ptr<const AiryWaves> sea)>
      build;
  HydrodynamicsCheck check;  // may be empty
  // (request) => the infinite-frequency added mass the body carries on the left-hand side (body
  // axes about its origin, naval order), or empty when the provider needs none
  std::function<ImpulseResponse::Matrix6(const HydrodynamicsRequest&)> addedMass;
  // (request, the run's end time s) => problems with a run that long (one sentence each with its
  // numbers and a way out), checked at the door with the scene's `until` or `--until`; may be empty
  std::function<std::vector<std::string>(const HydrodynamicsRequest&, double until)> runCheck;
  // (request) => the method's own marching step and its stability limit, for the stiffness guard
  // and run.json (marching_step.hpp); may be empty (nothing marched at a step of its own)
  std::function<MarchingStep(const HydrodynamicsRequest&)> marchingStep = {};
};

// (solver) => registered under its name (a second one of that name replaces the first)
void registerImpulseResponseSolver(ImpulseResponseSolver solver);
// (name, or "" for the only one registered) => the solver, or nullptr
const ImpulseResponseSolver* impulseResponseSolver(const std::string& name);
void registerTimeDomainMethod(TimeDomainMethod method);
const TimeDomainMethod* timeDomainMethod(const std::string& name);
std::vector<std::string> impulseResponseSolverNames();

// (request, solver name) => the cache key: the solver's name and 16 hex digits of FNV-1a 64 over
// the hull's vertices and triangles, the water, headings, dt, memory and settings
std::string requestKey(const HydrodynamicsRequest& request, const std::string& solver);
// (request, solver, cache folder) => the cached response of the request's key, or the solver's,
// written to the cache (its key set to the request's); throws CacheError for a damaged cache
// file, std::runtime_error when the solver fails
std::shared_ptr<const ImpulseResponse> cachedOrSolved(const HydrodynamicsRequest& request,
                                                      const ImpulseResponseSolver& solver,
                                                      const std::filesystem::path& cacheDir);

}  // namespace yardsim::forces::hydro
