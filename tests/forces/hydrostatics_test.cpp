// The hydrostatics provider on a free body: floating to the equilibrium draft of its mass, the
// metacentric height of a box against KB + BM - KG, the roll period of a stable box against
// 2 pi k / sqrt(g GM), an unstable (negative GM) box heeling over, the potential energy whose
// gradient is the force, and the energy balance in calm water and in waves.
#include <catch2/catch.hpp>

#include <cmath>

#include "dynamics/rotation.hpp"
#include "force_rig.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/gravity.hpp"
#include "forces/hydrostatics.hpp"
#include "forces/linear_quadratic_damping.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;
using dynamics::Matrix3;
using Catch::Matchers::Contains;

namespace {
constexpr double kRho = 1025.0, kG = 9.81;
constexpr double L = 20.0, B = 8.0, D = 4.0;  // the box barge, body origin at mid-depth

auto calm() { return std::make_shared<const AiryWaves>(WaterProperties{kRho, kG, 0.0}); }

// (mass, centre of mass height above the keel, roll radius of gyration) => a free box
dynamics::Model freeBox(double m, double KG, double kxx) {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  Matrix3 I = dynamics::boxInertia(m, Vector3(L, B, D)).inertiaCom;
  I(0, 0) = m * kxx * kxx;
  b.addBody("barge", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::makeInertia(m, Vector3(0, 0, KG - D / 2), I));
  return b.build();
}

// (draft, heel) => free-joint q: keel at -draft on the centreline, turned about x
void pose(Eigen::VectorXd& q, double draft, double heel) {
  const Matrix3 R = dynamics::axisRotation(Vector3::UnitX(), heel);
  const Vector3 p = -(R * Vector3(0, 0, -D / 2 + draft));  // waterline centre stays at the origin
  double quat[4];
  dynamics::matrixToQuaternion(R, quat);
  q << p, quat[0], quat[1], quat[2], quat[3];
}
}  // namespace

TEST_CASE("a free box floats to the equilibrium draft of its mass") {
  const double T = 1.5, m = kRho * L * B * T;
  const dynamics::Model model = freeBox(m, 2.0, 3.0);
  Gravity gravity("gravity", Vector3(0, 0, -kG));
  Hydrostatics hydro("hull", model, 1, boxMesh(Vector3(L, B, D), 4, 2, 2), calm());
  const double wz = std::sqrt(kG / T);  // heave natural frequency without added mass
  DampingCoefficients c;
  c.linear = {0, 0, m * wz, 0, 0, 0};  // half of critical in heave
  LinearQuadraticDamping damping("damping", model, 1, Vector3::Zero(), c);
  Rig r(model, {&gravity, &hydro, &damping});
  pose(r.q, 0.4, 0.0);  // released high
  for (int k = 0; k < 3000; ++k) r.step(0.01);
  const HydrostaticReport& rep = hydro.report(r.stage());
  CHECK(rep.draft == Approx(T).epsilon(1e-9));
  CHECK(rep.displacement == Approx(m).epsilon(1e-9));
  CHECK(rep.submerged.waterplaneArea == Approx(L * B).epsilon(1e-12));
  CHECK(std::abs(rep.heel) < 1e-12);
  CHECK(std::abs(rep.trim) < 1e-12);
  CHECK(r.v.norm() < 1e-8);
}

