// The contact provider on a block (2 x 2 x 1 m, vertical prismatic joint, gravity by the
// provider) with an analytic ground source at its four bottom corners: resting force = weight and
// the static sink mg / (4k), the same motion when the contact is written the other way round
// (ground as B), and the energy balance of a drop with the spring's energy and the dissipation.
#include "forces/contact.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>

#include "force_rig.hpp"
#include "forces/gravity.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;

namespace {

const Vector3 kG(0.0, 0.0, -9.81);

// (ground as A or as B) => the four corners' contacts from q (height of the block's centre)
ContactSource groundCorners(bool groundFirst) {
  return [groundFirst](const Stage& s, std::vector<ContactPoint>& out) {
    const double depth = 0.5 - s.q[0];
    if (depth <= 0.0) return;
    for (double x : {-1.0, 1.0}) {
      for (double y : {-1.0, 1.0}) {
        ContactPoint c;
        c.bodyA = groundFirst ? 0 : 1;
        c.bodyB = groundFirst ? 1 : 0;
        c.n_W = groundFirst ? Vector3::UnitZ() : Vector3(-Vector3::UnitZ());
        c.p_W = Vector3(x, y, s.q[0] - 0.5);
        c.depth = depth;
        out.push_back(c);
      }
    }
  };
}

}  // namespace

TEST_CASE("contact_law: provider: refuses what it cannot use") {
  CHECK_THROWS_AS(ContactForce("c", nullptr, {}, {}), std::invalid_argument);
  CHECK_THROWS_AS(
      ContactForce("c", groundCorners(true), {NormalLawKind::kLinear, -1.0, 0.0, 1.0}, {}),
      std::invalid_argument);
  CHECK_THROWS_AS(ContactForce("c", groundCorners(true), {}, {0.3, 0.0, FrictionForm::kSqrt}),
                  std::invalid_argument);
}

TEST_CASE("contact_law: provider: a block resting on four corner contacts carries its weight") {
  const double m = 1000.0, k = 1e8;
  const dynamics::Model model = verticalBlock(m);
  Gravity gravity("gravity", kG);
  for (bool groundFirst : {true, false}) {
    ContactForce contact("ground", groundCorners(groundFirst),
                         {NormalLawKind::kLinear, k, 2.0 * 0.5 * std::sqrt(k * m / 4.0), 1.0},
                         {0.3, 1e-3, FrictionForm::kSqrt});
    Rig rig(model, {&gravity, &contact});
    rig.q[0] = 0.5;
    for (int i = 0; i < 20000; ++i) rig.step(1e-3);  // 20 s
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(1);
    dynamics::ExternalForces f(model);
    const auto scratch = contact.makeScratch();  // what the provider applied, read back
    Stage at = rig.stage();
    at.scratch = scratch.get();
    contact.evaluate(at, f, tau);
    const auto& applied = static_cast<const ContactForce::Scratch&>(*scratch);
    double total = 0.0;
    for (const ContactResponse& r : applied.responses) total += r.normalForce;
    INFO("ground first " << groundFirst);
    CHECK(applied.points.size() == 4);
    CHECK(total == Approx(m * 9.81).epsilon(1e-9));
    CHECK(f.worldFrame(1)[5] == Approx(m * 9.81).epsilon(1e-9));  // the force on the block, up
    CHECK(0.5 - rig.q[0] == Approx(m * 9.81 / (4.0 * k)).epsilon(1e-9));
    CHECK(std::abs(rig.v[0]) < 1e-12);
  }
}

TEST_CASE("contact_law: provider: energy balance of a block dropped on Hunt-Crossley corners") {
  const double m = 500.0, k = 2e9;
  const dynamics::Model model = verticalBlock(m);
  Gravity gravity("gravity", kG);
  ContactForce contact("ground", groundCorners(true),
                       {NormalLawKind::kHuntCrossley, k, k * 0.3, 1.5}, {});
  // (h) => the balance over 0.8 s: the fall, the impact and the rebound
  auto balance = [&](double h) {
    Rig rig(model, {&gravity, &contact});
    rig.q[0] = 0.7;  // 0.2 m above the ground
    return rig.energyBalance(h, static_cast<int>(std::lround(0.8 / h)));
  };
  const auto coarse = balance(4e-5), fine = balance(2e-5);
  INFO("error " << coarse.maxError << " J at h = 4e-5 s, " << fine.maxError
                << " J at 2e-5 s; dissipated " << fine.maxWork << " J");
  CHECK(fine.maxWork > 50.0);  // the impact dissipated a good part of m g 0.2 = 981 J
  CHECK(fine.maxError < 1e-5 * m * 9.81 * 0.2);
  CHECK(fine.maxError < coarse.maxError / 3.0);  // and the balance closes as h -> 0
}
