// The masses that follow a winch (mechanics/follow_mass.hpp with forces/lines/
// lumped_line_provider.hpp): a lumped rope under a winch has at a time t the mass matrix, the
// accelerations, the energy and the line's Jacobian blocks of the same rope built with the
// winch's length L(t), and its nodes' masses stay positive at the winch's minimum length; a rope
// hauled in from 20 m to 14 m and held rings with a block at the axial frequency of a spring-mass
// chain of 14 m, no longer at that of 14 m of rope with the inertia of 20 m; while it hauls in,
// the kinetic energy leaving with the rope is in the balance.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Cholesky>

#include "dynamics/crba.hpp"
#include "dynamics/kinematics.hpp"
#include "mechanics/energy.hpp"
#include "mechanics/follow_mass.hpp"
#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "support/csv_file.hpp"
#include "tests/mechanics/mechanics_fixture.hpp"

using namespace yardsim;

namespace {

// (staged system, t, q, v) => its mass matrix with the masses that follow at t (CRBA)
Eigen::MatrixXd massMatrix(testing::StagedSystem& s, double t, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v) {
  dynamics::Data& kin = s.data.scratch;
  s.data.scratchWritten();
  dynamics::forwardKinematics(s.model(), kin, q, v);
  mechanics::followMass(s.system, t, kin, kin);
  return dynamics::crba(s.model(), kin, q);
}

// (staged system, t, q, v) => the line's blocks d a_i/d r_j, d a_i/d v_j at t
std::vector<dynamics::Matrix3> lineBlocks(testing::StagedSystem& s, double t,
                                          const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  const forces::LumpedLineProvider& line = *s.system.winchedLines().at(0);
  const std::size_t size =
      static_cast<std::size_t>((2 * line.line().jacobianBandwidth() + 1) * line.line().nodes());
  std::vector<dynamics::Matrix3> dadr(size), dadv(size);
  dynamics::forwardKinematics(s.model(), s.data.view, q, v);
  line.accelerationJacobian(s.data.stage(s.system, t, s.data.view, q, v), dadr, dadv);
  dadr.insert(dadr.end(), dadv.begin(), dadv.end());
  return dadr;
}

// (block mass M, rope: n segments of k = EA/l between inner nodes of mass m, the top fixed) =>
// the lowest axial frequency of the chain, rad/s: u_j = sin(j theta) with omega^2 = 2 k/m
// (1 - cos theta) at the inner nodes, and at the block M omega^2 sin(n theta) = k (sin(n theta) -
// sin((n - 1) theta)), its first root in (0, pi/n) by bisection
double chainFrequency(double M, double m, double k, int n) {
  auto residual = [&](double th) {
    return M * 2.0 * k / m * (1.0 - std::cos(th)) * std::sin(n * th) -
           k * (std::sin(n * th) - std::sin((n - 1) * th));
  };
  double a = 1e-9, b = std::numbers::pi / n - 1e-12;
  REQUIRE(residual(a) * residual(b) < 0.0);
  for (int i = 0; i < 200; ++i) {
    const double c = 0.5 * (a + b);
    (residual(a) * residual(c) <= 0.0 ? b : a) = c;
  }
  return std::sqrt(2.0 * k / m * (1.0 - std::cos(0.5 * (a + b))));
}

// (rope of mass per metre mu and length L, EA, a block M at its end) => the lowest axial
// frequency of the continuous rope, omega = beta/L sqrt(EA/mu), beta tan beta = mu L / M, rad/s
double rodFrequency(double mu, double L, double ea, double M) {
  double a = 1e-9, b = 0.5 * std::numbers::pi - 1e-12;
  for (int i = 0; i < 200; ++i) {
    const double c = 0.5 * (a + b);
    (c * std::tan(c) > mu * L / M ? b : a) = c;
  }
  return 0.5 * (a + b) / L * std::sqrt(ea / mu);
}

}  // namespace

