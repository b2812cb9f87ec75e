#pragma once
// Error against run time (`yardsim wp SCENE.yaml -o OUTDIR`, docs/numerics.md): the scene is
// run with each integrator of its `wp:` sweep, sampled on a common output grid, and compared
// with a reference run (a tight run of a different method, itself checked against a second
// one). Per run: the error norms over the scene's error channels, the largest loop residual,
// the integrator's work (steps, right-hand-side = ABA evaluations, ...), the median wall time
// of repeated runs after a warm-up, and whether it blew up.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "studies/work_precision_reader.hpp"

namespace yardsim::studies {

using scene::Scene;

// One run sampled on the grid: values[k][c] for grid time k and error channel c, until the
// end or a numerical failure.
struct WpSeries {
  std::vector<std::vector<double>> values;
  double gMax = 0.0;  // largest loop residual seen on the grid (0 without loops)
  bool ok = true;
  std::string failure;  // the numerical failure's message
  std::uint64_t steps = 0, fEvals = 0, jacEvals = 0, newtonIts = 0, errFails = 0;
  double wall = 0.0;  // s, the simulation (not the assembly)
};

// (scene, run, spec) => the run on the grid; the scene's integrator is set for the run and
// restored; a numerical failure ends the series early (ok = false)
WpSeries runOnGrid(Scene& scene, const WpRun& run, const WpSpec& spec);

struct ErrorNorms {
  double final = 0.0, rms = 0.0, max = 0.0;  // of e_k = |y_k - y_ref,k| (Euclidean over channels)
};
// (run, reference) => the norms over the grid times both reached
ErrorNorms errorNorms(const WpSeries& run, const WpSeries& reference);

struct WpRow {
  WpRun run;
  double omegaDt = 0.0;  // omega_max times the (mean) step
  WpSeries series;       // values dropped after measuring; counters and wall kept
  ErrorNorms error;
  double wallMedian = 0.0;
  std::string status;    // ok | blow-up
};

struct WpResult {
  std::string scene;
  double omegaMax = 0.0;  // rad/s, the stiffness estimate (largest over the mechanical systems)
  std::vector<WpRow> rows;
  ErrorNorms referenceCheck;  // the check run against the reference
};

// (scene, spec, per-run log line) => every run of the sweep measured
WpResult workPrecision(Scene& scene, const WpSpec& spec,
                       const std::function<void(const std::string&)>& log = {});

}  // namespace yardsim::studies
