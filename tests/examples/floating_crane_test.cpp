// Regression test of examples/floating_crane (its rated_lift.yaml): the floating crane lifting
// its rated load in calm water. Statics against the weights (the hoist's 16 parts carry the hook
// and the load, the hull displaces the whole mass), the trim against the wall-sided hand
// calculation of the README (the hung load acting at the tip sheaves), no heel (the lift is in
// the centreline plane), and the 2 m hoist in time with the trim unchanged.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "devs/simulator.hpp"
#include "dynamics/model.hpp"
#include "models/multibody/multibody_model.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/channel_reader.hpp"
#include "support/record_collector.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

namespace {
constexpr double kG = 9.81;

using Reader = testing::ChannelReader;
}  // namespace

TEST_CASE("floating crane: rated lift statics and the hand-calculated trim and heel", "[long]") {
  auto scene = scene::loadSceneOrThrow(std::string(YARDSIM_SOURCE_DIR) +
                                       "/examples/floating_crane/rated_lift.yaml");
  auto root = scene::assemble(*scene);
  devs::Simulator sim(*root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  const auto& mb = static_cast<const models::MultibodyModel&>(*root->findComponent("mechanics"));
  const Reader read(mb);
  const dynamics::Model& m = mb.mechanics();
  auto mass = [&](const char* b) { return m.inertias[m.bodyIndex(b)].mass; };

  // 1. at rest in static equilibrium before the hoist starts
  sim.runUntil(9.0);
  const double hung = mass("FC.hook") + mass("load");
  REQUIRE(hung == Approx(3.08e6));
  CHECK(16.0 * read("FC.main_hoist.tension") == Approx(hung * kG).epsilon(1e-6));
  double total = hung;
  for (const char* b : {"FC.barge", "FC.ballast_aft_ps", "FC.ballast_aft_sb", "FC.ballast_fore_ps",
                        "FC.ballast_fore_sb", "FC.aframe", "FC.boom"})
    total += mass(b);
  CHECK(read("FC.hull.displacement") == Approx(total).epsilon(1e-6));

  // (masses in the barge frame, the hung load at the tip sheaves; the boom at its settled angle)
  // => trim of a wall-sided box (below z = 5 m: x from -60 to 54 m, 46 m wide):
  // x_G - x_c = tan(theta) (GM_L + BM_L tan^2(theta) / 2)
  const double q = read("FC.luff.q");
  CHECK(q == Approx(65.0 * M_PI / 180).margin(0.01));  // the luffing servo droops a little
  const double tipX = 44 + 100 * std::cos(q), tipZ = 12 + 100 * std::sin(q);
  const double items[][3] = {{7.5e6, -8, 5},
                             {3.0e6, -48, 3},
                             {3.0e6, -48, 3},
                             {1.0e5, 45, 3},
                             {1.0e5, 45, 3},
                             {6.0e5, 36, 30},
                             {1.1e6, 44 + 50 * std::cos(q), 12 + 50 * std::sin(q)},
                             {hung, tipX, tipZ}};
  double M = 0, mx = 0, mz = 0;
  for (const auto& it : items) {
    M += it[0];
    mx += it[0] * it[1];
    mz += it[0] * it[2];
  }
  REQUIRE(M == Approx(total));
  const double L = 114, B = 46, rho = 1025, xc = -3.0;
  const double T = M / (rho * L * B), BM = L * L / (12 * T), GM = T / 2 + BM - mz / M;
  double t = 0;
  for (int k = 0; k < 50; ++k) t = (mx / M - xc) / (GM + 0.5 * BM * t * t);
  const double trim = std::atan(t);
  INFO("trim " << read("FC.hull.trim") << " rad, hand " << trim << " rad");
  CHECK(read("FC.hull.trim") == Approx(trim).epsilon(2e-3));
  CHECK(std::abs(read("FC.hull.heel")) < 1e-6);

  // 2. the hoist lifts the load 2 m at 0.05 m/s from t = 10 s
  const double z0 = read("load.z");
  sim.runUntil(scene->until);
  std::map<std::string, double> finished;
  for (const auto& r : rec.ofKind("out"))
    if (r.port == "finished") finished[r.model] = r.t;
  REQUIRE(finished.count("lift") == 1);
  CHECK(finished.at("lift") == Approx(10.0 + 2.0 / 0.05).margin(1e-6));
  CHECK(read("load.z") - z0 == Approx(2.0).margin(0.03));
  CHECK(std::abs(read("FC.hull.trim") - trim) < 0.02 * trim);
}

// examples/floating_crane/long_wave.yaml: the crane (linear hydrostatics, the committed
// response's radiation and excitation) in a 0.5 m, 60 s head sea in 20 m of water (k = 0.00749
// 1/m, 839 m long). A wave this long lifts the barge quasi-statically: the heave at the keel
// point follows the mean elevation over the 114 m waterplane, sin(kL/2) / (kL/2) = 0.970 of the
// wave there, times the share of the Froude-Krylov heave force that the diffraction leaves in
// 20 m of water (0.913: the frequency-domain solve of the same panels, 4.657e7 against 5.098e7
// N/m; the horizontal flow under a 46 m wide keel with 17 m below it), 0.886, in phase, up to the
// dynamic terms of order (omega / omega_heave)^2 = 3 %; and it pitches with the waterplane's
// mean slope, 0.00184 rad (the diffraction changes the pitch moment by +0.5 % there), a quarter
// period behind the elevation at the keel point. The heave, pitch and elevation are fitted at the
// wave's frequency over two periods after the ramp. (Until the response's impulsive wave
// followed the depth it pitched 0.00050 rad: docs/hydrodynamics.md.)
TEST_CASE(
    "floating crane: heave in a long head sea follows the surface through the excitation "
    "response",
    "[long]") {  // 2 s in Release, about 220 s under the sanitizers
  auto scene = scene::loadSceneOrThrow(std::string(YARDSIM_SOURCE_DIR) +
                                       "/examples/floating_crane/long_wave.yaml");
  auto root = scene::assemble(*scene);
  devs::Simulator sim(*root);
  const auto& mb = static_cast<const models::MultibodyModel&>(*root->findComponent("mechanics"));
  const Reader read(mb);
  const double omega = 2 * M_PI / 60.0;
  // (channel samples over [180, 300) s) => amplitude and phase at omega about their mean
  std::vector<double> t, z, eta, pitch;
  for (double s = 180.0; s < 300.0 - 1e-9; s += 0.1) {
    sim.runUntil(s);
    t.push_back(s);
    z.push_back(read("FC.barge.z"));
    eta.push_back(read("FC.hull.wave_elevation"));
    pitch.push_back(read("FC.barge.pitch"));
  }
  auto fit = [&](const std::vector<double>& v) {
    const double n = static_cast<double>(v.size());
    double mean = 0, c = 0, sn = 0;
    for (double x : v) mean += x / n;
    for (size_t i = 0; i < v.size(); ++i) {
      c += (v[i] - mean) * std::cos(omega * t[i]);
      sn += (v[i] - mean) * std::sin(omega * t[i]);
    }
    return std::pair{2 * std::hypot(c, sn) / n, std::atan2(sn, c)};
  };
  const auto [za, zp] = fit(z);
  const auto [ea, ep] = fit(eta);
  const auto [pa, pp] = fit(pitch);
  INFO("heave " << za << " m at " << zp << " rad, elevation " << ea << " m at " << ep
                << " rad, pitch " << pa << " rad at " << pp << " rad");
  CHECK(ea == Approx(0.25).epsilon(0.01));  // the wave at the keel point
  CHECK(za / ea == Approx(0.886).epsilon(0.06));
  CHECK(std::abs(zp - ep) < 0.05);
  CHECK(pa == Approx(0.00184).epsilon(0.08));
  CHECK(std::abs(std::abs(pp - ep) - 0.5 * M_PI) < 0.1);
}