TEST_CASE("stable box: GM = KB + BM - KG, and it rolls with period 2 pi k / sqrt(g GM)") {
  const double T = 2.0, m = kRho * L * B * T, KG = 2.0, k = 3.5;
  const double GM = T / 2 + B * B / (12 * T) - KG;
  const dynamics::Model model = freeBox(m, KG, k);
  Gravity gravity("gravity", Vector3(0, 0, -kG));
  Hydrostatics hydro("hull", model, 1, boxMesh(Vector3(L, B, D), 2, 2, 2), calm());
  Rig r(model, {&gravity, &hydro});
  pose(r.q, T, 0.0);
  const HydrostaticReport& up = hydro.report(r.stage());
  CHECK(up.gmTransverse == Approx(GM).epsilon(1e-12));
  CHECK(up.gmLongitudinal == Approx(T / 2 + L * L / (12 * T) - KG).epsilon(1e-12));
  // (released at 3 deg) => upward zero crossings of the heel, evenly spaced by the period
  const double phi0 = 3.0 * M_PI / 180;
  pose(r.q, T, phi0);
  const double h = 0.005;
  std::vector<double> crossings;
  double prev = phi0, maxHeel = 0.0;
  for (int i = 0; i < 12000; ++i) {
    r.step(h);
    const double phi = hydro.report(r.stage()).heel;
    maxHeel = std::max(maxHeel, std::abs(phi));
    if (prev < 0.0 && phi >= 0.0) crossings.push_back(r.t - h * phi / (phi - prev));
    prev = phi;
  }
  REQUIRE(crossings.size() >= 4);
  const double period = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  CHECK(period == Approx(2 * M_PI * k / std::sqrt(kG * GM)).epsilon(0.005));
  CHECK(maxHeel < phi0 * 1.001);  // no energy from nowhere
}

TEST_CASE("unstable box (negative GM) capsizes from a small heel") {
  const double T = 2.0, m = kRho * L * B * T, KG = 4.5;
  const dynamics::Model model = freeBox(m, KG, 3.5);
  Gravity gravity("gravity", Vector3(0, 0, -kG));
  Hydrostatics hydro("hull", model, 1, boxMesh(Vector3(L, B, D), 2, 2, 2), calm());
  DampingCoefficients c;
  c.linear = {1e5, 1e5, 2e6, 2e7, 2e8, 1e7};
  LinearQuadraticDamping damping("damping", model, 1, Vector3::Zero(), c);
  Rig r(model, {&gravity, &hydro, &damping});
  pose(r.q, T, 0.0);
  CHECK(hydro.report(r.stage()).gmTransverse == Approx(T / 2 + B * B / (12 * T) - KG).epsilon(1e-12));
  CHECK(hydro.report(r.stage()).gmTransverse < 0.0);
  pose(r.q, T, 1.0 * M_PI / 180);
  for (int i = 0; i < 6000; ++i) r.step(0.01);
  // (this box's angle of loll is past deck-edge immersion: it capsizes and floats upside down,
  // G now low above the deck) => heel near 180 deg, at rest, stable again
  const HydrostaticReport& rep = hydro.report(r.stage());
  CHECK(std::abs(rep.heel) > 179.0 * M_PI / 180);
  CHECK(r.v.norm() < 1e-2);
  CHECK(rep.gmTransverse > 0.0);
  CHECK(rep.displacement == Approx(m).epsilon(1e-6));
}

