// The added mass following the draft (forces/hydro/draft_added_mass.hpp): the table's A-infinity
// at each draft against the panel solver called directly on the hull placed elsewhere in the
// plane; linear interpolation from the dry hull; the momentum force -A' V against a finite
// difference of the fluid's momentum A V along the motion while the body enters, none while it
// leaves, and the energy: the power reported is half the entry force's power (the other half is
// the change of 1/2 V.A V that A' makes by itself), and that change alone while it leaves.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "dynamics/added_mass.hpp"
#include "dynamics/external_forces.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/model_builder.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/hydro/added_mass.hpp"
#include "forces/hydro/draft_added_mass.hpp"

using namespace yardsim;
using dynamics::Matrix6;
using dynamics::Vector3;
using forces::hydro::DraftAddedMass;
using forces::hydro::DraftAddedMassTable;

namespace {

constexpr double kRho = 1025.0;

// a 20 x 8 x 4 m box barge, body origin at mid-depth (its keel at z = -2 in the body frame)
forces::hydro::PanelMesh box() {
  return forces::hydro::panelMesh(forces::boxMesh(Vector3(20, 8, 4), 10, 4, 4));
}

std::shared_ptr<const DraftAddedMassTable> table(const std::vector<double>& drafts) {
  return std::make_shared<const DraftAddedMassTable>(
      forces::hydro::draftAddedMassTable(box(), dynamics::Matrix3::Identity(), drafts, kRho, 0.0));
}

// (one body on a translation joint) => its model
dynamics::Model oneBody() {
  dynamics::ModelBuilder b;
  b.addBody("barge", "world", dynamics::Joint::translation(), dynamics::Transform::identity(),
            dynamics::makeInertia(4.0e5, Vector3::Zero(), Vector3(2e6, 1.4e7, 1.5e7).asDiagonal()));
  return b.build();
}

}  // namespace

TEST_CASE("the table holds the panel solver's A-infinity at each draft") {
  const std::vector<double> drafts{0.5, 1.0, 2.0, 3.0};
  const auto t = table(drafts);
  REQUIRE(t->A_B.size() == drafts.size());
  // the keel point: the middle of the flat bottom
  CHECK(t->p_BK.z() == -2.0);
  CHECK(std::abs(t->p_BK.x()) < 1e-12);
  CHECK(std::abs(t->p_BK.y()) < 1e-12);
  for (std::size_t k = 0; k < drafts.size(); ++k) {
    // (the hull at draft d, 7 m east and 3 m south of the table's place) => the same matrix
    // about the body origin in body axes
    dynamics::Transform X_WB =
        dynamics::Transform::translation(Vector3(7.0, -3.0, 2.0 - drafts[k]));
    const Matrix6 A = forces::hydro::floatingAddedMass(box(), X_WB, kRho, 0.0);
    const Matrix6 direct =
        dynamics::addedMassAboutOrigin(0.5 * (A + A.transpose()), Vector3::Zero());
    INFO("draft " << drafts[k] << " m: A33 table " << t->A_B[k](5, 5) << " direct "
                  << direct(5, 5));
    CHECK((t->A_B[k] - direct).norm() < 1e-6 * direct.norm());  // rounding of the moved panels
  }
  // heave added mass: positive at every draft, of the order of the flat plate's rho pi/8 B^2 L
  const double plate = kRho * M_PI / 8.0 * 8.0 * 8.0 * 20.0;
  for (const auto& A : t->A_B) {
    CHECK(A(5, 5) > 0.3 * plate);
    CHECK(A(5, 5) < 1.5 * plate);
  }
}

