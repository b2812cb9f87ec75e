// Reading a scene file: one YAML document, a mapping, from a regular file below the size limit;
// anything else refused with the place and the reason before it is parsed (a device or a FIFO
// would never end, a huge file would take the memory).
#include "scene/yaml_source.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <fstream>

#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
std::string errors(const std::filesystem::path& file) {
  models::Diagnostics d;
  CHECK_FALSE(scene::readYamlFile(file, {}, "", d));
  return d.report();
}
}  // namespace

TEST_CASE("a scene file is one YAML document, a mapping, in a regular file of at most 16 MiB") {
  testing::SceneDir dir;
  CHECK_THAT(errors("/dev/zero"), Catch::Contains("'/dev/zero' is not a regular file"));
  CHECK_THAT(errors(dir.write("two.yaml", "schema_version: 1\n---\nfoo: 1\n")),
             Catch::Contains("two.yaml:2:1") &&
                 Catch::Contains("a second one starts here"));  // at the '---' line
  CHECK_THAT(errors(dir.write("list.yaml", "- 1\n- 2\n")), Catch::Contains("must be a mapping"));
  CHECK_THAT(errors(dir.path() / "missing.yaml"), Catch::Contains("cannot read scene file"));
  {
    std::ofstream big(dir.path() / "big.yaml");
    big << "schema_version: 1\n# " << std::string(scene::kMaxSceneFileBytes, 'x') << "\n";
  }
  CHECK_THAT(errors(dir.path() / "big.yaml"), Catch::Contains("a scene file has at most 16777216"));
  models::Diagnostics d;
  CHECK(scene::readYamlFile(dir.write("ok.yaml", "schema_version: 1\n"), {}, "", d));
  CHECK_FALSE(d.hasErrors());
}

TEST_CASE("an include of a device is refused at the include, not read") {
  testing::SceneDir dir;
  const auto r = scene::loadScene(
      dir.write("s.yaml", "schema_version: 1\ncomponents:\n  x: {include: /dev/urandom}\n"));
  CHECK_FALSE(r.scene);
  CHECK_THAT(r.diagnostics.report(),
             Catch::Contains("s.yaml:3:16") && Catch::Contains("not a regular file"));
}

TEST_CASE("a YAML alias bomb is refused at once, not expanded") {
  // 10 levels of 10 aliases each: 10^10 nodes from a dozen lines
  std::string bomb = "schema_version: 1\na: &a [x, x, x, x, x, x, x, x, x, x]\n";
  for (char c = 'b'; c <= 'j'; ++c) {
    const char p = static_cast<char>(c - 1);
    bomb += std::string(1, c) + ": &" + c + " [";
    for (int i = 0; i < 10; ++i) bomb += std::string(i ? ", *" : "*") + p;
    bomb += "]\n";
  }
  testing::SceneDir dir;
  CHECK_THAT(errors(dir.write("bomb.yaml", bomb)),
             Catch::Contains("expands to more than 1000000 nodes"));
}

TEST_CASE("a mapping key that is not a plain name is refused at its place") {
  testing::SceneDir dir;
  // (fuzzer finding) a list or an empty key reached the readers' key checks and threw there
  CHECK_THAT(errors(dir.write("list_key.yaml", "schema_version: 1\nparams:\n  ? [a, b]\n  : 1\n")),
             Catch::Contains("list_key.yaml:3:5") &&
                 Catch::Contains("a key must be a plain name, got a list"));
  CHECK_THAT(errors(dir.write("null_key.yaml", "schema_version: 1\n~: 2\n")),
             Catch::Contains("null_key.yaml:2:1") && Catch::Contains("a key must be a plain name"));
  models::Diagnostics d;
  CHECK(scene::readYamlFile(dir.write("plain.yaml", "schema_version: 1\n1: 2\ntrue: 3\n"), {}, "",
                            d));
}

TEST_CASE("a stray comma before the first node is a located syntax error and does not hang") {
  // (fuzzer finding, scene_loader_fuzz timeout) yaml-cpp's LoadAll read this as empty documents
  // without end, taking all the memory; the loader now stops at the second document
  testing::SceneDir dir;
  const auto start = std::chrono::steady_clock::now();
  CHECK_THAT(errors(dir.write("comma.yaml", "# a comment\n, (x)\nschema_version: 1\n")),
             Catch::Contains("comma.yaml:2:1") &&
                 Catch::Contains("YAML syntax error: ',' outside any mapping or list"));
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
}

TEST_CASE("an alias inside its own anchor is refused and does not overflow the stack") {
  // (fuzzer finding, scene_loader_fuzz stack overflow) a: &a [x, *a] is a node that contains
  // itself; counting its nodes recursed without end
  testing::SceneDir dir;
  CHECK_THAT(errors(dir.write("self.yaml", "schema_version: 1\na: &a [x, *a, *a]\n")),
             Catch::Contains("self.yaml:1:1") && Catch::Contains("nests deeper than 64 levels"));
  // 60 levels of lists are still a document (a scene nests a dozen)
  models::Diagnostics d;
  CHECK(scene::readYamlFile(dir.write("deep.yaml", "schema_version: 1\na: " + std::string(60, '[') +
                                                       std::string(60, ']') + "\n"),
                            {}, "", d));
}

TEST_CASE("resolveRefs replaces every $name at any depth and keeps the rest and its places") {
  // (a document with references in maps, sequences of maps, an empty map and list, a literal
  // "!" string and an unknown name; a scope of a number and of a mapping) => the resolved copy:
  // the same structure and scalars, parameters' values in place of their names, the scalars of
  // the file with their line and column, the unknown name reported at its place and null
  const YAML::Node doc = YAML::Load(
      "a: $len\n"
      "b:\n"
      "  - {x: 1, y: $len}\n"
      "  - [$pose, 2]\n"
      "c: {}\n"
      "d: []\n"
      "f: ! $len\n"
      "g: $nope\n");
  scene::Scope scope;
  scope.values["len"] = YAML::Load("12.5");
  scope.values["pose"] = YAML::Load("{at: [1, 2, 3]}");
  models::Diagnostics d;
  const YAML::Node r = scene::resolveRefs(doc, scope, "s.yaml", "", d);
  CHECK(r["a"].as<double>() == 12.5);
  CHECK(r["b"][0]["x"].as<int>() == 1);
  CHECK(r["b"][0]["y"].as<double>() == 12.5);
  CHECK(r["b"][1][0]["at"][2].as<int>() == 3);
  CHECK(r["b"][1][1].as<int>() == 2);
  CHECK(r["c"].IsMap());
  CHECK(r["c"].size() == 0);
  CHECK(r["d"].IsSequence());
  CHECK(r["d"].size() == 0);
  CHECK(r["f"].as<std::string>() == "$len");  // "!": a literal string
  CHECK(r["g"].IsNull());
  CHECK(r.size() == 6);
  CHECK_THAT(d.report(),
             Catch::Contains("s.yaml:8:4") && Catch::Contains("unknown parameter 'nope'"));
  CHECK(r["b"][0]["x"].Mark().line == 2);  // a scalar of the file keeps its place
  CHECK(r["b"][1][1].Mark().column == 12);
  // the source is not changed, and a second resolution of it gives the same text
  CHECK(doc["a"].as<std::string>() == "$len");
  CHECK(YAML::Dump(doc["b"]) == "- {x: 1, y: $len}\n- [$pose, 2]");
  models::Diagnostics d2;
  CHECK(YAML::Dump(scene::resolveRefs(doc, scope, "s.yaml", "", d2)) == YAML::Dump(r));
}
