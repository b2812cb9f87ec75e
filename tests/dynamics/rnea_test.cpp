// RNEA against independent quantities: M ddq + h from CRBA; gravity torques from the gradient of
// the potential energy; external forces equivalent in body and world frames.
#include <catch2/catch.hpp>

#include "dynamics/configuration.hpp"
#include "dynamics/crba.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/rnea.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("RNEA = M ddq + h (CRBA), on random trees with every joint type") {
  std::mt19937 rng(14);
  for (int n : {1, 5, 17, -2, -6, -17}) {
    // negative n: |n| bodies on coordinate axes in translated frames (the kernels' special case)
    const Model m = n > 0 ? randomTree(rng, n) : randomAxisTree(rng, -n);
    Data d(m);
    const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv),
                          a = randomVectorX(rng, m.nv);
    const Eigen::VectorXd h = biasForces(m, d, q, v);
    const Eigen::MatrixXd M = crba(m, d, q);
    const Eigen::VectorXd tau = rnea(m, d, q, v, a);
    CHECK(relativeError(tau, M * a + h) < 1e-10);
  }
}

TEST_CASE("RNEA = M ddq + h and RNEA(ddq = 0) = h with diagonal inertias") {
  // the kernels' shortcut for inertias diagonal about the centre of mass (Model::inertiaDiagonal)
  // in RNEA's centroidal form, biasForces' spatial form and CRBA, on coordinate-axis trees whose
  // bodies turn about every axis (a gyroscopic term taken in the wrong frame shows here)
  std::mt19937 rng(16);
  for (int n : {3, 9, 24}) {
    const Model m = randomAxisTree(rng, n, false, true);
    Data d(m);
    const Eigen::VectorXd q = randomConfiguration(m, rng), v = 3.0 * randomVectorX(rng, m.nv);
    const Eigen::VectorXd a = randomVectorX(rng, m.nv);
    const Eigen::VectorXd h = biasForces(m, d, q, v);
    const Eigen::MatrixXd M = crba(m, d, q);
    CHECK(relativeError(rnea(m, d, q, v, a), M * a + h) < 1e-10);
    CHECK(relativeError(rnea(m, d, q, v, Eigen::VectorXd::Zero(m.nv)), h) < 1e-12);
  }
}

TEST_CASE("RNEA with ddq = 0 equals the bias forces of the spatial form") {
  // rnea's inertia force is written about the centre of mass, biasForces' in spatial form
  // (rnea.cpp): two formulas for the same torques, a bias of the Coriolis, centrifugal or
  // gyroscopic terms in either shows here
  std::mt19937 rng(15);
  for (int n : {1, 6, 17, -3, -17}) {
    const Model m = n > 0 ? randomTree(rng, n) : randomAxisTree(rng, -n);
    Data d(m);
    const Eigen::VectorXd q = randomConfiguration(m, rng), v = 3.0 * randomVectorX(rng, m.nv);
    const Eigen::VectorXd h = biasForces(m, d, q, v);
    const Eigen::VectorXd tau = rnea(m, d, q, v, Eigen::VectorXd::Zero(m.nv));
    CHECK(relativeError(tau, h) < 1e-12);
  }
}

TEST_CASE("gravity torques are the gradient of the potential energy") {
  const Model m = planarChain(5);
  Data d(m);
  std::mt19937 rng(15);
  const Eigen::VectorXd q = randomVectorX(rng, m.nv, 2.0);
  const Eigen::VectorXd g = biasForces(m, d, q, Eigen::VectorXd::Zero(m.nv));
  for (int k = 0; k < m.nv; ++k) {
    Eigen::VectorXd qp = q, qm = q;
    const double h = 1e-6;
    qp[k] += h;
    qm[k] -= h;
    const double dU = (potentialEnergy(m, d, qp) - potentialEnergy(m, d, qm)) / (2 * h);
    CHECK(g[k] == Approx(dU).epsilon(1e-7).margin(1e-7));
  }
}

TEST_CASE("an external force in the world frame equals the same force in the body frame") {
  std::mt19937 rng(16);
  const Model m = randomTree(rng, 9);
  Data d(m);
  const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv),
                        a = randomVectorX(rng, m.nv);
  forwardKinematics(m, d, q);
  ExternalForces fw(m), fb(m);
  for (int i = 1; i < m.nbodies; ++i) {
    const Force F_W = randomVectorX(rng, 6);
    fw.addWorldFrame(i, F_W);
    fb.addBodyFrame(i, d.X_WB[i].invActForce(F_W));
  }
  const Eigen::VectorXd t1 = rnea(m, d, q, v, a, &fw);
  const Eigen::VectorXd t2 = rnea(m, d, q, v, a, &fb);
  CHECK(relativeError(t1, t2) < 1e-12);
}