TEST_CASE("a rope under a winch has at t the mass matrix and accelerations of a rope of L(t)") {
  testing::StagedSystem hauled(testing::buildFromScene(testing::hangingRopeScene(20.0)));
  testing::StagedSystem shorter(testing::buildFromScene(testing::hangingRopeScene(19.2)));
  REQUIRE(hauled.system.winchedLines().size() == 1);
  REQUIRE(hauled.model().nv == shorter.model().nv);
  // (hauling in at 0.4 m/s from t = 1 s) => L(3) = 19.2 m
  forces::Winch& winch = *hauled.system.winches().at(0).winch;
  winch.setPayoutRate(1.0, -0.4);
  const double t = 3.0;
  REQUIRE(winch.length(t) == Approx(19.2).epsilon(1e-15));
  // (a state off rest: every dof moved and moving) => the same in both systems
  Eigen::VectorXd q = hauled.system.description().q0, v(hauled.model().nv);
  for (int k = 0; k < hauled.model().nv; ++k) {
    v[k] = 0.1 * std::sin(1.7 * k);
    if (k >= 6) q[k] += 0.003 * std::cos(2.3 * k);  // (the nodes' positions: their q is p_W)
  }
  // (CRBA with the masses written at t) => the shorter rope's, to rounding
  const Eigen::MatrixXd M = massMatrix(hauled, t, q, v), expected = massMatrix(shorter, t, q, v);
  const double nodeMass = 10.0 * 19.2 / 8.0;
  const int node = hauled.model().idxV[hauled.model().bodyIndex("hoist.node4")];
  CHECK(expected(node, node) == Approx(nodeMass).epsilon(1e-3));  // (less the air's buoyancy)
  CHECK((M - expected).norm() <= 1e-14 * expected.norm());
  // (the stage: ABA with the node masses at t, the weight w l(t) on them) => the same
  // accelerations; the energy and the line's Jacobian blocks alike
  Eigen::VectorXd a(q.size()), b(q.size());
  hauled.data.kernel.acceleration(t, q, v, a);
  shorter.data.kernel.acceleration(t, q, v, b);
  INFO("accelerations up to " << b.cwiseAbs().maxCoeff() << ", difference " << (a - b).norm());
  CHECK(b.cwiseAbs().maxCoeff() > 100.0);
  CHECK((a - b).norm() <= 1e-11 * b.norm());
  CHECK(mechanics::energy(hauled.system, hauled.data, hauled.data.view, q, v, t) ==
        Approx(mechanics::energy(shorter.system, shorter.data, shorter.data.view, q, v, t))
            .epsilon(1e-12));
  const auto blocks = lineBlocks(hauled, t, q, v), expectedBlocks = lineBlocks(shorter, t, q, v);
  double worst = 0.0, scale = 0.0;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    worst = std::max(worst, (blocks[k] - expectedBlocks[k]).norm());
    scale = std::max(scale, expectedBlocks[k].norm());
  }
  CHECK(worst <= 1e-13 * scale);
  // (before the winch starts) => no mass written: the node slots are off, the 20 m rope's matrix
  const Eigen::MatrixXd atStart = massMatrix(hauled, 0.5, q, v);
  const auto& written = hauled.data.scratch.hasAddedMass;
  CHECK(std::none_of(written.begin(), written.end(), [](char c) { return c != 0; }));
  CHECK(atStart(node, node) == Approx(10.0 * 20.0 / 8.0).epsilon(1e-3));
  // (at the winch's minimum length, 0.01 m) => positive node masses of 0.01/8 m of rope
  const Eigen::MatrixXd held = massMatrix(hauled, 100.0, q, v);
  CHECK(held(node, node) == Approx(10.0 * 0.01 / 8.0).epsilon(1e-3));
  CHECK(Eigen::LLT<Eigen::MatrixXd>(held).info() == Eigen::Success);
}

