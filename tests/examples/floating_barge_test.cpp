// examples/floating_barge against the hand formulas of its README: the equilibrium draft
// m / (rho L B), the trim x_G / GM_L, the steady wind heel F_y (z_wind - z_damping) / (m g GM_T),
// the roll period 2 pi sqrt(I_eff / (m g GM_T)) with I_eff = I_xx - I_xz^2 / I_zz about G, the
// energy balance, and the beam sea rolling the barge once it has grown (run to 80 s of 150); and
// irregular_sea.yaml: the barge in an irregular swell on the impulse-response path.
#include <catch2/catch.hpp>
#include <cmath>

#include "forces/hydro/irregular_sea.hpp"
#include "forces/hydro/wave_spectrum.hpp"
#include "scene/assembler.hpp"
#include "scene/mechanical_systems.hpp"
#include "run/runner.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

namespace {
// rad/s: irregular_sea.yaml's `cutoff` (its synthetic response's excitation window)
constexpr double kIrregularCutoff = 2.0;
}  // namespace

TEST_CASE(
    "floating barge: draft, trim, wind heel and roll period of the hand formulas, and waves roll "
    "it",
    "[long]") {
  auto scene = scene::loadSceneOrThrow(std::string(YARDSIM_SOURCE_DIR) + "/examples/floating_barge/scene.yaml");
  auto root = scene::assemble(*scene);
  testing::SceneDir out;
  run::runScene(*scene, *root, {out.path(), 80.0, {}, {}, 0.1});
  const testing::CsvFile csv((out.path() / "timeseries.csv").string());
  const int t = 0, draft = csv.column("hull.draft[m]"), heel = csv.column("hull.heel[rad]"),
            trim = csv.column("hull.trim[rad]"), gm = csv.column("hull.gm_t[m]"),
            disp = csv.column("hull.displacement[kg]"), fy = csv.column("wind.fy[N]"),
            balance = csv.column("mechanics.energy_balance[J]"), work = csv.column("mechanics.work[J]");
  REQUIRE(std::min({draft, heel, trim, gm, disp, fy, balance, work}) > 0);

  // (the barge: 60 x 20 x 5 box, 1500 t with G 2 m above the keel; the crane: 500 t, G at x = 10, z = 13)
  const double rho = 1025.0, g = 9.81, L = 60.0, B = 20.0, mb = 1.5e6, mc = 5e5, m = mb + mc;
  const double T = m / (rho * L * B), KG = (mb * 2.0 + mc * 13.0) / m, xG = mc * 10.0 / m;
  const double GMt = T / 2 + B * B / (12 * T) - KG, GMl = T / 2 + L * L / (12 * T) - KG;
  const double Ixx = 5.3125e7 + mb * std::pow(KG - 2.0, 2) + 4.5e6 + mc * std::pow(13.0 - KG, 2);
  const double Izz = 5.0e8 + mb * xG * xG + 2.0e6 + mc * std::pow(10.0 - xG, 2);
  const double Ixz = -(mb * (0.0 - xG) * (2.0 - KG) + mc * (10.0 - xG) * (13.0 - KG));
  const double period = 2 * M_PI * std::sqrt((Ixx - Ixz * Ixz / Izz) / (m * g * GMt));

  // (calm phase, settled: 50 .. 60 s) => mean draft, trim, heel
  double sDraft = 0, sTrim = 0, sHeel = 0, sFy = 0, n = 0;
  std::vector<double> crossings;
  for (std::size_t k = 1; k < csv.rows.size(); ++k) {
    const auto& r = csv.rows[k];
    if (r[t] >= 50.0 && r[t] < 60.0) {
      sDraft += r[draft];
      sTrim += r[trim];
      sHeel += r[heel];
      sFy += r[fy];
      n += 1;
    }
  }
  const double meanHeel = sHeel / n;
  CHECK(sDraft / n == Approx(T).epsilon(1e-3));
  CHECK(csv.rows[csv.rows.size() / 2][disp] == Approx(m).epsilon(2e-3));
  CHECK(sTrim / n == Approx(std::atan(xG / GMl)).epsilon(0.01));
  // (wind towards -y, F_y < 0) => heel > 0: starboard (-y) down, leaning away from the wind
  CHECK(meanHeel == Approx(-sFy / n * (7.0 - 0.8) / (m * g * GMt)).epsilon(0.05));
  CHECK(csv.rows[1000][gm] == Approx(GMt).epsilon(0.01));
  // (roll decay about the wind heel, 0 .. 50 s) => upward crossings one period apart
  for (std::size_t k = 1; k < csv.rows.size() && csv.rows[k][t] < 50.0; ++k) {
    const double a = csv.rows[k - 1][heel] - meanHeel, b = csv.rows[k][heel] - meanHeel;
    if (a < 0 && b >= 0) crossings.push_back(csv.rows[k - 1][t] + (csv.rows[k][t] - csv.rows[k - 1][t]) * -a / (b - a));
  }
  REQUIRE(crossings.size() >= 8);
  CHECK((crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1) ==
        Approx(period).epsilon(0.003));
  // (beam sea from 60 s, grown by 75 s) => rolling of more than a degree; energy balance closed
  double roll = 0, worst = 0;
  const double scale = std::abs(csv.rows.back()[work]) + m * g * 1.0;
  for (const auto& r : csv.rows) {
    if (r[t] > 75.0) roll = std::max(roll, std::abs(r[heel] - meanHeel));
    worst = std::max(worst, std::abs(r[balance] - csv.rows[0][balance]));
  }
  CHECK(roll > 1.0 * M_PI / 180);
  CHECK(worst < 1e-6 * scale);
}

