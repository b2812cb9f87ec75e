// The added mass on the kernel's left-hand side, end to end: the infinite-frequency heave added
// mass A33 of a floating vertical cylinder from the panel solver, given to the body, with the
// real hydrostatics provider (hull clipped at the water surface) and model gravity. Released
// from a heave offset in still water, the body oscillates about its floating position with the
// period 2 pi sqrt((M + A33) / C33), C33 = rho g A_wp (a wall-sided hull: exactly linear). A
// light floater under a heavy load stays stable with A33 on the left-hand side and blows up
// when A33 is fed back as a force from the last step's acceleration.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "dynamics/added_mass.hpp"
#include "dynamics/kinematics.hpp"
#include "forces/force_rig.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/hydro/added_mass.hpp"
#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/panel_geometry.hpp"
#include "forces/hydro/wetted_surface.hpp"
#include "forces/hydrostatics.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;

namespace {

constexpr double kRho = 1025.0, kG = 9.81;
constexpr double kR = 5.0, kT = 4.0, kF = 2.0;  // radius, draft, freeboard; body origin on the waterline
constexpr int kSides = 32;

// (hull) => infinite-frequency 6x6 added mass about the body origin, naval order
hydro::Matrix6 cylinderAddedMass(const hydro::PanelMesh& hull) {
  hydro::AddedMassOptions o;
  o.rho = kRho;
  o.solver.freeSurface = hydro::FreeSurface::NegativeImage;
  return hydro::addedMass(hydro::wettedSurface(hull), o);
}

struct Heave {
  double period = 0.0;
  double mean = 0.0;
};

// (A33 given to the body or not) => period from the upward zero crossings of the heave, and the
// mean heave over those whole periods
Heave releasedHeave(const hydro::Matrix6& A, bool withAddedMass) {
  const double awp = 0.5 * kSides * kR * kR * std::sin(2.0 * std::numbers::pi / kSides);  // polygon
  const double mass = kRho * awp * kT;
  dynamics::ModelBuilder b;
  b.setGravity(Vector3(0.0, 0.0, -kG));
  b.addBody("spar", "world", dynamics::Joint::prismatic(Vector3::UnitZ()), dynamics::Transform::identity(),
            dynamics::makeInertia(mass, Vector3(0.0, 0.0, -1.0), mass * Eigen::Matrix3d::Identity()));
  if (withAddedMass) b.setAddedMass("spar", dynamics::addedMassAboutOrigin(A, Vector3::Zero()));
  const dynamics::Model model = b.build();
  Hydrostatics hull("hull", model, 1, cylinderMesh(kR, -kT, kF, kSides, 3),
                    std::make_shared<const AiryWaves>(WaterProperties{kRho, kG, 0.0}));
  Rig r(model, {&hull});
  r.q[0] = 0.3;
  const double h = 0.01;  // about 400 RK4 steps per period
  std::vector<double> up;
  double prev = r.q[0], sum = 0.0, first = 0.0;
  for (int i = 0; i < 4000; ++i) {
    r.step(h);
    const double z = r.q[0];
    if (prev < 0.0 && z >= 0.0) {
      up.push_back(r.t - h * z / (z - prev));
      if (up.size() == 1) first = sum;
    }
    sum += z;
    prev = z;
    if (up.size() == 7) break;
  }
  REQUIRE(up.size() == 7);
  Heave out;
  out.period = (up.back() - up.front()) / 6.0;
  out.mean = (sum - first) * h / (up.back() - up.front());
  return out;
}

// A stiff rope between a light floater and the heavy load hanging under it, as a joint force on
// the load's prismatic joint (q: its height relative to the floater, at rest at the static stretch).
class Hanger final : public ForceProvider {
 public:
  explicit Hanger(double k) : ForceProvider("hanger"), k_(k) {}

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces&, Eigen::VectorXd& tau) const override { tau[1] -= k_ * s.q[1]; }
  double doPotentialEnergy(const Stage& s) const override { return 0.5 * k_ * s.q[1] * s.q[1]; }

 private:
  double k_;
};

// The added mass fed back as an external force -A33 a, a being the floater's acceleration over
// the last step (what a loosely coupled hydrodynamic force can offer), set by the caller.
class LaggedAddedMassForce final : public ForceProvider {
 public:
  explicit LaggedAddedMassForce(double a33) : ForceProvider("lagged added mass"), a33_(a33) {}
  double lastAcceleration = 0.0;

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd&) const override {
    f.addPointForceWorld(1, dynamics::pointPosition(s.data, 1, Vector3::Zero()), Vector3(0.0, 0.0, -a33_ * lastAcceleration));
  }

 private:
  double a33_;
};

}  // namespace

