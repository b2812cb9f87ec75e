// The providers allocate nothing once built: evaluate(), potentialEnergy(), power() and the
// reports of every provider in this folder, with every global operator new counted.
#include <catch2/catch.hpp>

#include "support/allocation_counter.hpp"

#include <vector>

#include "force_rig.hpp"
#include "forces/body_load.hpp"
#include "forces/rope.hpp"
#include "forces/gravity.hpp"
#include "forces/rope.hpp"
#include "forces/current_load.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/hydrostatics.hpp"
#include "forces/hydro/impulse_response_force.hpp"
#include "forces/hydro/irregular_sea.hpp"
#include "forces/linear_quadratic_damping.hpp"
#include "forces/wind_load.hpp"
#include "forces/bushing.hpp"
#include "forces/lines/catenary_line.hpp"
#include "forces/lines/lumped_line.hpp"
#include "forces/rotational_spring_damper.hpp"
#include "forces/spring_damper.hpp"
#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/rankine_td_provider.hpp"

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

TEST_CASE("catenary lines do not allocate at a stage") {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("barge", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(2e6, Vector3(40, 12, 5)));
  const dynamics::Model m = b.build();
  CatenaryLine taut("taut", m, {0, Vector3(-420, 0, -150)}, {1, Vector3(-20, 0, 0)},
                    {500.0, 7.5e8, 1020.0, true, 0.0});
  CatenaryLine friction("friction", m, {0, Vector3(420, 0, -150)}, {1, Vector3(20, 0, 0)},
                        {500.0, 7.5e8, 1020.0, true, 1.0});
  Rig r(m, {&taut, &friction});
  r.q << 0.5, 0.2, 0.1, 1.0, 0.0, 0.0, 0.0;
  r.v.setConstant(0.1);
  r.step(1e-2);
  const Stage s = r.stage();
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  const std::size_t before = allocationCount();
  double sink = 0.0;
  for (ForceProvider* fp : std::initializer_list<ForceProvider*>{&taut, &friction}) {
    fp->evaluate(s, f, tau);
    sink += fp->potentialEnergy(s) + fp->power(s);
  }
  sink += taut.fairleadStiffness(s).norm() + friction.state(s).solution.laidLength;
  CHECK(allocationCount() == before);
  CHECK(std::isfinite(sink));
}

TEST_CASE("a lumped line's node forces and masses do not allocate") {
  LumpedLineProperties p;
  p.length = 100.0;
  p.segments = 10;
  p.diameter = 0.1;
  p.massPerLength = 80.0;
  p.ea = 5e8;
  p.damping = -0.5;
  p.cdn = 1.2;
  p.cdt = 0.4;
  p.can = 1.0;
  p.cat = 0.1;
  p.seabed = true;
  p.seabedZ = -60.0;
  p.bedStiffness = 1e6;
  p.bedFriction = 0.5;
  WaterProperties water;
  water.depth = 60.0;
  const AiryWaves waves(water, {{2.0, 8.0, 0.0, 0.0}});
  CurrentProperties cp;
  cp.speed = 0.5;
  const CurrentField current(cp);
  const LumpedLine line(p, "line", &waves, &current);
  Eigen::Matrix3Xd r(3, 11), v(3, 11), f(3, 11);
  for (int i = 0; i <= 10; ++i) r.col(i) = Vector3(9.0 * i, 0.0, -60.0 + 5.0 * i);
  v.setConstant(0.1);
  Eigen::VectorXd tension(10);
  std::vector<dynamics::Matrix3> m(11);
  const std::size_t before = allocationCount();
  line.nodeForces(r, v, 1.0, f, tension);
  line.nodeMass(r, m);
  const double e = line.potentialEnergy(r);
  CHECK(allocationCount() == before);
  CHECK(std::isfinite(e + f.sum() + tension.sum() + m[3].sum()));
}

TEST_CASE("the rankine_td provider does not allocate at a stage or a panel step") {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("float", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(2e3, Vector3(2, 2, 1)));
  const dynamics::Model m = b.build();
  hydro::RankineTdSettings settings;
  settings.freeSurface.truncationRadius = 8.0;
  settings.freeSurface.firstSpacing = 0.3;
  settings.freeSurface.maxSpacing = 1.0;
  settings.freeSurface.dampingWidth = 3.0;
  settings.freeSurface.dampingStrength = 1.0;
  const auto panels = std::make_shared<const hydro::RankineTdModel>(
      hydro::cubeSphere(1.0, 4), dynamics::Transform{}, settings);
  const hydro::RankineTdProvider radiation("radiation", m, 1, panels, 0.1);
  Rig r(m, {});
  r.v[2] = 0.3;  // moving, so that the march has something to do
  const Stage s = r.stage();
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  auto scratch = radiation.makeScratch();
  double sink = 0.0;
  const std::size_t before = allocationCount();
  for (int n = 0; n < 6; ++n) {
    // (a step's first stage at t = n dt / 2: a panel step every other one) => evaluate and power
    Stage own = s;
    own.t = own.stepStart = 0.05 * n;
    own.scratch = scratch.get();
    radiation.evaluate(own, f, tau);
    own.t += 0.025;
    radiation.evaluate(own, f, tau);
    sink += radiation.power(own);
  }
  CHECK(allocationCount() == before);
  CHECK(sink != 0.0);
}

TEST_CASE("the impulse-response force does not allocate at a stage") {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("barge", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(3e5, Vector3(20, 8, 4)));
  const dynamics::Model m = b.build();
  // (60 s of memory at 0.05 s, one heading, a sea of 50 components)
  auto ir = std::make_shared<hydro::ImpulseResponse>();
  ir->dt = 0.05;
  ir->radiation.assign(1200, hydro::ImpulseResponse::Matrix6::Identity());
  ir->headings = {0.0};
  ir->excitationStart = -2.0;
  ir->excitation.assign(1, std::vector<hydro::ImpulseResponse::Vector6>(80, hydro::ImpulseResponse::Vector6::Ones()));
  hydro::IrregularSea spec;
  spec.hs = 2.0, spec.tp = 8.0, spec.components = 50;
  const auto sea = std::make_shared<const AiryWaves>(WaterProperties{}, hydro::irregularWaves(spec));
  const hydro::ImpulseResponseForce p("radiation", m, 1, ir, sea);
  auto scratch = p.makeScratch();
  dynamics::Data data(m);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m.nq), v = Eigen::VectorXd::Constant(m.nv, 0.1);
  q[3] = 1.0;
  dynamics::forwardKinematics(m, data, q, v);
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  p.evaluate(Stage{0.0, m, data, q, v, scratch.get(), 0.0}, f, tau);  // (the first commit)
  std::vector<double> carried;  // (a checkpoint's buffer, the caller's)
  carried.reserve(20000);
  const std::size_t before = allocationCount();
  double sink = 0.0;
  for (int i = 1; i < 50; ++i) {  // (commits at the steps' starts, stages between, a step again)
    const double t = 0.04 * i;
    p.evaluate(Stage{t, m, data, q, v, scratch.get(), t}, f, tau);
    p.evaluate(Stage{t + 0.02, m, data, q, v, scratch.get(), t}, f, tau);
    sink += p.power(Stage{t + 0.04, m, data, q, v, scratch.get(), t});
  }
  p.evaluate(Stage{1.0, m, data, q, v, scratch.get(), 1.0}, f, tau);
  scratch->carried(carried);
  scratch->restoreCarried(carried);
  CHECK(allocationCount() == before);
  CHECK(carried.size() > 7200);
  CHECK(std::isfinite(sink));
  CHECK(sink != 0.0);
}