TEST_CASE("a force at the tip of a horizontal chain needs joint torques f * lever arm") {
  const Model m = planarChain(3);
  Data d(m);
  ExternalForces f(m);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3);
  forwardKinematics(m, d, zero);
  // an upward pull of 10 N at the tip (x = 3) cancelling gravity on nothing else: gravity off
  Model mg = m;
  mg.gravity.setZero();
  f.addPointForceWorld(3, Vector3(3, 0, 0), Vector3(0, 0, 10));
  const Eigen::VectorXd tau = rnea(mg, d, zero, zero, zero, &f);
  // holding torque about +y at joint k (x = k) is -(F x r)_y = -(r x F)_y, r = (3 - k) e_x, F = 10
  // e_z: (r x F)_y = -10 (3 - k)
  for (int k = 0; k < 3; ++k) CHECK(tau[k] == Approx(10.0 * (3 - k)));
}

TEST_CASE(
    "the bias forces of some joints' subtrees, on placed kinematics, are biasForces' doubles") {
  // (random trees, random wanted joints) => the mask is closed under children and forward holds
  // their ancestors; the wanted joints' h equals biasForces' bit for bit (the same operations on
  // the same placements); every other entry keeps the value it had
  std::mt19937 rng(24);
  std::bernoulli_distribution pick(0.3);
  for (int n : {1, 6, 17, -5, -17}) {
    const Model m = n > 0 ? randomTree(rng, n) : randomAxisTree(rng, -n);
    Data full(m), kin(m), sub(m);
    const Eigen::VectorXd q = randomConfiguration(m, rng), v = 3.0 * randomVectorX(rng, m.nv);
    const Eigen::VectorXd h = biasForces(m, full, q, v);
    forwardKinematics(m, kin, q, v);
    std::vector<char> roots(static_cast<std::size_t>(m.nbodies), 0);
    for (int i = 1; i < m.nbodies; ++i) roots[static_cast<std::size_t>(i)] = pick(rng) ? 1 : 0;
    SubtreeMask mask;
    mask.mark(m, roots);
    for (int i = 1; i < m.nbodies; ++i) {
      const auto u = static_cast<std::size_t>(i), p = static_cast<std::size_t>(m.parent[i]);
      CHECK(mask.subtree[u] == ((roots[u] != 0 || (p > 0 && mask.subtree[p] != 0)) ? 1 : 0));
      if (mask.forward[u] != 0 && p > 0) CHECK(mask.forward[p] == 1);
      if (mask.subtree[u] != 0) CHECK(mask.forward[u] == 1);
    }
    sub.nle.setConstant(12345.0);
    biasForcesOfSubtrees(m, sub, kin, q, v, mask);
    for (int i = 1; i < m.nbodies; ++i)
      for (int k = 0; k < m.jointNv[i]; ++k) {
        const int iv = m.idxV[i] + k;
        INFO("body " << i << ", dof " << iv);
        if (mask.subtree[static_cast<std::size_t>(i)] != 0)
          CHECK(sub.nle[iv] == h[iv]);
        else
          CHECK(sub.nle[iv] == 12345.0);
      }
  }
}