TEST_CASE("a light floater under a heavy load: stable with the added mass on the left-hand side only") {
  // the floater carries 20 % of the displaced mass, the load hanging from it 80 %; A33 = 0.74 of
  // the displaced mass is 3.7 times the floater's own mass, so a lagged -A33 a fed back as a
  // force amplifies itself by about 3.7 per step, whatever the step; on the left-hand side the
  // same A33 is just more inertia
  const hydro::Matrix6 A = cylinderAddedMass(hydro::verticalCylinder(kR, -kT, kF, kSides, 6, 6));
  const double awp = 0.5 * kSides * kR * kR * std::sin(2.0 * std::numbers::pi / kSides);
  const double M = kRho * awp * kT, mFloat = 0.2 * M, mLoad = 0.8 * M, k = 2e7;
  REQUIRE(A(2, 2) > 3.0 * mFloat);
  // (left-hand side or lagged force, step) => the lagged force blows up at a ten times smaller step too
  for (const auto& [onLeftHandSide, h] : {std::pair{true, 0.01}, std::pair{false, 0.01}, std::pair{false, 0.001}}) {
    INFO((onLeftHandSide ? "added mass on the left-hand side" : "added mass as a lagged force") << ", h = " << h);
    dynamics::ModelBuilder b;
    b.setGravity(Vector3(0.0, 0.0, -kG));
    b.addBody("float", "world", dynamics::Joint::prismatic(Vector3::UnitZ()), dynamics::Transform::identity(),
              dynamics::makeInertia(mFloat, Vector3::Zero(), mFloat * Eigen::Matrix3d::Identity()));
    b.addBody("load", "float", dynamics::Joint::prismatic(Vector3::UnitZ()), dynamics::Transform::translation(Vector3(0, 0, -10)),
              dynamics::makeInertia(mLoad, Vector3::Zero(), mLoad * Eigen::Matrix3d::Identity()));
    if (onLeftHandSide) b.setAddedMass("float", dynamics::addedMassAboutOrigin(A, Vector3::Zero()));
    const dynamics::Model model = b.build();
    Hydrostatics hull("hull", model, 1, cylinderMesh(kR, -kT, kF, kSides, 3),
                      std::make_shared<const AiryWaves>(WaterProperties{kRho, kG, 0.0}));
    Hanger hanger(k);
    LaggedAddedMassForce lagged(A(2, 2));
    std::vector<ForceProvider*> providers{&hull, &hanger};
    if (!onLeftHandSide) providers.push_back(&lagged);
    Rig r(model, providers);
    r.q[0] = 0.3;                    // released high
    r.q[1] = -mLoad * kG / k;        // the rope at its static stretch
    double peak = 0.0;
    for (int i = 0; i < 3000 && std::isfinite(r.q[0]) && std::abs(r.q[0]) < 100.0; ++i) {
      const double v0 = r.v[0];
      r.step(h);
      lagged.lastAcceleration = (r.v[0] - v0) / h;
      peak = std::max(peak, std::abs(r.q[0]));
    }
    if (onLeftHandSide) CHECK(peak < 0.3 * 1.01);  // 30 s of heave, no growth
    else CHECK((!std::isfinite(r.q[0]) || peak > 100.0));
  }
}

TEST_CASE("a floating cylinder heaves with the period 2 pi sqrt((M + A33) / C33)") {
  const hydro::Matrix6 A = cylinderAddedMass(hydro::verticalCylinder(kR, -kT, kF, kSides, 6, 6));
  const double awp = 0.5 * kSides * kR * kR * std::sin(2.0 * std::numbers::pi / kSides);
  const double M = kRho * awp * kT, C33 = kRho * kG * awp;
  INFO("A33 / M = " << A(2, 2) / M);
  REQUIRE(A(2, 2) > 0.1 * M);
  const Heave with = releasedHeave(A, true);
  CHECK(with.period == Approx(2.0 * std::numbers::pi * std::sqrt((M + A(2, 2)) / C33)).epsilon(1e-3));
  // it oscillates about its floating position: gravity does not pull on the added mass
  CHECK(std::abs(with.mean) < 2e-3);
  // without the added mass the period is the dry-mass one, measurably shorter
  const Heave without = releasedHeave(A, false);
  CHECK(without.period == Approx(2.0 * std::numbers::pi * std::sqrt(M / C33)).epsilon(1e-3));
  CHECK(with.period / without.period > 1.05);
}

TEST_CASE("the hull's own triangle mesh goes through the panel solver") {
  // the hydrostatics' triangle mesh (fans on the end caps) as panels: consistently oriented, and
  // its wetted part has the side and bottom areas of the 32-gon prism below the waterline
  const hydro::PanelMesh wet = hydro::wettedSurface(hydro::panelMesh(cylinderMesh(kR, -kT, kF, kSides, 3)));
  const std::vector<hydro::Panel> panels = hydro::buildPanels(wet);
  double area = 0.0;
  for (const hydro::Panel& p : panels) area += p.area;
  const double side = 2.0 * kR * std::sin(std::numbers::pi / kSides);
  CHECK(area == Approx(kSides * side * kT + 0.5 * kSides * kR * kR * std::sin(2.0 * std::numbers::pi / kSides)));
}
