// The providers allocate nothing once built: evaluate(), potentialEnergy(), power() and the
// reports of every provider in this folder, with every heap allocation counted (those of
// forces/lines and forces/hydro: lines/allocation_test.cpp and hydro/allocation_test.cpp).
#include <catch2/catch.hpp>

#include "support/allocation_counter.hpp"

#include <vector>

#include "force_rig.hpp"
#include "forces/body_load.hpp"
#include "forces/bushing.hpp"
#include "forces/contact.hpp"
#include "forces/current_load.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/gravity.hpp"
#include "forces/hydrostatics.hpp"
#include "forces/linear_quadratic_damping.hpp"
#include "forces/rope.hpp"
#include "forces/rotational_spring_damper.hpp"
#include "forces/spring_damper.hpp"
#include "forces/wind_load.hpp"

using yardsim::testing::allocationCount;

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;

TEST_CASE("gravity and wire rope and equalizer and body load do not allocate at a stage") {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("hook", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(5e3, Vector3(1, 1, 1)));
  b.addBody("load", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(1e5, Vector3(6, 4, 2)));
  const dynamics::Model m = b.build();
  RopeProperties p;
  p.ea = 1e9;
  p.l0 = 5.0;
  p.damping = 1e5;
  p.breakingLoad = 1e7;
  Gravity gravity("gravity", Vector3(0.0, 0.0, -9.81));
  Rope wire("hoist", m,
                {{0, Vector3(0, 0, 40)}, {0, Vector3(1, 0, 40)}, {1, Vector3(0, 0, 0.5)}}, p, 4);
  wire.setPayoutRate(0.0, 0.083);
  p.l0 = 10.0;
  Rope eq("eq", m, {1, Vector3(0, 0, -0.5)},
               {{{2, Vector3(-3, 0, 1)}}, {{2, Vector3(0, 1, 1)}, {2, Vector3(3, 0, 1)}}}, p);
  BodyLoad load("wind", m, 2, Vector3(1, 0, 0), LoadFrame::Body);
  load.setTable({{0.0, 1, 2, 3, 4, 5, 6}, {1.0, 0, 0, 0, 0, 0, 0}, {2.0, 5, 5, 5, 5, 5, 5}});
  Rig r(m, {&gravity, &wire, &eq, &load});
  r.q << 0.0, 0.0, 33.0, 1.0, 0.0, 0.0, 0.0, 0.1, 0.0, 25.0, 1.0, 0.0, 0.0, 0.0;
  r.v.setConstant(0.1);
  r.step(1e-3);  // everything warmed up
  const Stage s = r.stage();
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  const std::initializer_list<ForceProvider*> providers{&gravity, &wire, &eq, &load};
  std::vector<std::unique_ptr<ProviderScratch>> scratch;  // the caller's, made once
  for (ForceProvider* fp : providers) scratch.push_back(fp->makeScratch());
  const std::size_t before = allocationCount();
  double sink = 0.0;
  std::size_t k = 0;
  for (ForceProvider* fp : providers) {
    Stage own = s;
    own.scratch = scratch[k++].get();
    fp->evaluate(own, f, tau);
    sink += fp->potentialEnergy(own) + fp->power(own);
  }
  sink += wire.tension(s) + wire.length(s) + eq.tension(s) + eq.length(s) + load.at(1.5).force.x();
  sink += wire.exceedsBreakingLoad(s) ? 1.0 : 0.0;
  const std::size_t after = allocationCount();
  CHECK(after == before);
  // (the counter counts) => a vector that escapes is seen
  std::vector<double> probe(100, 1.0);
  volatile double read = probe[37];
  CHECK(read == 1.0);
  CHECK(allocationCount() > after);
  CHECK(wire.tension(s) > 0.0);
  CHECK(eq.tension(s) > 0.0);
  CHECK(std::isfinite(sink));
}

TEST_CASE("hydrostatics, damping, wind (steady and gusty) and current loads do not allocate at a stage") {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("barge", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(3e5, Vector3(20, 8, 4)));
  const dynamics::Model m = b.build();
  const WaterProperties water{1025.0, 9.81, 0.0, 50.0, 5.0};
  Hydrostatics calm("calm", m, 1, boxMesh(Vector3(20, 8, 4), 4, 2, 2), std::make_shared<const AiryWaves>(water));
  Hydrostatics waves("waves", m, 1, boxMesh(Vector3(20, 8, 4), 4, 2, 2),
                     std::make_shared<const AiryWaves>(water, std::vector<WaveComponent>{{2.0, 8.0, 1.0, 0.0}}));
  DampingCoefficients c;
  c.linear.fill(1e4);
  c.quadratic.fill(1e3);
  LinearQuadraticDamping damping("damping", m, 1, Vector3(0, 0, 1), c);
  WindProperties wp;
  wp.speed = 20.0;
  wp.profile = WindProfileKind::Npd;
  WindLoad wind("wind", m, 1, Vector3(0, 0, 8), {50, 200, 20},
                FlowCoefficients({0, M_PI / 2, M_PI}, {-1, 0, 1}, {0, -1, 0}, {0, 0.1, 0}),
                std::make_shared<const WindField>(wp));
  wp.gusts = GustProperties{};  // (time-varying gusts) => 200 components summed at the stage's t
  WindLoad gusty("gusty", m, 1, Vector3(0, 0, 8), {50, 200, 20}, FlowCoefficients(),
                 std::make_shared<const WindField>(wp));
  CurrentProperties cp;
  cp.speed = 1.0;
  cp.profile = {{-10.0, 0.5}, {0.0, 1.0}};
  CurrentLoad current("current", m, 1, Vector3(0, 0, -1), {30, 80, 20}, FlowCoefficients(),
                      std::make_shared<const CurrentField>(cp));
  Rig r(m, {&calm, &waves, &damping, &wind, &gusty, &current});
  r.q << 0.0, 0.0, 0.5, std::cos(0.1), std::sin(0.1), 0.0, 0.0;
  r.v.setConstant(0.1);
  r.t = 3.0;
  r.step(1e-3);
  const Stage s = r.stage();
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  const std::initializer_list<ForceProvider*> providers{&calm, &waves, &damping, &wind, &gusty, &current};
  std::vector<std::unique_ptr<ProviderScratch>> scratch;  // the caller's, made once
  for (ForceProvider* fp : providers) scratch.push_back(fp->makeScratch());
  Stage calmStage = s, waveStage = s;
  calmStage.scratch = scratch[0].get();
  waveStage.scratch = scratch[1].get();
  const std::size_t before = allocationCount();
  double sink = 0.0;
  std::size_t k = 0;
  for (ForceProvider* fp : providers) {
    Stage own = s;
    own.scratch = scratch[k++].get();
    fp->evaluate(own, f, tau);
    sink += fp->potentialEnergy(own) + fp->power(own);
  }
  sink += calm.report(calmStage).draft + waves.report(waveStage).gmTransverse + wind.load(s).speed +
          gusty.load(s).speed + current.load(s).speed;
  const double volume = waves.report(waveStage).submerged.volume;
  sink += damping.load(s)[0] + volume;
  CHECK(allocationCount() == before);
  CHECK(volume > 0.0);
  CHECK(std::isfinite(sink));
}

