// The chart Newton system (the sparse linear solver of CVODE and ARKODE for systems with a
// Jacobian pattern) against the dense first-order Newton matrix I - gamma J, J formed by central
// differences of the whole right-hand side y' = (chartRate(theta, v), a(q* (+) theta, v)), on a
// tree with a free joint and a spherical joint away from the chart's origin (their kinematics
// theta' = G(theta) v is not the identity there): the elimination of x_theta is exact, not an
// approximation of G by I; with the kinematics explicit (ARKODE's IMEX) it solves the system
// whose kinematic rows are zero. A pattern that gives a rotational joint's columns different
// rows is completed, not refused.
#include <catch2/catch.hpp>

#include <Eigen/LU>
#include <random>

#include "dynamics/configuration.hpp"
#include "dynamics/integrators/chart_newton_system.hpp"
#include "dynamics/model_builder.hpp"
#include "dynamics/multibody_system.hpp"

using namespace yardsim::dynamics;

namespace {

// A floating block (free joint) with a pendulum on a spherical joint and a slider, under gravity:
// 6 + 3 + 1 dofs, coupled through the tree's inertia and the gyroscopic terms
Model floatingTree() {
  ModelBuilder mb;
  mb.setGravity(Vector3(0.0, 0.0, -9.81));
  mb.addBody("block", "world", Joint::free(), {},
             makeInertia(3.0, Vector3(0.1, 0.0, 0.0), Vector3(1.0, 2.0, 3.0).asDiagonal()));
  mb.addBody("pendulum", "block", Joint::spherical(),
             Transform::translation(Vector3(0.5, 0.2, 0.0)),
             makeInertia(1.0, Vector3(0.0, 0.0, -0.8), Vector3(0.1, 0.2, 0.15).asDiagonal()));
  mb.addBody("slider", "block", Joint::prismatic(Vector3::UnitX()),
             Transform::translation(Vector3(0, 0.3, 0.1)),
             makeInertia(0.5, Vector3::Zero(), Vector3(0.1, 0.1, 0.1).asDiagonal()));
  return mb.build();
}

JacobianPattern fullPattern(int n) {
  JacobianPattern p;
  p.n = n;
  for (int j = 0; j < n; ++j) {
    p.rows.emplace_back();
    for (int i = 0; i < n; ++i) p.rows.back().push_back(i);
  }
  return p;
}

struct Case {
  Model model = floatingTree();
  MultibodySystem sys{model};
  Eigen::VectorXd origin, y, q, a;
  int n = model.nv;
  Case() {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    origin = randomConfiguration(model, rng);
    y.resize(2 * n);
    // (theta: up to 0.6 rad in the rotations, the chart's G far from I; v: turning and moving)
    for (int i = 0; i < 2 * n; ++i) y[i] = (i < n ? 0.6 : 1.5) * u(rng);
    q.resize(model.nq);
    a.resize(n);
    integrate(model, origin, y.head(n), 1.0, q);
    sys.acceleration(0.0, q, y.tail(n), a);
  }
  // (y) => the whole first-order right-hand side; kinematic: its theta rows, else zero there
  Eigen::VectorXd rhs(const Eigen::VectorXd& yy, bool kinematic) {
    Eigen::VectorXd out(2 * n), rate(n), qq(model.nq), aa(n);
    const Eigen::VectorXd theta = yy.head(n), v = yy.tail(n);
    chartRate(model, theta, v, rate);
    integrate(model, origin, theta, 1.0, qq);
    sys.acceleration(0.0, qq, v, aa);
    out << (kinematic ? rate : Eigen::VectorXd::Zero(n)), aa;
    return out;
  }
  // (gamma) => I - gamma J with J by central differences of rhs
  Eigen::MatrixXd denseMatrix(double gamma, bool kinematic) {
    Eigen::MatrixXd J(2 * n, 2 * n);
    for (int j = 0; j < 2 * n; ++j) {
      const double h = 1e-6 * std::max(1.0, std::abs(y[j]));
      Eigen::VectorXd yp = y, ym = y;
      yp[j] += h;
      ym[j] -= h;
      J.col(j) = (rhs(yp, kinematic) - rhs(ym, kinematic)) / (2.0 * h);
    }
    return Eigen::MatrixXd::Identity(2 * n, 2 * n) - gamma * J;
  }
};

}  // namespace

TEST_CASE(
    "the chart Newton system solves I - gamma J as the dense first-order Jacobian does, through a "
    "free and a spherical joint's chart") {
  Case c;
  const JacobianPattern pattern = fullPattern(c.n);
  for (const bool kinematic : {true, false}) {
    INFO((kinematic ? "kinematics implicit (CVODE, ARKODE DIRK)"
                    : "kinematics explicit (ARKODE IMEX)"));
    ChartNewtonSystem newton(c.model, pattern, nullptr, kinematic);
    const int evaluations = newton.form(c.sys, 0.0, c.origin, c.y.data(), c.q, c.a);
    CHECK(evaluations == 2 * newton.matrix().colouring().count());
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const double gamma : {0.002, 0.05}) {
      INFO("gamma " << gamma);
      REQUIRE(newton.factorise(gamma));
      const Eigen::MatrixXd A = c.denseMatrix(gamma, kinematic);
      Eigen::VectorXd b(2 * c.n);
      for (int i = 0; i < 2 * c.n; ++i) b[i] = u(rng);
      const Eigen::VectorXd exact = A.partialPivLu().solve(b);
      Eigen::VectorXd x(2 * c.n);
      newton.solve(b.data(), x.data());
      INFO("error " << (x - exact).lpNorm<Eigen::Infinity>() << " of "
                    << exact.lpNorm<Eigen::Infinity>());
      CHECK((x - exact).lpNorm<Eigen::Infinity>() < 1e-6 * exact.lpNorm<Eigen::Infinity>());
      // (the residual of the dense system) => small: x solves it, not a neighbouring one
      CHECK((A * x - b).lpNorm<Eigen::Infinity>() < 1e-6 * b.lpNorm<Eigen::Infinity>());
      // (in place: x and b the same vector) => the same solution
      Eigen::VectorXd inPlace = b;
      newton.solve(inPlace.data(), inPlace.data());
      CHECK((inPlace - x).lpNorm<Eigen::Infinity>() == 0.0);
    }
  }
}

TEST_CASE("the chart Newton system completes a pattern whose rotational columns differ in rows") {
  // (the free joint's first column couples only to itself) => its group gets the union of rows,
  // and the solve still matches the dense one
  Case c;
  JacobianPattern pattern = fullPattern(c.n);
  pattern.rows[0] = {0};
  ChartNewtonSystem newton(c.model, pattern, nullptr, true);
  newton.form(c.sys, 0.0, c.origin, c.y.data(), c.q, c.a);
  REQUIRE(newton.factorise(0.05));
  const Eigen::MatrixXd A = c.denseMatrix(0.05, true);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(2 * c.n, -1.0, 1.0);
  Eigen::VectorXd x(2 * c.n);
  newton.solve(b.data(), x.data());
  CHECK((A * x - b).lpNorm<Eigen::Infinity>() < 1e-6);
}