TEST_CASE("a rope hauled in from 20 m to 14 m rings with its block at the chain's 14 m frequency") {
  // (a 50 kg block on 20 m of rope, 10 kg/m, EA 1e5 N, 10 segments, undamped, on a vertical
  // slider; hauled in 6 m from t = 0.5 s by an S-curve drive: 1 m/s, 0.5 m/s^2, 0.25 m/s^3,
  // done at t = 10.5 s, then held) => the block's bounce after it, by its upward crossings of
  // its mean, against the lowest axial mode of the rope of 14 m
  const double M = 50.0, mu = 10.0, ea = 1.0e5, L0 = 20.0, L1 = 14.0;
  const int n = 10;
  const double g = 9.81, w = (mu - 1.225 * std::numbers::pi / 4.0 * 0.04 * 0.04) * g;
  const double rest = 30.0 - L0 - (M * g * L0 + 0.5 * w * L0 * L0) / ea;
  const std::string yaml = R"(schema_version: 1
integrator: {method: rk4, dt: 0.002}
components:
  up: {type: wire_actor, params: {rope: hoist, payout: -6, speed: 1, accel: 0.5, jerk: 0.25, start_at: 0.5}}
mechanics:
  bodies:
    top: {parent: world, joint: {type: fixed}, placement: {xyz: [0, 0, 30]}, mass: 1000, inertia: [1, 1, 1]}
    block: {parent: world, joint: {name: lift, type: prismatic, axis: [0, 0, 1], q0: )" +
                           std::to_string(rest) + R"(}, mass: 50, inertia: [1, 1, 1]}
  ropes:
    hoist: {model: lumped, path: [{body: top, point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}],
            L0: 20, segments: 10, EA: 1.0e5, mass_per_length: 10, diameter: 0.04, damping_ratio: 0}
record: {interval: 0.004, channels: ["lift.q", "hoist.unstretched_length", "mechanics.energy_balance", "mechanics.work"]}
)";
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", yaml));
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / "out", 25.0, {}, {}, 0.1});
  const testing::CsvFile csv((dir.path() / "out" / "timeseries.csv").string());
  const int z = csv.column("lift.q[m]"), length = csv.column("hoist.unstretched_length[m]");
  const int balance = csv.column("mechanics.energy_balance[J]"),
            work = csv.column("mechanics.work[J]");
  REQUIRE(std::min({z, length, balance, work}) > 0);
  REQUIRE(csv.rows.back()[length] == Approx(L1).epsilon(1e-12));
  // (held from 11 s) => the mean height and the upward crossings through it
  double mean = 0.0;
  int rows = 0;
  for (const auto& r : csv.rows)
    if (r[0] >= 11.0) {
      mean += r[z];
      ++rows;
    }
  mean /= rows;
  std::vector<double> up;
  for (std::size_t k = 1; k < csv.rows.size(); ++k) {
    const double a = csv.rows[k - 1][z] - mean, b = csv.rows[k][z] - mean;
    if (csv.rows[k - 1][0] >= 11.0 && a < 0.0 && b >= 0.0)
      up.push_back(csv.rows[k - 1][0] + (csv.rows[k][0] - csv.rows[k - 1][0]) * -a / (b - a));
  }
  REQUIRE(up.size() >= 10);
  const double measured =
      2.0 * std::numbers::pi * static_cast<double>(up.size() - 1) / (up.back() - up.front());
  // (the chain of 14 m: inner nodes of mu l1, springs EA/l1, l1 = 1.4 m; the stale one: the
  // nodes' masses of 20 m of rope on the same springs; the continuous rope of 14 m)
  const double l1 = L1 / n, right = chainFrequency(M, mu * l1, ea / l1, n);
  const double stale = chainFrequency(M, mu * L0 / n, ea / l1, n);
  const double rod = rodFrequency(mu, L1, ea, M);
  INFO("measured " << measured << " rad/s; the 14 m chain " << right << ", with 20 m of inertia "
                   << stale << ", the continuous 14 m rope " << rod << " rad/s; " << up.size()
                   << " crossings");
  CHECK(measured == Approx(right).epsilon(2e-3));
  CHECK(std::abs(measured - stale) > 0.05 * right);
  // (the chain against the rope: first order in l, the block end's half segment of rope not in
  // the block's inertia) => 3.3 % at 10 segments
  CHECK(right == Approx(rod).epsilon(0.04));
  // (the winch hauls in 60 kg of rope moving at up to 1 m/s: the kinetic energy that leaves with
  // it is in the power) => the balance closes
  double drift = 0.0;
  for (const auto& r : csv.rows)
    drift = std::max(drift, std::abs(r[balance] - csv.rows[0][balance]));
  const double done = std::abs(csv.rows.back()[work] - csv.rows[0][work]);
  INFO("balance drift " << drift << " J of the winch's " << done << " J");
  CHECK(done > 0.5 * M * g * 6.0);
  CHECK(drift < 1e-7 * done);
}
