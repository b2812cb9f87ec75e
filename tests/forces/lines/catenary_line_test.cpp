// The catenary line as a provider: the force and moment on the fairlead body from the 3D points
// (by hand from the 2D solution), the analytic 3x3 stiffness against finite differences of that
// force, the surge period of a body between two lines against the stiffness, the weight of a
// line hung between two bodies, the energy balance with and without sea-bed friction, refused
// input and a fairlead driven below the sea bed.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "forces/force_rig.hpp"
#include "forces/gravity.hpp"
#include "forces/lines/catenary_line.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;
using dynamics::Matrix3;

namespace {
// a chain in water: 120 kg/m in air, about 1.0 kN/m submerged; EA 7.5e8 N
CatenaryParameters chain(bool seabed, double friction = 0.0) {
  return {500.0, 7.5e8, 1020.0, seabed, friction};
}
dynamics::Model freeBody(double m) {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("barge", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(m, Vector3(40, 12, 5)));
  return b.build();
}
void place(Rig& r, const Vector3& p, double yaw) {
  r.q.head<7>() << p.x(), p.y(), p.z(), std::cos(yaw / 2), 0, 0, std::sin(yaw / 2);
}
}  // namespace

TEST_CASE("the force and moment on the fairlead body follow from the 2D solution") {
  const dynamics::Model model = freeBody(2e6);
  const Vector3 fair_B(15.0, -5.0, 1.0), anchor_W(-330.0, 220.0, -200.0);
  for (bool seabed : {false, true}) {
    CatenaryLine line("l", model, {0, anchor_W}, {1, fair_B}, chain(seabed, 0.5));
    Rig r(model, {&line});
    place(r, Vector3(2.0, -1.0, 0.5), 0.3);
    const Stage s = r.stage();
    // (by hand) => the fairlead in the world, the spans, e_h
    const Vector3 pB = s.data.X_WB[1].actPoint(fair_B), d = pB - anchor_W;
    const double xf = std::hypot(d.x(), d.y());
    const Vector3 e(d.x() / xf, d.y() / xf, 0.0);
    const CatenarySolution c = solveCatenary(chain(seabed, 0.5), xf, d.z());
    REQUIRE(c.status == CatenaryStatus::Converged);
    CHECK(c.profile == (seabed ? CatenaryProfile::TouchingDown : CatenaryProfile::Suspended));
    const Vector3 F = -c.hf * e - c.vf * Vector3::UnitZ();
    dynamics::ExternalForces f(model);
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(model.nv);
    const auto scratch = line.makeScratch();  // the warm start the next stage starts from
    Stage own = s;
    own.scratch = scratch.get();
    line.evaluate(own, f, tau);
    CHECK((f.worldFrame(1).tail<3>() - F).norm() < 1e-9 * F.norm());
    CHECK((f.worldFrame(1).head<3>() - pB.cross(F)).norm() < 1e-9 * pB.norm() * F.norm());
    CHECK(static_cast<const CatenaryLine::Scratch&>(*scratch).last.hf == c.hf);
  }
}

TEST_CASE("the 3x3 fairlead stiffness agrees with finite differences of the force") {
  const dynamics::Model model = freeBody(2e6);
  for (const CatenaryParameters& p : {chain(false), chain(true), chain(true, 0.7)}) {
    CatenaryLine line("l", model, {0, Vector3(-330.0, 220.0, -200.0)}, {1, Vector3(15, -5, 1)}, p);
    Rig r(model, {&line});
    place(r, Vector3(2.0, -1.0, 0.5), 0.3);
    const Matrix3 K = line.fairleadStiffness(r.stage());
    Matrix3 fd;
    const double h = 1e-3;
    for (int j = 0; j < 3; ++j) {
      Rig up(model, {&line}), down(model, {&line});
      up.q = down.q = r.q;
      up.q[j] += h;
      down.q[j] -= h;
      fd.col(j) = -(line.state(up.stage()).fairleadForce - line.state(down.stage()).fairleadForce) /
                  (2 * h);
    }
    CHECK((K - fd).norm() < 1e-6 * K.norm());
    if (p.friction == 0.0) CHECK((K - K.transpose()).norm() < 1e-9 * K.norm());
  }
}

TEST_CASE("a body between two lines surges at sqrt(2 k_xx / m) of the analytic stiffness") {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  const double m = 5e5;
  b.addBody("body", "world", dynamics::Joint::prismatic(Vector3::UnitX()),
            dynamics::Transform::identity(), dynamics::boxInertia(m, Vector3(20, 10, 4)));
  const dynamics::Model model = b.build();
  CatenaryLine west("w", model, {0, Vector3(-420, 0, -150)}, {1, Vector3::Zero()}, chain(true));
  CatenaryLine east("e", model, {0, Vector3(420, 0, -150)}, {1, Vector3::Zero()}, chain(true));
  Rig r(model, {&west, &east});
  const double kxx =
      west.fairleadStiffness(r.stage())(0, 0) + east.fairleadStiffness(r.stage())(0, 0);
  CHECK(kxx > 0.0);
  const double period = 2 * std::numbers::pi * std::sqrt(m / kxx);
  r.q[0] = 0.01;  // 1 cm: linear
  const double h = period / 500.0;
  double prev = r.q[0], firstUp = -1.0, lastUp = -1.0;
  int ups = 0;
  while (ups < 4) {
    r.step(h);
    if (prev < 0.0 && r.q[0] >= 0.0) {  // upward zero crossing, interpolated
      const double tc = r.t - h * r.q[0] / (r.q[0] - prev);
      if (ups == 0) firstUp = tc;
      lastUp = tc;
      ++ups;
    }
    prev = r.q[0];
  }
  CHECK((lastUp - firstUp) / 3.0 == Approx(period).epsilon(1e-5));
}

