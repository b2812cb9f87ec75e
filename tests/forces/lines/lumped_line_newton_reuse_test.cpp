// The implicit methods' reuse of their Newton matrix with lumped lines, across a fast rigid change:
// HHT keeps its matrix over steps until Newton slows (seven iterations with line blocks; the
// lines' blocks are fresh at every iterate, the rigid dofs' columns age), CVODE forms its
// coloured Jacobian after a failed Newton solve or every 1000 steps (docs/integrators.md). A buoy
// moored by four lumped chains (tests/mechanics/mechanics_fixture.hpp) runs long enough for the
// matrix to age, then a step load drives it into a stiff stop of a fender spring: the rigid
// dofs' stiffness jumps by two orders of magnitude within a step. Each run is compared with the
// same method forming a fresh matrix at every step (its only difference), and the Newton
// iterations per step come back to the level before the change once the buoy rests on the stop.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "dynamics/integrators/adaptive_integrator.hpp"
#include "dynamics/integrators/factory.hpp"
#include "dynamics/integrators/generalized_alpha.hpp"
#include "tests/mechanics/mechanics_fixture.hpp"

using namespace yardsim;
using testing::buildFromScene;
using testing::mooredBuoyScene;
using testing::StagedSystem;

namespace {

// A fender: a soft spring (1e3 N/m) with a damper from a world post 1 km behind the buoy (so
// that it acts along the surge, without a sway instability), with a stop 1 m back from the
// buoy's start of 1e8 N/m: about 500 times the lines' surge stiffness
const char* kFender = R"(  springs:
    fender: {between: [{point: [-1000, 0, 39]}, {body: buoy}], k: 1000, c: 4.0e6,
             free_length: 1000, stops: {min_length: 999, max_length: 2000, k: 1.0e8}}
)";

constexpr double kStep = 0.05, kLoadAt = 30.0, kUntil = 40.0;
constexpr double kLoad = 2.0e6;  // N, toward the post: 3 m of the lines' stretch without the stop

struct Run {
  Eigen::VectorXd q, v;
  std::vector<double> x;       // the buoy's surge at every step, m
  std::vector<long> newton;    // Newton iterations of every step
  std::vector<long> matrices;  // iteration matrices formed in every step
};

// (method, a fresh matrix at every step) => the run: at rest-ish motion (released at 0.5 m/s)
// until kLoadAt, then the step load toward the fender, until kUntil
Run run(const std::string& method, bool fresh) {
  StagedSystem b(buildFromScene(mooredBuoyScene(kFender)));
  dynamics::IntegratorSpec spec;
  spec.method = method;
  spec.dt = kStep;
  auto integrator = dynamics::makeIntegrator(spec, b.model());
  if (auto* alpha = dynamic_cast<dynamics::GeneralizedAlpha*>(integrator.get()))
    alpha->refreshEveryStep(fresh);
  if (auto* adaptive = dynamic_cast<dynamics::AdaptiveIntegrator*>(integrator.get()))
    adaptive->setLinesJacobianAge(fresh ? 1 : 1000);
  Run r{b.system.description().q0, b.system.description().v0, {}, {}, {}};
  const int buoy = b.model().bodyIndex("buoy");
  REQUIRE(buoy > 0);
  double t = 0.0;
  const int steps = static_cast<int>(std::lround(kUntil / kStep));
  for (int k = 0; k < steps; ++k) {
    if (std::abs(t - kLoadAt) < 0.5 * kStep)
      b.sp.loads[static_cast<std::size_t>(buoy)].force = Eigen::Vector3d(-kLoad, 0.0, 0.0);
    const dynamics::IntegratorStats before = integrator->stats();
    integrator->step(b.data.kernel, t, r.q, r.v, kStep);
    r.x.push_back(r.q[0]);
    r.newton.push_back(integrator->stats().newton_its - before.newton_its);
    r.matrices.push_back(integrator->stats().jac_evals - before.jac_evals);
  }
  return r;
}

// (run, from t0 to t1) => its Newton iterations per step there
double newtonPerStep(const Run& r, double t0, double t1) {
  long sum = 0, n = 0;
  for (std::size_t k = 0; k < r.newton.size(); ++k) {
    const double t = (static_cast<double>(k) + 1.0) * kStep;
    if (t > t0 && t <= t1) {
      sum += r.newton[k];
      ++n;
    }
  }
  REQUIRE(n > 0);
  return static_cast<double>(sum) / static_cast<double>(n);
}

}  // namespace

TEST_CASE("lumped lines: a fast rigid change after a long reuse of the Newton matrix", "[long]") {
  for (const std::string method : {"hht", "cvode_bdf"}) {
    INFO(method);
    const Run reused = run(method, false), fresh = run(method, true);
    // (the change) => the buoy strikes the stop (x = -1 m) 2 s after the load and rests on it,
    // pressed 2 cm in by the load
    std::size_t strike = 0;
    while (strike < fresh.x.size() && fresh.x[strike] > -1.0) ++strike;
    REQUIRE(strike < fresh.x.size());
    const double tStrike = static_cast<double>(strike + 1) * kStep;
    CHECK(tStrike > kLoadAt + 1.0);
    CHECK(fresh.x.back() == Approx(-1.0 - kLoad / 1.0e8).margin(2e-3));
    // (the matrix) => the reference forms one at every step; the run under test reuses its
    // matrix over hundreds of steps before the load
    long reusedMatrices = 0;
    for (std::size_t k = 0; k < reused.matrices.size(); ++k)
      if (static_cast<double>(k) * kStep < kLoadAt) reusedMatrices += reused.matrices[k];
    CHECK(reusedMatrices < 20);
    // (trajectories) => alike to the solvers' tolerance over the whole run: HHT's Newton
    // tolerance (1e-8 of a step's motion: the same steps), CVODE's error control (rtol 1e-6 on a
    // motion of about 1 m, its steps chosen anew by each run: ten times that)
    const double tolerance = method == "hht" ? 1e-6 : 1e-5;
    double worst = 0.0;
    for (std::size_t k = 0; k < reused.x.size(); ++k)
      worst = std::max(worst, std::abs(reused.x[k] - fresh.x[k]));
    INFO("largest surge difference " << worst << " m");
    CHECK(worst < tolerance);
    CHECK((reused.q - fresh.q).lpNorm<Eigen::Infinity>() < tolerance);
    CHECK((reused.v - fresh.v).lpNorm<Eigen::Infinity>() < 1e-5);
    // (Newton, from a quarter second after the strike) => the run under test needs at most half
    // as many iterations again as the reference per step; HHT's steps stay below the seven
    // iterations that mark its matrix stale (before the fix it kept the matrix without the
    // stop's stiffness for a second, 9 to 12 iterations a step)
    const double reusedIts = newtonPerStep(reused, tStrike + 0.25, kUntil);
    const double freshIts = newtonPerStep(fresh, tStrike + 0.25, kUntil);
    INFO("Newton iterations per step after the strike: " << reusedIts << ", fresh " << freshIts);
    CHECK(reusedIts < 1.5 * freshIts);
    if (method == "hht")
      for (std::size_t k = strike + 5; k < reused.newton.size(); ++k) CHECK(reused.newton[k] < 7);
  }
}
