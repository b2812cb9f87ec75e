// examples/yard/goliath_turnover.yaml takes its block (from_db, lugs as rope points), cranes
// (facility) and hoist ropes (catalogue) from the fixture database that
// examples/yard/build_fixture.sh builds from the examples' own data. Run as processes, it must
// give exactly what examples/goliath_turnover/scene.yaml gives: trace.jsonl byte for byte, and
// timeseries.csv byte for byte but for the two header lines that name the scene file and its hash.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "support/scene_files.hpp"
#include "support/shell_command.hpp"
#include "support/test_paths.hpp"

using Catch::Matchers::Contains;
using yardsim::testing::shell;

namespace {

const std::string kYardsim = YARDSIM_EXE;
const std::string kSource = YARDSIM_SOURCE_DIR;

// (file) => its bytes
std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// (timeseries.csv text) => without the "# scene " and "# scene_sha256 " header lines
std::string withoutSceneLines(const std::string& text) {
  std::istringstream in(text);
  std::string out, line;
  while (std::getline(in, line))
    if (line.rfind("# scene ", 0) != 0 && line.rfind("# scene_sha256 ", 0) != 0) out += line + "\n";
  return out;
}

}  // namespace

TEST_CASE(
    "the goliath turnover from the yard database equals the hand-typed scene to the last digit",
    "[long]") {
  yardsim::testing::SceneDir dir;
  const std::string db = dir.file("yard.sqlite");
  auto r = shell(kSource + "/examples/yard/build_fixture.sh " + kYardsim + " " + db);
  INFO(r.out);
  REQUIRE(r.status == 0);
  r = shell(kYardsim + " run " + kSource +
            "/examples/goliath_turnover/scene.yaml --trace jsonl -o " + dir.file("typed"));
  INFO(r.out);
  REQUIRE(r.status == 0);
  r = shell("env YARDSIM_DB=" + db + " " + kYardsim + " run " + kSource +
            "/examples/yard/goliath_turnover.yaml --trace jsonl -o " + dir.file("db"));
  INFO(r.out);
  REQUIRE(r.status == 0);
  const std::string typedTrace = slurp(dir.path() / "typed/trace.jsonl");
  REQUIRE(typedTrace.size() > 100000);  // a whole run's trace, not an empty file
  CHECK(slurp(dir.path() / "db/trace.jsonl") == typedTrace);
  const std::string typedSeries = slurp(dir.path() / "typed/timeseries.csv");
  const std::string dbSeries = slurp(dir.path() / "db/timeseries.csv");
  CHECK_THAT(dbSeries, Contains("# scene_sha256 "));
  CHECK(withoutSceneLines(dbSeries) == withoutSceneLines(typedSeries));
  CHECK(withoutSceneLines(dbSeries).size() + 200 > typedSeries.size());  // only those lines dropped
  // the same, as the brief asks: cmp on the files (the series without the two lines)
  std::ofstream(dir.file("typed.csv")) << withoutSceneLines(typedSeries);
  std::ofstream(dir.file("db.csv")) << withoutSceneLines(dbSeries);
  CHECK(shell("cmp " + dir.file("typed.csv") + " " + dir.file("db.csv")).status == 0);
  CHECK(shell("cmp " + dir.file("typed/trace.jsonl") + " " + dir.file("db/trace.jsonl")).status ==
        0);
  // and where the values came from
  r = shell("env YARDSIM_DB=" + db + " " + kYardsim + " validate --print-resolved " + kSource +
            "/examples/yard/goliath_turnover.yaml");
  CHECK(r.status == 0);
  CHECK_THAT(r.out,
             Contains("block.mass = 920000 kg  <- blocks row 1 'GT-BLOCK-920'") &&
                 Contains("GOC202.lower_aft.EA = 2e+08 N  <- ropes row 1") &&
                 Contains("GOC201.params.hoist_speed = 0.083  <- facilities row 1 'GOC201'") &&
                 Contains("(lug L202A)") &&
                 Contains("hook-load check GOC202 (facility GOC202, from GOC202.gantry)"));
  // both cranes' hook loads (about 4.8 MN each, peaks 1.18 x) stay under their curves (7.36 MN)
  CHECK_THAT(slurp(dir.path() / "db/run.json"), !Contains("over_hook_load"));
}