TEST_CASE("the potential energy's gradient is the hydrostatic force and moment") {
  const dynamics::Model model = freeBox(2e5, 2.0, 3.0);
  Hydrostatics hydro("hull", model, 1, boxMesh(Vector3(L, B, D), 3, 2, 2), calm());
  dynamics::Data data(model);
  Eigen::VectorXd q(7), v = Eigen::VectorXd::Zero(6);
  for (double heel : {0.1, 0.6, 2.5}) {  // upright-ish, deck edge in, nearly capsized
    INFO("heel " << heel);
    pose(q, 1.7, heel);
    q[0] = 3.0;
    auto at = [&](const Eigen::VectorXd& qq) {
      dynamics::forwardKinematics(model, data, qq, v);
      return hydro.potentialEnergy(Stage{0.0, model, data, qq, v});
    };
    dynamics::forwardKinematics(model, data, q, v);
    dynamics::ExternalForces f(model);
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(6);
    hydro.evaluate(Stage{0.0, model, data, q, v}, f, tau);
    const dynamics::Force F = f.worldFrame(1);  // about the world origin
    // (z moved by +-d) => -dV/dz = F_z
    const double d = 1e-5;
    Eigen::VectorXd qp = q, qm = q;
    qp[2] += d;
    qm[2] -= d;
    CHECK(-(at(qp) - at(qm)) / (2 * d) == Approx(F[5]).epsilon(1e-6));
    // (turned about the world x axis through the origin by +-d) => -dV/dtheta = M_x about the origin
    auto turned = [&](double a) {
      Eigen::VectorXd qq = q;
      const Matrix3 Rx = dynamics::axisRotation(Vector3::UnitX(), a);
      const Matrix3 R = Rx * dynamics::quaternionToMatrix(q.data() + 3);
      qq.head<3>() = Rx * q.head<3>();
      dynamics::matrixToQuaternion(R, qq.data() + 3);
      return qq;
    };
    CHECK(-(at(turned(d)) - at(turned(-d))) / (2 * d) == Approx(F[0]).margin(1e-6 * std::abs(F[5]) * B));
  }
}

TEST_CASE("energy balance: conservative in calm water, closed by the wave power in waves") {
  const double m = kRho * L * B * 1.8;
  const dynamics::Model model = freeBox(m, 2.5, 3.0);
  Gravity gravity("gravity", Vector3(0, 0, -kG));
  for (bool waves : {false, true}) {
    INFO((waves ? "waves" : "calm"));
    auto sea = waves ? std::make_shared<const AiryWaves>(WaterProperties{kRho, kG, 0.0, 40.0, 0.0},
                                                         std::vector<WaveComponent>{{1.5, 7.0, 1.2, 0.0}})
                     : calm();
    Hydrostatics hydro("hull", model, 1, boxMesh(Vector3(L, B, D), 4, 2, 2), sea);
    Rig r(model, {&gravity, &hydro});
    pose(r.q, 1.2, 0.45);  // 26 deg, deck edge under water, released high
    r.v << 0.05, -0.02, 0.01, 0.3, -0.2, 0.4;
    const double scale = m * kG * D;
    const Rig::Balance b = r.energyBalance(0.002, 4000);
    CHECK(b.maxError < 1e-6 * scale);
    if (waves) CHECK(b.maxWork > 1e-2 * scale);  // the waves did work that the balance accounts for
  }
}

TEST_CASE("a hull that is not closed is refused with the provider's and the mesh's names") {
  const dynamics::Model model = freeBox(1e5, 2.0, 3.0);
  TriangleMesh open = boxMesh(Vector3(L, B, D));
  open.source = "barge.stl";
  open.triangles.pop_back();
  CHECK_THROWS_WITH(Hydrostatics("hull", model, 1, open, calm()),
                    Contains("hydrostatics 'hull'") && Contains("barge.stl: face") && Contains("not closed"));
  CHECK_THROWS_AS(Hydrostatics("hull", model, 0, boxMesh(Vector3(L, B, D)), calm()), std::invalid_argument);
  CHECK_THROWS_AS(Hydrostatics("hull", model, 1, boxMesh(Vector3(L, B, D)), nullptr), std::invalid_argument);
}

