// The lines' closed-form blocks that couple a line's end node to the dofs of the body its end is
// on (mechanics/line_jacobian.hpp): equal to central differences of the stage's accelerations, for
// a buoy on two sliders and for a float on a free joint with its lines at points off its centre
// (the rotation's omega x p), and present only where an end is on a body.
#include "mechanics/line_jacobian.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "dynamics/configuration.hpp"
#include "tests/mechanics/mechanics_fixture.hpp"

using namespace yardsim;
using testing::buildFromScene;
using testing::mooredBuoyScene;
using testing::StagedSystem;

namespace {

// () => a 200 t float on a free joint, turned, with three lumped chains of 8 segments at points
// off its centre, no gravity on the bodies (the lines keep their own weight)
std::string floatScene() {
  std::string s = R"(schema_version: 1
integrator: {method: hht, dt: 0.05, stiffness_check: off}
mechanics:
  gravity: [0, 0, 0]
  bodies:
    float: {parent: world, joint: {type: free, q0: {xyz: [0, 0, 39], rpy_deg: [5, -3, 20]}},
            mass: 2.0e5, inertia: [2.0e6, 3.0e6, 4.0e6]}
  mooring:
)";
  const char* points[] = {"[10, 5, 0]", "[-8, 6, 1]", "[0, -7, -1]"};
  for (int k = 0; k < 3; ++k) {
    const double a = k * 2.0 * M_PI / 3.0 + 0.3;
    s += "    line" + std::to_string(k) + ": {model: lumped, anchor: [" +
         std::to_string(290.0 * std::cos(a)) + ", " + std::to_string(290.0 * std::sin(a)) +
         ", 0], fairlead: {body: float, point: " + points[k] +
         "}, length: 314, EA: 1.2e9, mass: 282.21, diameter: 0.216, segments: 8}\n";
  }
  return s + "until: 1\n";
}

}  // namespace

TEST_CASE("a line's end node is coupled to its body's dofs in closed form") {
  for (const std::string& scene : {mooredBuoyScene(), floatScene()}) {
    StagedSystem b(buildFromScene(scene));
    const auto& m = b.model();
    const dynamics::JacobianBlocks* blocks = b.data.kernel.jacobianBlocks();
    REQUIRE(blocks != nullptr);
    // (per line one end on the body, one node next to it, every dof of the body's chain)
    const int rigid = m.nv - 3 * 7 * static_cast<int>(scene == floatScene() ? 3 : 4);
    CHECK(static_cast<int>(blocks->columns.size()) == (scene == floatScene() ? 3 : 4) * rigid);
    // (a state off rest, at rest in v: the drag's dependence on the positions is left out of
    // the blocks on purpose and vanishes there) => the blocks and the central differences
    Eigen::VectorXd q(m.nq), v = Eigen::VectorXd::Zero(m.nv), delta(m.nv);
    for (int i = 0; i < m.nv; ++i) delta[i] = 0.02 * std::sin(1.0 + 3.0 * i);
    dynamics::integrate(m, b.system.description().q0, delta, 1.0, q);
    const std::size_t squares = blocks->at.size();
    std::vector<Eigen::Matrix3d> dq(squares + blocks->columns.size(), Eigen::Matrix3d::Zero());
    std::vector<Eigen::Matrix3d> dv = dq;
    b.data.kernel.blockJacobian(0.0, q, v, dq, dv);
    Eigen::VectorXd ap(m.nv), am(m.nv), qp(m.nq), qm(m.nq), step(m.nv);
    double largest = 0.0;
    for (std::size_t k = 0; k < blocks->columns.size(); ++k) {
      const auto [r0, c0] = blocks->columns[k];
      INFO("scene " << (scene == floatScene() ? "float" : "buoy") << ", rows " << r0 << ", column "
                    << c0);
      const double h = 1e-5;
      step.setZero();
      step[c0] = h;
      dynamics::integrate(m, q, step, 1.0, qp);
      dynamics::integrate(m, q, step, -1.0, qm);
      b.data.kernel.acceleration(0.0, qp, v, ap);
      b.data.kernel.acceleration(0.0, qm, v, am);
      const Eigen::Vector3d fq = (ap - am).segment<3>(r0) / (2.0 * h);
      Eigen::VectorXd vp = v, vm = v;
      vp[c0] += h;
      vm[c0] -= h;
      b.data.kernel.acceleration(0.0, q, vp, ap);
      b.data.kernel.acceleration(0.0, q, vm, am);
      const Eigen::Vector3d fv = (ap - am).segment<3>(r0) / (2.0 * h);
      CHECK((dq[squares + k].col(0) - fq).norm() <= 1e-5 * std::max(1.0, fq.norm()));
      CHECK((dv[squares + k].col(0) - fv).norm() <= 1e-5 * std::max(1.0, fv.norm()));
      largest = std::max(largest, fq.norm());
    }
    // (the couplings are not all zero: the chains are taut at the buoy)
    CHECK(largest > 1.0);
  }
}