// examples/floating_barge/irregular_sea.yaml: the barge on the impulse-response path in a JONSWAP
// beam swell (Hs 1.5 m, Tp 12 s, cut at its synthetic response's window, 2 rad/s). The sea's
// components carry Hs^2/16 times the spectrum's share below the cut (F(w_c) by the spectrum's
// cumulative, independent of the components), and the recorded elevation at the barge has that
// variance over 40 .. 300 s; a swell this long (225 m at the peak, the barge 20 m wide) lifts the
// barge nearly quasi-statically at the peak (dynamic amplification 1 / (1 - (w / w_heave)^2),
// w_heave = 1.55 rad/s with the file's A33: 1.13 at the peak); the components near the resonance
// add to it (below).
TEST_CASE("floating barge in an irregular swell: the sea's variance, and it heaves with the swell",
          "[long]") {
  auto scene = scene::loadSceneOrThrow(std::string(YARDSIM_SOURCE_DIR) +
                                       "/examples/floating_barge/irregular_sea.yaml");
  // (the scene's sea) => its components' variance against the spectrum's energy below the cut
  forces::hydro::IrregularSea swell;
  swell.hs = 1.5;
  swell.tp = 12.0;
  swell.gamma = 3.3;
  swell.cutoff = kIrregularCutoff;
  const forces::hydro::WaveSpectrum spectrum(swell.spectrum, swell.hs, swell.tp, swell.gamma);
  const double m0 = swell.hs * swell.hs / 16,
               kept = (spectrum.cumulative(swell.cutoff) / m0 - 0.001) / 0.998;
  const auto& waves = scene->systems.at(0)->spec.waves;
  REQUIRE(waves.size() == 200);
  double variance = 0, highest = 0;
  for (const auto& w : waves) {
    variance += w.height * w.height / 8;
    highest = std::max(highest, 2 * M_PI / w.period);
  }
  CHECK(variance == Approx(kept * m0).epsilon(1e-9));
  CHECK(highest <= swell.cutoff);
  CHECK(kept > 0.99);  // (a 12 s swell has next to nothing above 2 rad/s)
  auto root = scene::assemble(*scene);
  testing::SceneDir out;
  run::runScene(*scene, *root, {out.path(), 300.0, {}, {}, 0.1});
  const testing::CsvFile csv((out.path() / "timeseries.csv").string());
  const int t = 0, eta = csv.column("hull.wave_elevation[m]"), z = csv.column("barge.z[m]");
  REQUIRE(std::min(eta, z) > 0);
  // (40 .. 300 s, after the ramp) => variances and the correlation of heave and elevation
  double n = 0, se = 0, sz = 0;
  for (const auto& r : csv.rows)
    if (r[t] >= 40.0) n += 1, se += r[eta], sz += r[z];
  const double me = se / n, mz = sz / n;
  double vee = 0, vzz = 0, vez = 0;
  for (const auto& r : csv.rows)
    if (r[t] >= 40.0) {
      vee += (r[eta] - me) * (r[eta] - me) / n;
      vzz += (r[z] - mz) * (r[z] - mz) / n;
      vez += (r[eta] - me) * (r[z] - mz) / n;
    }
  const double ratio = std::sqrt(vzz / vee), correlation = vez / std::sqrt(vee * vzz);
  INFO("elevation variance " << vee << " m^2 against " << kept * m0 << " m^2; heave/elevation "
                             << ratio << ", correlation " << correlation);
  CHECK(vee == Approx(kept * m0).epsilon(0.15));
  // (heave against elevation) => it heaves with the swell, more than the quasi-static lift: the
  // sea reaches 2 rad/s, past the heave resonance at 1.55 rad/s, where the synthetic response's
  // made-up radiation damping is light (measured 2026-11-28: ratio 1.68, correlation 0.79; the
  // first estimate of 0.85 .. 1.35 and > 0.9 assumed a quasi-static lift and did not hold)
  CHECK(ratio > 0.85);
  CHECK(ratio < 2.5);
  CHECK(correlation > 0.6);
}