TEST_CASE("without the incident pressure the hull is clipped at the still-water level in waves") {
  // (the same heeled, heaving box in a 1.5 m sea: the linear form) => the calm-water force,
  // moment, potential and report exactly, zero power; the nonlinear form differs
  const double m = kRho * L * B * 1.8;
  const dynamics::Model model = freeBox(m, 2.5, 3.0);
  const auto sea = std::make_shared<const AiryWaves>(
      WaterProperties{kRho, kG, 0.0, 40.0, 0.0}, std::vector<WaveComponent>{{1.5, 7.0, 1.2, 0.3}});
  Hydrostatics linear("hull", model, 1, boxMesh(Vector3(L, B, D), 4, 2, 2), sea, false);
  Hydrostatics still("hull", model, 1, boxMesh(Vector3(L, B, D), 4, 2, 2), calm());
  Hydrostatics waves("hull", model, 1, boxMesh(Vector3(L, B, D), 4, 2, 2), sea);
  CHECK_FALSE(linear.incidentPressure());
  Rig r(model, {});
  pose(r.q, 1.2, 0.3);
  r.v << 0.05, -0.02, 0.01, 0.3, -0.2, 0.4;
  for (const double t : {0.0, 1.3, 2.9}) {
    r.t = t;
    const Stage s = r.stage();
    // (provider) => its generalized force at the stage
    auto force = [&](const Hydrostatics& h) {
      dynamics::ExternalForces f(model);
      Eigen::VectorXd tau = Eigen::VectorXd::Zero(model.nv);
      h.evaluate(s, f, tau);
      return dynamics::Force(f.worldFrame(1));
    };
    CHECK(force(linear) == force(still));
    CHECK((force(waves) - force(still)).norm() > 1e-2 * m * kG);
    CHECK(linear.potentialEnergy(s) == still.potentialEnergy(s));
    CHECK(linear.power(s) == 0.0);
    CHECK(linear.report(s).submerged.volume == still.report(s).submerged.volume);
  }
}

TEST_CASE("the scratch's last clipping is given again only for the same time and pose") {
  // (a heeled box in waves, asked at poses A, B, A, A at t1, then A at t2, with one scratch) =>
  // force, moment, potential and power bit for bit those of a fresh clipping (no scratch), and a
  // different force at a different time or pose
  const double m = kRho * L * B * 1.8;
  const dynamics::Model model = freeBox(m, 2.5, 3.0);
  const auto sea = std::make_shared<const AiryWaves>(
      WaterProperties{kRho, kG, 0.0, 40.0, 0.0}, std::vector<WaveComponent>{{1.5, 7.0, 1.2, 0.3}});
  Hydrostatics hydro("hull", model, 1, boxMesh(Vector3(L, B, D), 4, 2, 2), sea);
  const std::unique_ptr<ProviderScratch> scratch = hydro.makeScratch();
  Rig r(model, {});
  r.v << 0.05, -0.02, 0.01, 0.3, -0.2, 0.4;
  std::vector<dynamics::Force> seen;
  for (const auto& [t, heel] : std::vector<std::pair<double, double>>{
           {1.3, 0.3}, {1.3, 0.1}, {1.3, 0.3}, {1.3, 0.3}, {2.9, 0.3}}) {
    r.t = t;
    pose(r.q, 1.2, heel);
    const Stage fresh = r.stage();
    Stage cached = fresh;
    cached.scratch = scratch.get();
    // (stage) => the world-frame force the provider adds there
    auto force = [&](const Stage& s) {
      dynamics::ExternalForces f(model);
      Eigen::VectorXd tau = Eigen::VectorXd::Zero(model.nv);
      hydro.evaluate(s, f, tau);
      return dynamics::Force(f.worldFrame(1));
    };
    const dynamics::Force F = force(cached);
    CHECK(F == force(fresh));
    CHECK(hydro.power(cached) == hydro.power(fresh));
    CHECK(hydro.potentialEnergy(cached) == hydro.potentialEnergy(fresh));
    // (the forces' clipping holds the force and moment alone) => the report's volume clipped anew
    CHECK(force(cached) == F);
    CHECK(hydro.report(cached).submerged.volume == hydro.report(fresh).submerged.volume);
    CHECK(hydro.report(cached).submerged.volume > 0.0);
    CHECK(force(cached) == F);  // asked twice at once
    seen.push_back(F);
  }
  CHECK(seen[0] != seen[1]);  // another pose
  CHECK(seen[0] == seen[2]);
  CHECK(seen[3] != seen[4]);  // another time, the same pose
}

