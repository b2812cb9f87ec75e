// ARKODE ARKStep (explicit, diagonally implicit and IMEX Runge-Kutta) on the multibody state:
// the error follows the tolerance, statistics match the kind of method, roots are located,
// and the implicit variants step over a stiff mode the explicit one must resolve.
#include <catch2/catch.hpp>

#include "dynamics/integrators/arkode.hpp"
#include "integrator_cases.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

namespace {
IntegratorSpec adaptive(const std::string& method, double rtol) {
  IntegratorSpec s = specOf(method);
  s.rtol = rtol;
  s.atol = rtol * 1e-2;
  return s;
}
}  // namespace

TEST_CASE("ARKODE ERK, DIRK and IMEX reach their tolerance on a tree with a free joint") {
  const SmoothTree p;
  for (const char* method : {"arkode_erk", "arkode_dirk", "arkode_imex"}) {
    INFO(method);
    const double loose = p.error(adaptive(method, 1e-5), 1), tight = p.error(adaptive(method, 1e-9), 1);
    INFO("errors " << loose << " " << tight);
    CHECK(loose < 1e-3);
    CHECK(tight < 1e-7);
    CHECK(tight < loose / 100);
    Arkode ark(p.model, adaptive(method, 1e-8));
    MultibodySystem sys(p.model);
    Eigen::VectorXd q = p.q0, v = p.v0;
    double t = 0.0;
    ark.step(sys, t, q, v, p.T);
    CHECK(ark.stats().steps > 3);
    CHECK(ark.stats().f_evals >= 4 * ark.stats().steps);
    if (std::string(method) == "arkode_erk") {
      CHECK(ark.stats().newton_its == 0);
      CHECK(ark.stats().jac_evals == 0);
    } else {
      CHECK(ark.stats().newton_its >= ark.stats().steps);
      CHECK(ark.stats().jac_evals >= 1);
    }
  }
}

TEST_CASE("ARKODE root finding locates a falling mass passing 1 m below its start at sqrt(2/g)") {
  for (const char* method : {"arkode_erk", "arkode_dirk", "arkode_imex"}) {
    INFO(method);
    FallingMass fall;
    Arkode ark(fall.model, adaptive(method, 1e-10));
    ark.findRoots(true);
    Eigen::VectorXd q = Eigen::VectorXd::Zero(1), v = Eigen::VectorXd::Zero(1);
    double t = 0.0;
    ark.step(fall, t, q, v, 1.0);
    CHECK(ark.lastEvent() == 0);
    CHECK(t == Approx(std::sqrt(2.0 / 9.81)).epsilon(1e-9));
    CHECK(v[0] == Approx(-std::sqrt(2.0 * 9.81)).epsilon(1e-9));
  }
}

TEST_CASE("ARKODE DIRK and IMEX follow a slow motion through a stiff mode that ERK must resolve") {
  Oscillator osc(1e4, 1.0);
  osc.forcing = 1.0;
  auto steps = [&](const char* method) {
    Arkode ark(osc.model, adaptive(method, 1e-6));
    Eigen::VectorXd q = Eigen::VectorXd::Ones(1), v = Eigen::VectorXd::Zero(1);
    double t = 0.0;
    ark.step(osc, t, q, v, 1.0);
    CHECK(q[0] == Approx(osc.steadyState(1.0)).margin(1e-5));
    return ark.stats().steps;
  };
  const long erk = steps("arkode_erk"), dirk = steps("arkode_dirk"), imex = steps("arkode_imex");
  INFO("ERK " << erk << ", DIRK " << dirk << ", IMEX " << imex);
  CHECK(erk > 3000);  // omega h below its stability bound (about 3 on the negative real axis)
  CHECK(dirk < erk);
  CHECK(imex < erk);
}