TEST_CASE("the added mass is interpolated from the dry hull and held beyond the table") {
  const auto t = table({0.5, 1.0, 2.0});
  const dynamics::Model m = oneBody();
  const DraftAddedMass p("am", m, 1, t);
  Matrix6 A, dA;
  // dry: no added mass
  CHECK_FALSE(p.interpolate(0.0, A, dA));
  CHECK(A.isZero(0.0));
  CHECK_FALSE(p.interpolate(-1.0, A, dA));
  // below the first draft: from zero at draft 0
  REQUIRE(p.interpolate(0.2, A, dA));
  CHECK((A - 0.4 * t->A_B[0]).norm() < 1e-12 * A.norm());
  CHECK((dA - t->A_B[0] / 0.5).norm() < 1e-12 * dA.norm());
  // between drafts: linear
  REQUIRE(p.interpolate(1.5, A, dA));
  CHECK((A - 0.5 * (t->A_B[1] + t->A_B[2])).norm() < 1e-12 * A.norm());
  CHECK((dA - (t->A_B[2] - t->A_B[1])).norm() < 1e-12 * t->A_B[2].norm());
  // at a tabulated draft: that matrix exactly (a body at constant draft sees a constant matrix)
  REQUIRE(p.interpolate(1.0, A, dA));
  CHECK(A == t->A_B[1]);
  // beyond: the deepest, no slope
  REQUIRE(p.interpolate(5.0, A, dA));
  CHECK(A == t->A_B[2]);
  CHECK(dA.isZero(0.0));
  // the draft of the keel point
  CHECK(p.draft(dynamics::Transform::translation(Vector3(3, 4, 0.5))) == Approx(1.5));
}

TEST_CASE("the entry force is the rate of the fluid's momentum and its energy is accounted") {
  const auto t = table({0.5, 1.0, 2.0});
  const dynamics::Model m = oneBody();
  dynamics::Data d(m);
  const DraftAddedMass p("am", m, 1, t);
  // (going down at 0.4 m/s and sideways at 0.3 m/s at a draft of 0.7 m) => F = -A' V
  Eigen::VectorXd q(3), v(3);
  q << 1.0, 2.0, 2.0 - 0.7;
  v << 0.3, 0.0, -0.4;
  dynamics::forwardKinematics(m, d, q, v);
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(3);
  const forces::Stage st{0.0, m, d, q, v};
  p.evaluate(st, f, tau);
  const dynamics::Force F = f.bodyFrame(1);
  // (finite difference of A(d(t)) V along the motion, dd/dt = 0.4) => -d(A V)/dt at constant V
  const dynamics::Motion V = d.V_B[1];
  Matrix6 Ap, Am, dA;
  const double h = 1e-4;
  p.interpolate(0.7 + 0.4 * h, Ap, dA);
  p.interpolate(0.7 - 0.4 * h, Am, dA);
  const dynamics::Force expected = -(Ap - Am) * V / (2 * h);
  INFO("F " << F.transpose() << "\nexpected " << expected.transpose());
  CHECK((F - expected).norm() < 1e-8 * expected.norm());
  // entering, the water pushes back: an upward force against the heave velocity
  CHECK(F(5) > 0.0);
  // power: -1/2 V.A'V, half the force's own power V.F
  CHECK(p.power(st) == Approx(0.5 * V.dot(F)).epsilon(1e-12));
  CHECK(p.power(st) < 0.0);
  // (leaving the water at the same speed) => no force (the water keeps its momentum); the power
  // is the change 1/2 V.A'V of the kinetic energy that A' makes alone, < 0
  v[2] = 0.4;
  dynamics::forwardKinematics(m, d, q, v);
  dynamics::ExternalForces out(m);
  const forces::Stage leaving{0.0, m, d, q, v};
  p.evaluate(leaving, out, tau);
  CHECK(out.bodyFrame(1).isZero(0.0));
  const dynamics::Motion Vout = d.V_B[1];
  const Matrix6 AdotOut = -(Ap - Am) / (2 * h);  // dd/dt = -0.4
  CHECK(p.power(leaving) == Approx(0.5 * Vout.dot(AdotOut * Vout)).epsilon(1e-6));
  CHECK(p.power(leaving) < 0.0);
  v[2] = -0.4;
  // dry, or deeper than the table: no force
  for (const double draft : {-0.5, 2.5}) {
    q[2] = 2.0 - draft;
    dynamics::forwardKinematics(m, d, q, v);
    dynamics::ExternalForces g(m);
    p.evaluate(forces::Stage{0.0, m, d, q, v}, g, tau);
    CHECK(g.bodyFrame(1).isZero(0.0));
  }
}

TEST_CASE("bad tables are refused") {
  CHECK_THROWS_AS(table({}), std::invalid_argument);
  CHECK_THROWS_AS(table({0.0, 1.0}), std::invalid_argument);
  CHECK_THROWS_AS(table({1.0, 0.5}), std::invalid_argument);
  const dynamics::Model m = oneBody();
  CHECK_THROWS_AS(DraftAddedMass("am", m, 0, table({1.0})), std::invalid_argument);
}