TEST_CASE(
    "before its waves start the sea is clipped once with calm water, and a step's end is kept") {
  // (a heeled box in a sea whose waves start at t = 5 s, one scratch; a step's calls as the
  // multibody model makes them: the power and energy at its end, the next step's stages, then the
  // samples' energy at the end before) => the same doubles as fresh clippings (no scratch) and as
  // integrateSubmerged at the sea itself, with the clippings the scratch counts
  const double m = kRho * L * B * 1.8;
  const dynamics::Model model = freeBox(m, 2.5, 3.0);
  const auto sea =
      std::make_shared<const AiryWaves>(WaterProperties{kRho, kG, 0.0, 40.0, 2.0, 5.0},
                                        std::vector<WaveComponent>{{1.5, 7.0, 1.2, 0.3}});
  const TriangleMesh hull = boxMesh(Vector3(L, B, D), 4, 2, 2);
  Hydrostatics hydro("hull", model, 1, hull, sea);
  const std::unique_ptr<ProviderScratch> scratch = hydro.makeScratch();
  const auto& counted = static_cast<const Hydrostatics::Scratch&>(*scratch);
  Rig r(model, {});
  r.v << 0.05, -0.02, 0.01, 0.3, -0.2, 0.4;
  // (t, heel) => the stage there, with the scratch or without
  auto at = [&](double t, double heel, bool cached) {
    r.t = t;
    pose(r.q, 1.2, heel);
    Stage s = r.stage();
    if (cached) s.scratch = scratch.get();
    return s;
  };
  auto force = [&](const Stage& s) {
    dynamics::ExternalForces f(model);
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(model.nv);
    hydro.evaluate(s, f, tau);
    return dynamics::Force(f.worldFrame(1));
  };
  for (const double t : {3.0, 6.5}) {  // calm (ramp 0), then in waves (the ramp under way)
    INFO("t = " << t);
    const bool calm = sea->ramp(t) == 0.0;
    // (a step's end: power, then the energy, then the next step's first stage) => one clipping
    // before the waves start (calm water serves the sea), two in waves (calm water and the sea)
    const unsigned long before = counted.clippings;
    CHECK(hydro.power(at(t, 0.3, true)) == hydro.power(at(t, 0.3, false)));
    CHECK(hydro.potentialEnergy(at(t, 0.3, true)) == hydro.potentialEnergy(at(t, 0.3, false)));
    const dynamics::Force F = force(at(t, 0.3, true));
    CHECK(counted.clippings - before == (calm ? 1U : 2U));
    CHECK(F == force(at(t, 0.3, false)));
    // (the sea's own clipping) => the same force and moment
    SubmergedWorkspace ws(hull, sea->size());
    const dynamics::Data& d = at(t, 0.3, false).data;
    const SubmergedProperties direct = integrateSubmerged(hull, d.X_WB[1], *sea, t, ws);
    CHECK(F.tail<3>() == direct.force);
    CHECK(F.head<3>() == direct.moment);
    // (the next step's stages at other poses, its end's power and energy) => the samples' energy
    // and report at the step's end before clip nothing more, and are those of fresh clippings
    for (double heel : {0.31, 0.32, 0.33}) force(at(t + 0.01, heel, true));
    hydro.power(at(t + 0.02, 0.34, true));
    hydro.potentialEnergy(at(t + 0.02, 0.34, true));
    const unsigned long after = counted.clippings;
    CHECK(hydro.potentialEnergy(at(t, 0.3, true)) == hydro.potentialEnergy(at(t, 0.3, false)));
    CHECK(counted.clippings == after);
    if (calm) {  // (the report clips at the sea: calm water's clipping before the waves start)
      CHECK(hydro.report(at(t, 0.3, true)).submerged.volume ==
            hydro.report(at(t, 0.3, false)).submerged.volume);
      CHECK(counted.clippings == after);
    }
  }
}
