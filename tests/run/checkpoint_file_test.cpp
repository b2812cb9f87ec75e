// Checkpoint files: the name, the header, and every way a file is refused (another scene,
// another yardsim, a truncated or altered file, something else altogether).
#include "run/checkpoint_file.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>

#include "devs/checkpoint_archive.hpp"
#include "run/runner.hpp"
#include "run/timeseries_writer.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using devs::CheckpointError;

namespace {
std::string springScene(double stiffness) {
  return "schema_version: 1\ncomponents:\n  s: {type: spring_mass, params: {mass: 1, stiffness: " +
         std::to_string(stiffness) +
         ", x0: 1, dt: 0.01, method: rk4, blowup_limit: 1000}}\nrecord: {interval: 0.1, channels: "
         "['s.*']}\nuntil: 3\n";
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
void spill(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}
}  // namespace

TEST_CASE("checkpoint names carry the time with three decimals") {
  CHECK(run::checkpointName(50.0) == "t000050.000.ckpt");
  CHECK(run::checkpointName(0.125) == "t000000.125.ckpt");
  CHECK(run::checkpointName(123456.5) == "t123456.500.ckpt");
}

TEST_CASE("a checkpoint file reads back its time and payload exactly") {
  testing::SceneDir dir;
  std::string payload = "abc";
  payload += '\0';
  payload += "\n\ndef";
  const auto file = dir.path() / "c/t.ckpt";
  run::writeCheckpointFile(file, "f00d", 0.1 + 0.2, payload);
  const auto back = run::readCheckpointFile(file, "f00d");
  CHECK(back.t == 0.1 + 0.2);
  CHECK(back.payload == payload);
  CHECK_FALSE(std::filesystem::exists(file.string() + ".tmp"));
  CHECK(slurp(file).rfind("YARDSIM-CHECKPOINT " + std::to_string(run::kCheckpointFormat) + "\nyardsim " + std::string(run::kVersion) + "\n",
                          0) == 0);
}

TEST_CASE("a checkpoint is refused for another scene, another yardsim, or a damaged file") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("a.yaml", springScene(1.0)));
  auto root = scene::assemble(*scene);
  run::RunOptions opt{dir.path() / "out", scene->until, {}, {}, 0.1, 2000};
  opt.checkpointEvery = 1.0;
  run::runScene(*scene, *root, opt);
  const auto file = dir.path() / "out/checkpoints/t000001.000.ckpt";
  REQUIRE(std::filesystem::exists(file));
  const std::string fingerprint = run::sceneFingerprint(*scene);
  CHECK(run::readCheckpointFile(file, fingerprint).t == 1.0);
  const std::string good = slurp(file);

  // (another scene: one parameter differs) => another fingerprint, refused
  auto other = scene::loadSceneOrThrow(dir.write("b.yaml", springScene(2.0)));
  CHECK(run::sceneFingerprint(*other) != fingerprint);
  CHECK_THROWS_WITH(run::readCheckpointFile(file, run::sceneFingerprint(*other)),
                    Catch::Contains("written for another scene"));
  // (the same scene file loaded again) => the same fingerprint
  auto again = scene::loadSceneOrThrow(dir.path() / "a.yaml");
  CHECK(run::sceneFingerprint(*again) == fingerprint);

  // (another yardsim version) => refused, naming both
  std::string v = good;
  v.replace(v.find("yardsim ") + 8, std::string(run::kVersion).size(), "9.9.9");
  spill(file, v);
  CHECK_THROWS_WITH(run::readCheckpointFile(file, fingerprint),
                    Catch::Contains("written by yardsim 9.9.9"));
  // (truncated anywhere: in the header, in the payload) => refused
  for (const std::size_t n :
       {std::size_t{0}, std::size_t{10}, std::size_t{60}, good.size() / 2, good.size() - 1}) {
    spill(file, good.substr(0, n));
    CHECK_THROWS_AS(run::readCheckpointFile(file, fingerprint), CheckpointError);
  }
  spill(file, good.substr(0, good.size() - 5));
  CHECK_THROWS_WITH(run::readCheckpointFile(file, fingerprint), Catch::Contains("truncated"));
  // (one byte of the state altered) => its SHA-256 differs, refused
  std::string altered = good;
  altered[altered.size() - 3] ^= 0x01;
  spill(file, altered);
  CHECK_THROWS_WITH(run::readCheckpointFile(file, fingerprint), Catch::Contains("SHA-256"));
  // (not a checkpoint, or missing) => refused
  spill(file, "schema_version: 1\n");
  CHECK_THROWS_WITH(run::readCheckpointFile(file, fingerprint),
                    Catch::Contains("not a yardsim checkpoint"));
  CHECK_THROWS_WITH(run::readCheckpointFile(dir.path() / "none.ckpt", fingerprint),
                    Catch::Contains("cannot open"));
  // (a device or a folder) => refused before reading (/dev/zero's header line has no end: the
  // mutation experiment's `--restart /dev/zero` grew without bound)
  CHECK_THROWS_WITH(run::readCheckpointFile("/dev/zero", fingerprint),
                    Catch::Contains("/dev/zero: not a regular file"));
  CHECK_THROWS_WITH(run::readCheckpointFile(dir.path(), fingerprint),
                    Catch::Contains("not a regular file"));
}

TEST_CASE("a restart from another scene's checkpoint or at the end time simulates nothing") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("a.yaml", springScene(1.0)));
  auto root = scene::assemble(*scene);
  run::RunOptions opt{dir.path() / "out", scene->until, {}, {}, 0.1, 2000};
  opt.checkpointEvery = 1.0;
  run::runScene(*scene, *root, opt);

  auto other = scene::loadSceneOrThrow(dir.write("b.yaml", springScene(2.0)));
  auto otherRoot = scene::assemble(*other);
  run::RunOptions again{dir.path() / "again", other->until, {}, {}, 0.1, 2000};
  again.restartFrom = dir.path() / "out/checkpoints/t000002.000.ckpt";
  CHECK_THROWS_AS(run::runScene(*other, *otherRoot, again), CheckpointError);
  CHECK_FALSE(std::filesystem::exists(dir.path() / "again/timeseries.csv"));

  auto same = scene::loadSceneOrThrow(dir.path() / "a.yaml");
  auto sameRoot = scene::assemble(*same);
  run::RunOptions late{dir.path() / "late", 1.5, {}, {}, 0.1, 2000};
  late.restartFrom = dir.path() / "out/checkpoints/t000002.000.ckpt";
  CHECK_THROWS_WITH(run::runScene(*same, *sameRoot, late),
                    Catch::Contains("nothing is left to run"));
}