TEST_CASE("spring-dampers, joint springs and bushings do not allocate at a stage") {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("a", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(300.0, Vector3(2, 1, 1)));
  b.addBody("arm", "a", dynamics::Joint::revolute(Vector3::UnitZ()),
            dynamics::Transform::identity(), dynamics::boxInertia(50.0, Vector3(2, 0.2, 0.2)));
  const dynamics::Model m = b.build();
  SpringDamperProperties sp;
  sp.freeLength = 2.0;
  sp.curve = SpringCurve::table({-1.0, 0.0, 1.0}, {-1e4, 0.0, 2e3});
  sp.damping = 50.0;
  sp.minLength = 1.0;
  sp.stopStiffness = 1e5;
  SpringDamper spring("spring", m, {0, Vector3(0, 0, 5)}, {2, Vector3(1, 0, 0)}, sp);
  JointSpringProperties jp;
  jp.curve = SpringCurve::linear(300.0);
  jp.damping = 3.0;
  RotationalSpringDamper joint("joint", m, 2, 0, jp);
  BushingProperties bp;
  bp.stiffness = dynamics::Matrix6::Identity() * 1e4;
  bp.damping = dynamics::Matrix6::Identity() * 10.0;
  Bushing bushing("bushing", m, 1, dynamics::Transform::identity(), 2,
                  dynamics::Transform::translation(Vector3(0.5, 0, 0)), bp);
  Rig r(m, {&spring, &joint, &bushing});
  r.q << 0.1, 0.2, 0.3, 1.0, 0.0, 0.0, 0.0, 0.4;
  r.v.setConstant(0.1);
  r.step(1e-3);
  const Stage s = r.stage();
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  const std::size_t before = allocationCount();
  double sink = 0.0;
  for (ForceProvider* fp : std::initializer_list<ForceProvider*>{&spring, &joint, &bushing}) {
    fp->evaluate(s, f, tau);
    sink += fp->potentialEnergy(s) + fp->power(s);
  }
  sink += spring.state(s).force + spring.axialStiffness(s) + joint.generalizedForce(s) +
          bushing.state(s).generalizedForce.norm();
  CHECK(allocationCount() == before);
  CHECK(std::isfinite(sink));
  CHECK(sink != 0.0);
}

TEST_CASE("contact with friction on a block's corners does not allocate at a stage") {
  // (a 2 x 2 x 1 m block tilted on its four bottom corners, sliding: Hunt-Crossley and
  // regularised friction at each, from a source that reads the corners off the stage's pose) =>
  // evaluate, the energy, the power and the regime (the implicit methods' switch test)
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("block", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(1e3, Vector3(2, 2, 1)));
  const dynamics::Model m = b.build();
  const ContactSource corners = [](const Stage& s, std::vector<ContactPoint>& out) {
    for (double x : {-1.0, 1.0})
      for (double y : {-1.0, 1.0}) {
        const Vector3 p = s.data.X_WB[1].actPoint(Vector3(x, y, -0.5));
        if (p.z() < 0.0) out.push_back({0, 1, p, Vector3::UnitZ(), -p.z(), 0});
      }
  };
  ContactForce contact("ground", corners, {NormalLawKind::kHuntCrossley, 1e8, 1e8, 1.5, 0.0},
                       {0.3, 1e-3, FrictionForm::kTanh}, 4);
  Rig r(m, {&contact});
  r.q << 0.1, 0.2, 0.49, std::cos(0.002), std::sin(0.002), 0.0, 0.0;
  r.v.setConstant(0.1);
  r.step(1e-4);
  const auto scratch = contact.makeScratch();
  Stage s = r.stage();
  s.scratch = scratch.get();
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  double sink = 0.0;
  const std::size_t before = allocationCount();
  for (int k = 0; k < 10; ++k) {
    s.t = 1e-3 * k;
    contact.evaluate(s, f, tau);
    sink += contact.potentialEnergy(s) + contact.power(s) + static_cast<double>(contact.regime(s));
  }
  CHECK(allocationCount() == before);
  CHECK(static_cast<const ContactForce::Scratch&>(*scratch).points.size() == 4);
  CHECK(f.worldFrame(1)[5] > 0.0);  // (pushed up)
  CHECK(std::isfinite(sink));
}
