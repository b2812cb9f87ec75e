// The mass matrix: symmetric positive definite, 1/2 v^T M v equals the kinetic energy summed body
// by body, its columns are RNEA responses to unit accelerations, and M times ABA's response to a
// unit force is that force (ABA never forms M).
#include <catch2/catch.hpp>

#include <Eigen/Cholesky>

#include "dynamics/aba.hpp"

#include "dynamics/configuration.hpp"
#include "dynamics/crba.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/rnea.hpp"
#include "dynamics/tree_cholesky.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("CRBA: symmetric positive definite, kinetic energy, unit-acceleration columns") {
  std::mt19937 rng(18);
  for (int n : {1, 4, 9, 20, -1, -4, -9}) {
    // negative n: |n| bodies, every other one with a full 6x6 added mass
    Model m = randomTree(rng, std::abs(n), {0.0, 0.0, -9.81}, n < 0);
    m.gravity.setZero();
    Data d(m);
    const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv);
    const Eigen::MatrixXd M = crba(m, d, q);
    CHECK((M - M.transpose()).cwiseAbs().maxCoeff() == 0.0);
    CHECK(choleskyFactor(m, d));
    CHECK(0.5 * v.dot(M * v) == Approx(kineticEnergy(m, d, q, v)).epsilon(1e-12));
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m.nv);
    for (int k = 0; k < m.nv; ++k) {
      Eigen::VectorXd e = zero;
      e[k] = 1.0;
      CHECK(relativeError(rnea(m, d, q, zero, e), M.col(k)) < 1e-12);
    }
  }
}

TEST_CASE("a single free body has M = its spatial inertia in the body frame") {
  ModelBuilder b;
  std::mt19937 rng(19);
  const SpatialInertia I = randomInertia(rng);
  b.addBody("block", "world", Joint::free(), {}, I);
  const Model m = b.build();
  Data d(m);
  const Eigen::VectorXd q = randomConfiguration(m, rng);
  CHECK(relativeError(crba(m, d, q), I.matrix()) < 1e-13);
}

TEST_CASE("a single free body with added mass has M = its inertia + the added mass in the body frame") {
  ModelBuilder b;
  std::mt19937 rng(21);
  const SpatialInertia I = randomInertia(rng);
  const Matrix6 A = randomAddedMass(rng);
  b.addBody("float", "world", Joint::free(), {}, I);
  b.setAddedMass("float", A);
  const Model m = b.build();
  Data d(m);
  const Eigen::VectorXd q = randomConfiguration(m, rng);
  CHECK(relativeError(crba(m, d, q), I.matrix() + A) < 1e-13);
}

namespace {

// (model, two Data with the same added mass, q) => M of crba against RNEA's force for a unit
// acceleration of each dof, M times ABA's acceleration for a unit force, and the tree solve
// against Eigen's dense LLT
void checkColumns(const Model& m, Data& d, Data& other, const Eigen::VectorXd& q,
                  std::mt19937& rng) {
  const Eigen::MatrixXd M = crba(m, d, q);
  // crba's other outputs, X_WB and S_W, against forward kinematics and X_WB S column by column
  forwardKinematics(m, other, q);
  for (int i = 1; i < m.nbodies; ++i) {
    CHECK(relativeError(d.X_WB[i].R, other.X_WB[i].R) < 1e-14);
    CHECK(relativeError(d.X_WB[i].p, other.X_WB[i].p) < 1e-14);
    for (int k = 0; k < m.jointNv[i]; ++k) {
      const Motion s = other.X_WB[i].actMotion(other.S[i].col(k));
      CHECK(relativeError(d.S_W.col(m.idxV[i] + k), s) < 1e-14);
    }
  }
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m.nv);
  for (int k = 0; k < m.nv; ++k) {
    Eigen::VectorXd e = zero;
    e[k] = 1.0;
    CHECK(relativeError(rnea(m, other, q, zero, e), M.col(k)) < 1e-12);
    const Eigen::VectorXd x = aba(m, other, q, zero, e);
    CHECK((M * x - e).norm() <= 1e-12 * M.norm() * x.norm());
  }
  REQUIRE(choleskyFactor(m, d));
  const Eigen::VectorXd b = randomVectorX(rng, m.nv);
  Eigen::VectorXd x = b;
  choleskySolveInPlace(m, d, x);
  const Eigen::LLT<Eigen::MatrixXd> llt(M);
  REQUIRE(llt.info() == Eigen::Success);
  CHECK((x - llt.solve(b)).norm() <= 1e-9 * x.norm());
}

// (rng) => three roots: a floating base with a branch (body 1: crba's floating-base form), a
// fixed-base chain and a second floating body with two children beside it (their dofs' rows end
// at the world, not at body 1's)
Model threeRoots(std::mt19937& rng) {
  ModelBuilder b;
  const auto body = [&](const std::string& name, const std::string& parent, const Joint& j) {
    b.addBody(name, parent, j, Transform::translation(randomVector(rng)), randomInertia(rng));
  };
  body("base", "world", Joint::free());
  body("arm", "base", Joint::revolute(Vector3::UnitX()));
  body("slide", "arm", Joint::prismatic(Vector3::UnitY()));
  body("post", "world", Joint::revolute(Vector3::UnitZ()));
  body("boom", "post", Joint::revolute(Vector3::UnitY()));
  body("float", "world", Joint::free());
  body("hook", "float", Joint::revolute(Vector3::UnitX()));
  body("trolley", "float", Joint::prismatic(Vector3::UnitZ()));
  return b.build();
}

}  // namespace

TEST_CASE("CRBA's compact composites against RNEA and ABA column by column, and the tree solve") {
  // chains and floating-base trees of revolute, prismatic and free joints (the kernels' axis and
  // diagonal-inertia shortcuts and the general path; a floating base beside other roots): M from
  // 10-number composites, X_WB and S_W; then each
  // again with point masses at every third body origin written as added mass (as
  // mechanics::followMass writes a winched rope's node masses), which the 10 numbers carry too
  std::mt19937 rng(2811);
  std::vector<Model> models = {planarChain(8),
                               planarChain(33),
                               randomAxisTree(rng, 9, false, true),
                               randomAxisTree(rng, 33, false, false),
                               randomAxisTree(rng, 70, false, true),
                               randomTree(rng, 20),
                               threeRoots(rng)};
  for (Model& m : models) {
    m.gravity.setZero();
    for (bool pointMasses : {false, true}) {
      INFO("bodies " << m.nbodies - 1 << " dofs " << m.nv << " point masses " << pointMasses);
      Data d(m), other(m);
      if (pointMasses) {
        for (int i = 2; i < m.nbodies; i += 3) {
          for (Data* x : {&d, &other}) {
            x->addedMass[i].setZero();
            x->addedMass[i].bottomRightCorner<3, 3>().diagonal().setConstant(0.5 + 0.1 * i);
            x->hasAddedMass[i] = 1;
          }
        }
      }
      checkColumns(m, d, other, randomConfiguration(m, rng), rng);
    }
  }
}
