#pragma once
// The `wp:` block of a scene (docs/numerics.md): which channels measure the error, on which
// output grid, which integrators over which sweep, and the reference solution.
//
//   wp:
//     channels: [block.z]            # error channels (m); the error at a grid time is the
//                                    # Euclidean norm of their differences to the reference
//     interval: 0.05                 # s, the common output grid (default: record.interval)
//     until: 5                       # s (default: the scene's until)
//     methods:                       # one sweep each
//       - {method: rk4, dt0: 0.01, levels: 5}        # fixed step dt0 / 2^k, k = 0..levels-1
//       - {method: cvode_bdf, rtol: [1.0e-3, 1.0e-10], label: bdf}  # adaptive: one run per decade
//     reference: {method: rk4, dt: 1.0e-4}           # a tight run (dt or rtol), or a published
//                                                    # solution: {file: ref.csv} (time, channels)
//     check: {method: semi_implicit_euler, dt: 1.0e-5}  # a second, independent one
//     repeats: 3                     # timed runs after the warm-up; wall_median_s is their median
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "models/diagnostics.hpp"
#include "scene/scene.hpp"

namespace yardsim::studies {

using models::Diagnostics;
using scene::Scene;

// One run of the sweep: a method at one step or tolerance.
struct WpRun {
  std::string label;   // the `method` column (the method, or the entry's label)
  std::string method;  // the integrator
  double dt = 0.0;     // s, fixed-step runs
  double rtol = 0.0;   // adaptive runs (then dt is the scene's, the initial/max step)
  YAML::Node extra;    // the entry's other integrator keys (alpha, max_order, ...)
  std::string param() const;  // "dt=0.0125" or "rtol=1e-06"
};

struct WpSpec {
  std::vector<std::string> channels;
  double interval = 0.0;
  double until = 0.0;
  std::vector<WpRun> runs;  // every method's sweep, in order
  WpRun reference, check;   // check: optional with a reference file
  std::string referenceFile;  // a published reference (work_precision_reference.hpp), or ""

  int repeats = 3;
};

// (loaded scene) => its wp block read from the root file; problems (file:line:column, key
// path) in diags
WpSpec parseWpSpec(const Scene& scene, Diagnostics& diags);

}  // namespace yardsim::studies
