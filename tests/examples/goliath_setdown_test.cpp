// examples/goliath_turnover/scene_setdown.yaml: the turnover with collision on. The block is set
// down on the two dock supports: at rest there, the support reactions and what the hoist ropes
// still carry balance the weight of the block and its loader (statics, from the model's masses
// and the ropes' tension channels); the lower ropes stay clear of the loader beam, the upper ropes
// lie on the block's side face where the loader holds them; contact starts once,
// during the lowering; the energy balance closes.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

TEST_CASE("goliath set-down: the supports carry the weight and the rope clearances are reported",
          "[long]") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(std::string(YARDSIM_SOURCE_DIR) +
                                       "/examples/goliath_turnover/scene_setdown.yaml");
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / "out", scene->until, {"jsonl"}, {}, 0.1});
  const testing::CsvFile csv((dir.path() / "out" / "timeseries.csv").string());
  auto col = [&](const std::string& name) {
    const int k = csv.column(name);
    REQUIRE(k >= 0);
    return static_cast<std::size_t>(k);
  };
  const std::size_t last = csv.rows.size() - 1;
  const auto& end = csv.rows[last];
  // (masses of the block, the loader clamp and the beam) => the weight resting on the supports
  const double weight = (9.2e5 + 1.0e4 + 4.0e4) * 9.81;
  double ropes = 0.0;  // what the hoists still carry: 4 parts each, hanging within a few degrees
  for (const char* c : {"GOC201", "GOC202"})
    for (const char* r : {"upper_fore", "upper_aft", "lower_fore", "lower_aft"})
      ropes += 4 * end[col(std::string(c) + "." + r + ".tension[N]")];
  const double supports =
      -(end[col("collision.support_fore.fz[N]")] + end[col("collision.support_aft.fz[N]")]);
  CHECK(end[col("collision.points[-]")] >= 4);
  CHECK(end[col("collision.block.fz[N]")] == Approx(supports).epsilon(1e-9));
  CHECK(supports > 0.9 * weight);  // the supports carry the block
  CHECK(supports + ropes == Approx(weight).epsilon(2e-3));
  // (where the forces act) => the block's point of application is the supports' points weighted
  // by their reactions (the same contact points, seen from both sides), between the supports'
  // centres (x = 22 and 38 m), on their tops; none before contact (NaN)
  const double fore = -end[col("collision.support_fore.fz[N]")],
               aft = -end[col("collision.support_aft.fz[N]")];
  for (const char* axis : {"px", "py", "pz"}) {
    const std::string a(axis);
    const double mean = (fore * end[col("collision.support_fore." + a + "[m]")] +
                         aft * end[col("collision.support_aft." + a + "[m]")]) /
                        (fore + aft);
    CHECK(end[col("collision.block." + a + "[m]")] == Approx(mean).margin(0.05));
    CHECK(std::isnan(csv.rows[0][col("collision.block." + a + "[m]")]));
  }
  CHECK(end[col("collision.block.px[m]")] > 22.0);
  CHECK(end[col("collision.block.px[m]")] < 38.0);
  CHECK(end[col("collision.support_fore.px[m]")] == Approx(22.0).margin(2.0));  // on its 4 m top
  CHECK(end[col("collision.support_aft.px[m]")] == Approx(38.0).margin(2.0));
  // (the whole operation) => the minimum clearances, all positive, the block's inside its range
  double minBlock = 1e9, minBeam = 1e9;
  for (const auto& row : csv.rows) {
    minBlock = std::min(minBlock, row[col("rope_block.distance[m]")]);
    minBeam = std::min(minBeam, row[col("rope_beam.distance[m]")]);
  }
  INFO("minimum clearance rope-block " << minBlock << " m, rope-beam " << minBeam << " m");
  CHECK(minBeam > 0.5);  // the lower ropes stay clear of the beam
  // the upper ropes run down the block's side face to the loader's lugs on it (the example's
  // geometry): their capsules (radius 0.018 m) lie on the face from the start, so the minimum is
  // about minus a radius, and no crossing is located (nothing crosses: it starts there)
  CHECK(minBlock < 0.0);
  CHECK(minBlock > -0.03);
  CHECK(csv.rows[0][col("rope_block.distance[m]")] < 0.0);
  std::ifstream trace(dir.path() / "out" / "trace.jsonl");
  int contacts = 0, releases = 0, below = 0, touched = 0;
  for (std::string line; std::getline(trace, line);) {
    if (line.find("\"kind\":\"out\"") == std::string::npos)
      continue;  // the model's, not the actors' copies
    if (line.find("rope_block clearance_below") != std::string::npos) ++below;
    if (line.find("rope_block touched") != std::string::npos) {
      ++touched;
      CHECK(line.find("upper_") != std::string::npos);
      CHECK(line.find("block at (") != std::string::npos);
    }
    if (line.find("collision contact") != std::string::npos) {
      ++contacts;
      CHECK(std::stod(line.substr(line.find("\"t\":") + 4)) > 400.0);
    }
    if (line.find("collision release") != std::string::npos) ++releases;
  }
  CHECK(contacts == 1);  // contact once, in the lowering (after 400 s), never released
  CHECK(releases == 0);
  CHECK(below == 0);
  CHECK(touched == 0);
  // the energy balance over the whole run, against the energy exchanged
  const double drift = std::abs(end[col("mechanics.energy_balance[J]")] -
                                csv.rows[0][col("mechanics.energy_balance[J]")]);
  CHECK(drift < 1e-3 * weight * 10.0);
}