TEST_CASE(
    "the bias forces of translational subtrees are RNEA's: each joint carries its subtree's "
    "weight") {
  // (random trees of prismatic, translation and fixed joints in rotated frames, gravity along no
  // axis, random q and v) => the mask is translational and its short path equals biasForces to
  // round-off, and a subtree's vertical prismatic joint carries its bodies' weight; a revolute
  // joint in the forward set or added mass on a subtree's body takes RNEA (bit for bit)
  std::mt19937 rng(25);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const JointType kinds[3] = {JointType::Prismatic, JointType::Translation, JointType::Fixed};
  for (int trial = 0; trial < 12; ++trial) {
    const int n = 2 + trial;
    const bool rotating = trial % 4 == 3, added = trial % 4 == 2;
    ModelBuilder b;
    b.setGravity({0.4, -1.3, -9.7});
    for (int i = 0; i < n; ++i) {
      const std::string parent = i == 0 ? "world" : indexed("b", static_cast<int>(u(rng) * i));
      const JointType t = rotating && i == 1 ? JointType::Revolute : kinds[i % 3];
      b.addBody(indexed("b", i), parent, jointOfType(t, rng),
                Transform{randomRotation(rng), randomVector(rng)}, randomInertia(rng));
    }
    if (added) b.setAddedMass(indexed("b", n - 1), randomAddedMass(rng));
    const Model m = b.build();
    Data full(m), kin(m), sub(m);
    const Eigen::VectorXd q = randomConfiguration(m, rng), v = 3.0 * randomVectorX(rng, m.nv);
    const Eigen::VectorXd h = biasForces(m, full, q, v);
    forwardKinematics(m, kin, q, v);
    std::vector<char> roots(static_cast<std::size_t>(m.nbodies), 0);
    roots[1] = 1;  // the whole tree
    SubtreeMask mask;
    mask.mark(m, roots);
    INFO("trial " << trial << (rotating ? ", a revolute joint" : "")
                  << (added ? ", added mass" : ""));
    CHECK(mask.translational == !rotating);
    sub.nle.setZero();
    biasForcesOfSubtrees(m, sub, kin, q, v, mask);
    const double scale = h.cwiseAbs().maxCoeff();
    for (int iv = 0; iv < m.nv; ++iv) {
      if (rotating || added)
        CHECK(sub.nle[iv] == h[iv]);
      else
        CHECK(std::abs(sub.nle[iv] - h[iv]) <= 1e-13 * scale);
    }
  }
  // (a vertical hoist on a horizontal trolley, at speed) => the hoist carries the hook's weight,
  // the trolley nothing (its axis is horizontal)
  ModelBuilder b;
  b.addBody("trolley", "world", Joint::prismatic({1, 0, 0}), Transform{},
            SpatialInertia{2000.0, Vector3(0, 0, 1), Matrix3::Identity()});
  b.addBody("hook", "trolley", Joint::prismatic({0, 0, 1}), Transform{},
            SpatialInertia{300.0, Vector3(0.5, 0, 0), Matrix3::Identity()});
  const Model m = b.build();
  Data kin(m), sub(m);
  const Eigen::VectorXd q = Eigen::Vector2d(3.0, -12.0), v = Eigen::Vector2d(0.5, -0.3);
  forwardKinematics(m, kin, q, v);
  SubtreeMask mask;
  mask.mark(m, {0, 1, 0});
  REQUIRE(mask.translational);
  biasForcesOfSubtrees(m, sub, kin, q, v, mask);
  CHECK(sub.nle[0] == 0.0);
  CHECK(sub.nle[1] == Approx(300.0 * 9.81).epsilon(1e-15));
}

TEST_CASE("RNEA in the body frame equals RNEA in the world frame, torques and joint forces") {
  // rnea runs each body's step in its own frame (special steps for coordinate-axis revolute and
  // prismatic joints of translated frames), rneaWorld in the world frame: the same torques and,
  // moved to the world, the same joint forces, on every joint type, with added mass and external
  // forces in both frames (the body-frame step taken about the wrong axis or with a sign of its
  // e_K cross products flipped shows here)
  std::mt19937 rng(17);
  for (int n : {1, 6, 17, -2, -9, -24}) {
    for (bool added : {false, true}) {
      const Model m = n > 0 ? randomTree(rng, n, {0.3, -1.0, -9.81}, added)
                            : randomAxisTree(rng, -n, added, n == -9);
      Data d(m), dw(m);
      const Eigen::VectorXd q = randomConfiguration(m, rng), v = 3.0 * randomVectorX(rng, m.nv);
      const Eigen::VectorXd a = randomVectorX(rng, m.nv);
      ExternalForces f(m);
      for (int i = 1; i < m.nbodies; ++i) {
        if (i % 2 == 0) f.addWorldFrame(i, randomVectorX(rng, 6));
        if (i % 3 == 0) f.addBodyFrame(i, randomVectorX(rng, 6));
      }
      const ExternalForces* cases[] = {nullptr, &f};
      for (const ExternalForces* fext : cases) {
        const Eigen::VectorXd tw = rneaWorld(m, dw, q, v, a, fext);
        const Eigen::VectorXd tb = rnea(m, d, q, v, a, fext);
        CHECK(relativeError(tb, tw) < 1e-12);
        for (int i = 1; i < m.nbodies; ++i) {
          const Force F = dw.X_WB[i].actForce(d.F_W[i]);
          CHECK((F - dw.F_W[i]).norm() <= 1e-11 * (1.0 + dw.F_W[i].norm()));
        }
      }
    }
  }
}

TEST_CASE("RNEA of the planar chain: body-frame torques equal the world frame's") {
  // the bench's chain (revolute about y in translated frames, diagonal inertias) in both forms
  std::mt19937 rng(18);
  const Model m = planarChain(12);
  Data d(m), dw(m);
  const Eigen::VectorXd q = randomVectorX(rng, m.nv, 3.0), v = randomVectorX(rng, m.nv, 2.0);
  const Eigen::VectorXd a = randomVectorX(rng, m.nv);
  CHECK(relativeError(rnea(m, d, q, v, a), rneaWorld(m, dw, q, v, a)) < 1e-13);
}
