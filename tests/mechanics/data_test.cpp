// The workspace's two slots of committed-state kinematics (mechanics/data.hpp, scratchKinematics):
// a state asked for again is served from its slot, any other state is computed into the slot
// used less recently, and a write to scratch by another caller is never served.
#include "mechanics/data.hpp"

#include <catch2/catch.hpp>
#include <random>

#include "dynamics/configuration.hpp"
#include "dynamics/kinematics.hpp"
#include "tests/mechanics/mechanics_fixture.hpp"

using namespace yardsim;

namespace {
// (kinematics a, b) => the same placements and body velocities, bit for bit
bool sameKinematics(const dynamics::Model& m, const dynamics::Data& a, const dynamics::Data& b) {
  for (int i = 1; i < m.nbodies; ++i)
    if (a.X_WB[i].R != b.X_WB[i].R || a.X_WB[i].p != b.X_WB[i].p || a.V_B[i] != b.V_B[i])
      return false;
  return true;
}
}  // namespace

TEST_CASE("scratchKinematics serves two states from their slots and recomputes any other") {
  const mechanics::System sys(testing::buildFromYaml(testing::kHoistAndEqualizer), {}, "test");
  const auto& m = sys.model();
  mechanics::Data d(sys);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  const auto state = [&] {
    Eigen::VectorXd v(m.nv);
    for (int i = 0; i < m.nv; ++i) v[i] = u(rng);
    return v;
  };
  const Eigen::VectorXd q1 = sys.description().q0, v1 = state(), v2 = state(), v3 = state();
  Eigen::VectorXd q2 = q1;
  q2[0] += 0.25;
  const auto fresh = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
    dynamics::Data k(m);
    dynamics::forwardKinematics(m, k, q, v);
    return k;
  };
  // (two states) => two slots, each the kinematics of its state
  dynamics::Data& a = d.scratchKinematics(sys, q1, v1);
  CHECK(sameKinematics(m, a, fresh(q1, v1)));
  dynamics::Data& b = d.scratchKinematics(sys, q2, v2);
  CHECK(&b != &a);
  CHECK(sameKinematics(m, b, fresh(q2, v2)));
  // (the first state again) => its slot as it is, not computed again: a mark left in it stays
  a.X_WB[1].p.x() += 1.0;
  CHECK(&d.scratchKinematics(sys, q1, v1) == &a);
  CHECK(!sameKinematics(m, a, fresh(q1, v1)));
  // (a velocity one bit apart) => computed again, into the slot used less recently (b's)
  Eigen::VectorXd v1b = v1;
  v1b[3] = std::nextafter(v1b[3], 1.0);
  CHECK(&d.scratchKinematics(sys, q1, v1b) == &b);
  CHECK(sameKinematics(m, b, fresh(q1, v1b)));
  // (another caller writes scratch, then says so) => the state its slot held is computed again
  const bool scratchHeldB = &b == &d.scratch;
  REQUIRE((scratchHeldB || &a == &d.scratch));
  const Eigen::VectorXd& vHeld = scratchHeldB ? v1b : v1;
  dynamics::forwardKinematics(m, d.scratch, q2, v3);
  d.scratchWritten();
  dynamics::Data& c = d.scratchKinematics(sys, q1, vHeld);
  CHECK(sameKinematics(m, c, fresh(q1, vHeld)));
  // (a third state) => evicts the slot used less recently, the other stays
  dynamics::Data& e = d.scratchKinematics(sys, q2, v3);
  CHECK(&e != &c);
  CHECK(sameKinematics(m, e, fresh(q2, v3)));
  CHECK(&d.scratchKinematics(sys, q1, vHeld) == &c);
}