TEST_CASE("a line hung between two bodies: the two end forces sum to its weight") {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("a", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(1e5, Vector3(10, 5, 3)));
  b.addBody("b", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(1e5, Vector3(10, 5, 3)));
  const dynamics::Model model = b.build();
  const CatenaryParameters p{120.0, 1e8, 800.0, false, 0.0};
  CatenaryLine line("l", model, {1, Vector3(5, 0, 0)}, {2, Vector3(-5, 0, 0)}, p);
  Rig r(model, {&line});
  r.q << 0, 0, 0, 1, 0, 0, 0, 90, 30, 10, std::cos(0.2), 0, 0, std::sin(0.2);
  const CatenaryLineState st = line.state(r.stage());
  CHECK((st.anchorForce + st.fairleadForce + p.weight * p.length * Vector3::UnitZ()).norm() <
        1e-9 * st.fairleadForce.norm());
  // and the pair of point forces carries no net moment beyond the weight's about its centroid:
  // checked through the energy balance of the two tumbling bodies below
  Gravity up("float", Vector3(0, 0, 0.5 * p.weight * p.length / 1e5));  // holds the weight up
  Rig tumbling(model, {&line, &up});
  tumbling.q = r.q;
  tumbling.v << 0.02, -0.01, 0.03, 0.5, -0.2, 0.1, -0.01, 0.02, 0.01, -0.3, 0.4, 0.2;
  const double scale = tumbling.energy();
  const Rig::Balance bal = tumbling.energyBalance(0.01, 1000);
  CHECK(bal.maxWork == 0.0);
  CHECK(bal.maxError < 1e-9 * std::abs(scale));
}

TEST_CASE(
    "energy balance of a moored body: conservative without friction, friction's work with it") {
  const double m = 2e6;
  const dynamics::Model model = freeBody(m);
  for (double cb : {0.0, 1.0}) {
    std::vector<CatenaryLine*> lines;
    CatenaryLine l1("l1", model, {0, Vector3(-420, -30, -150)}, {1, Vector3(-20, -6, 0)},
                    chain(true, cb));
    CatenaryLine l2("l2", model, {0, Vector3(420, -30, -150)}, {1, Vector3(20, -6, 0)},
                    chain(true, cb));
    CatenaryLine l3("l3", model, {0, Vector3(420, 30, -150)}, {1, Vector3(20, 6, 0)},
                    chain(true, cb));
    CatenaryLine l4("l4", model, {0, Vector3(-420, 30, -150)}, {1, Vector3(-20, 6, 0)},
                    chain(true, cb));
    Rig probe(model, {});
    double vf = 0.0;
    for (CatenaryLine* l : {&l1, &l2, &l3, &l4}) vf += l->state(probe.stage()).solution.vf;
    Gravity buoyancy("buoyancy", Vector3(0, 0, vf / m));  // a stand-in: holds the lines' pull
    Rig r(model, {&l1, &l2, &l3, &l4, &buoyancy});
    r.v << 0.002, 0.001, 0.003, 0.6, -0.3, 0.1;  // surge, sway, heave, small rotations
    const double kinetic0 = 0.5 * m * (0.36 + 0.09 + 0.01);
    const Rig::Balance b = r.energyBalance(0.05, 2000);  // 100 s
    if (cb == 0.0) {
      CHECK(b.maxWork == 0.0);
      CHECK(b.maxError < 1e-6 * kinetic0);
    } else {
      CHECK(b.maxWork > 10.0);  // the friction did work, J
      CHECK(b.maxError < 1e-5 * b.maxWork);
    }
  }
}

TEST_CASE("a catenary line refuses bad input, and a fairlead below the sea bed at a stage") {
  const dynamics::Model model = freeBody(1e6);
  CHECK_THROWS_AS(CatenaryLine("l", model, {0, Vector3::Zero()}, {0, Vector3::Zero()}, chain(true)),
                  std::invalid_argument);
  CHECK_THROWS_AS(CatenaryLine("l", model, {2, Vector3::Zero()}, {1, Vector3::Zero()}, chain(true)),
                  std::invalid_argument);
  CHECK_THROWS_AS(
      CatenaryLine("l", model, {1, Vector3::Zero()}, {1, Vector3(1, 0, 0)}, chain(true)),
      std::invalid_argument);  // a sea bed that would move with the anchor's body
  CatenaryParameters p = chain(true);
  p.weight = 0.0;
  CHECK_THROWS_AS(CatenaryLine("l", model, {0, Vector3::Zero()}, {1, Vector3::Zero()}, p),
                  std::invalid_argument);
  CatenaryLine line("deep", model, {0, Vector3(-400, 0, -150)}, {1, Vector3::Zero()}, chain(true));
  Rig r(model, {&line});
  place(r, Vector3(0, 0, -160), 0.0);
  dynamics::ExternalForces f(model);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(model.nv);
  CHECK_THROWS_WITH(
      line.evaluate(r.stage(), f, tau),
      Catch::Matchers::Contains("deep") && Catch::Matchers::Contains("below the sea bed"));
}
