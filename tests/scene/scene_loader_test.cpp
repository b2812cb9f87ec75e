#include "scene/scene_loader.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>

#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;
using models::Diagnostic;

namespace {

// (file text) => the diagnostics of loading it
scene::LoadResult load(const testing::SceneDir& dir, const std::string& text,
                        const std::string& name = "scene.yaml") {
  return scene::loadScene(dir.write(name, text));
}

Diagnostic only(const scene::LoadResult& r) {
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 1);
  for (const auto& d : r.diagnostics.all())
    if (d.severity == Diagnostic::Severity::Error) return d;
  FAIL("no error");
  throw;
}

}  // namespace

TEST_CASE("a valid two-file scene loads with its overrides applied") {
  testing::SceneDir dir;
  dir.write("frame.yaml", R"(schema_version: 1
params: {period: 1.0, observe: 10.0}
inputs: {in: int}
outputs: {out: int}
components:
  genr: {type: generator, params: {period: $period}}
  transd: {type: transducer, params: {observe: $observe}}
couplings:
  - {from: genr.out, to: out}
  - {from: genr.out, to: transd.arrived}
  - {from: in, to: transd.solved}
  - {from: transd.stop, to: genr.stop}
)");
  const auto r = load(dir, R"(schema_version: 1
params: {p: 2.5}
components:
  a: {include: frame.yaml, params: {period: $p}, placement: {xyz: [1, 2, 3], rpy_deg: [0, 0, 90]}}
  b: {include: frame.yaml, params: {observe: 4}}
  proc: {type: processor, params: {processing_time: 0.5}}
couplings:
  - {from: a.out, to: proc.in}
  - {from: proc.out, to: a.in}
  - {from: b.out, to: b.in}
until: 30
)");
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  const auto& root = r.scene->root;
  REQUIRE(root.children.size() == 3);
  const auto* a = root.child("a");
  const auto* b = root.child("b");
  CHECK(a->child("genr")->params.number("period") == 2.5);   // override from the scene's $p
  CHECK(a->child("transd")->params.number("observe") == 10.0);  // the file's default
  CHECK(b->child("genr")->params.number("period") == 1.0);
  CHECK(b->child("transd")->params.number("observe") == 4.0);
  CHECK(a->child("genr")->path == "a.genr");
  CHECK(a->placement.xyz == std::array<double, 3>{1, 2, 3});
  CHECK(a->placement.rpyDeg[2] == 90.0);
  CHECK(r.scene->until == 30.0);
}

TEST_CASE("root params overridden from outside reach every $name, an unknown one is refused") {
  testing::SceneDir dir;
  const auto file = dir.write("scene.yaml", R"(schema_version: 1
params: {t: 2.5, unused: 1}
components:
  proc: {type: processor, params: {processing_time: $t}}
)");
  // (name, value, line) => an override as a sweep file gives it
  scene::ParamOverrides o;
  const auto give = [&o](const std::string& name, const std::string& value, int line) {
    scene::ParamOverride& v = o[name];
    v.value = YAML::Node(value);
    v.where.file = "sweep.yaml";
    v.where.line = line;
    v.where.column = 9;
    v.keyPath = "sweep.vary." + name;
  };
  give("t", "0.75", 4);
  const auto r = scene::loadScene(file, o);
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  CHECK(r.scene->root.child("proc")->params.number("processing_time") == 0.75);
  CHECK(scene::loadScene(file).scene->root.child("proc")->params.number("processing_time") == 2.5);
  give("tt", "1", 5);
  const auto bad = scene::loadScene(file, o);
  CHECK_FALSE(bad.scene);
  CHECK_THAT(bad.diagnostics.report(),
             Catch::Contains("sweep.yaml:5:9: error: sweep.vary.tt: no parameter 'tt'"));
}

TEST_CASE("unknown keys are errors with their position and a suggestion") {
  testing::SceneDir dir;
  const auto r = load(dir, R"(schema_version: 1
components:
  proc:
    type: processor
    params: {procesing_time: 1.0}
)");
  const auto d = only(r);
  CHECK(d.where.line == 5);
  CHECK(d.where.column == 14);
  CHECK(d.keyPath == "components.proc.params.procesing_time");
  CHECK(d.hint == "did you mean 'processing_time'?");
  CHECK_THAT(r.diagnostics.report(), Catch::Contains("scene.yaml:5:14: error:"));
}

TEST_CASE("a value of the wrong type names what was expected") {
  testing::SceneDir dir;
  const auto r = load(dir, R"(schema_version: 1
components:
  genr:
    type: generator
    params:
      period: fast
)");
  const auto d = only(r);
  CHECK(d.where.line == 6);
  CHECK(d.where.column == 15);
  CHECK(d.keyPath == "components.genr.params.period");
  CHECK_THAT(d.message, Catch::Contains("expected a number in s") && Catch::Contains("'fast'"));
}

TEST_CASE("missing required keys are reported where they belong") {
  testing::SceneDir dir;
  const auto r = load(dir, R"(components:
  genr:
    type: generator
    params: {}
)");
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 2);
  const auto& a = r.diagnostics.all()[0];
  CHECK(a.keyPath == "schema_version");
  CHECK(a.where.line == 1);
  const auto& b = r.diagnostics.all()[1];
  CHECK(b.keyPath == "components.genr.params");
  CHECK(b.where.line == 4);
  CHECK(b.where.column == 13);
  CHECK_THAT(b.message, Catch::Contains("missing required parameter 'period'"));
}

TEST_CASE("an unknown model type suggests the nearest registered one") {
  testing::SceneDir dir;
  const auto d = only(load(dir, R"(schema_version: 1
components:
  p: {type: procesor}
)"));
  CHECK(d.where.line == 3);
  CHECK(d.where.column == 13);
  CHECK(d.keyPath == "components.p.type");
  CHECK(d.hint == "did you mean 'processor'?");
}

TEST_CASE("dangling couplings name the missing component or port") {
  testing::SceneDir dir;
  const auto r = load(dir, R"(schema_version: 1
components:
  proc: {type: processor, params: {processing_time: 1}}
  genr: {type: generator, params: {period: 1}}
couplings:
  - {from: genr.out, to: prc.in}
  - {from: genr.output, to: proc.in}
)");
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 2);
  const auto& a = r.diagnostics.all()[0];
  CHECK(a.where.line == 6);
  CHECK(a.where.column == 26);
  CHECK(a.keyPath == "couplings[0].to");
  CHECK(a.hint == "did you mean 'proc'?");
  const auto& b = r.diagnostics.all()[1];
  CHECK(b.where.line == 7);
  CHECK(b.keyPath == "couplings[1].from");
  CHECK_THAT(b.message, Catch::Contains("no port 'output'"));
  CHECK(b.hint == "did you mean 'out'?");
}

TEST_CASE("a coupling between ports of different value types is refused") {
  testing::SceneDir dir;
  const auto d = only(load(dir, R"(schema_version: 1
components:
  genr: {type: generator, params: {period: 1}}
  transd: {type: transducer, params: {observe: 5}}
couplings:
  - {from: transd.stop, to: genr.stop}
  - {from: genr.out, to: genr.stop}
)"));
  CHECK(d.where.line == 7);
  CHECK(d.where.column == 5);
  CHECK(d.keyPath == "couplings[1]");
  CHECK_THAT(d.message, Catch::Contains("carries int") && Catch::Contains("takes bool"));
}

TEST_CASE("duplicate names are refused") {
  testing::SceneDir dir;
  const auto r = load(dir, R"(schema_version: 1
components:
  p: {type: processor, params: {processing_time: 1}}
  p: {type: processor, params: {processing_time: 2}}
)");
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() >= 1);
  const auto& d = r.diagnostics.all()[0];
  CHECK(d.where.line == 4);
  CHECK(d.where.column == 3);
  CHECK(d.keyPath == "components.p");
  CHECK_THAT(d.message, Catch::Contains("duplicate"));
}

TEST_CASE("include cycles are reported with the chain of files") {
  testing::SceneDir dir;
  dir.write("a.yaml", "schema_version: 1\ncomponents:\n  b: {include: b.yaml}\n");
  dir.write("b.yaml", "schema_version: 1\ncomponents:\n  a: {include: a.yaml}\n");
  const auto r = scene::loadScene(dir.path() / "a.yaml");
  const auto d = only(r);
  CHECK(d.where.file == (dir.path() / "b.yaml").string());
  CHECK(d.where.line == 3);
  CHECK(d.where.column == 16);
  CHECK(d.keyPath == "components.a.include");
  CHECK_THAT(d.message, Catch::Contains("include cycle: a.yaml -> b.yaml -> a.yaml"));
}

TEST_CASE("every error of a file is reported together") {
  testing::SceneDir dir;
  const auto r = load(dir, R"(schema_version: 1
components:
  a: {type: generator, params: {period: x}}
  b: {type: nothing}
  c: {type: processor, params: {processing_time: 1}, colour: red}
couplings:
  - {from: c.out, to: d.in}
)");
  INFO(r.diagnostics.report());
  CHECK_FALSE(r.scene);
  CHECK(r.diagnostics.errorCount() == 4);
  std::vector<int> lines;
  for (const auto& d : r.diagnostics.all()) lines.push_back(d.where.line);
  CHECK(lines == std::vector<int>{3, 4, 5, 7});
}

TEST_CASE("YAML syntax errors, unknown parameters and bad overrides have positions") {
  testing::SceneDir dir;
  const auto syntax = only(load(dir, "schema_version: 1\ncomponents: {a: [1, 2}\n"));
  CHECK(syntax.where.line == 2);
  CHECK_THAT(syntax.message, Catch::Contains("YAML syntax error"));

  const auto ref = only(load(dir, R"(schema_version: 1
params: {period: 1}
components:
  g: {type: generator, params: {period: $perod}}
)"));
  CHECK(ref.where.line == 4);
  CHECK(ref.where.column == 41);
  CHECK(ref.hint == "did you mean 'period'?");

  dir.write("frame.yaml", "schema_version: 1\nparams: {observe: 1}\n");
  const auto over = only(load(dir, R"(schema_version: 1
components:
  f: {include: frame.yaml, params: {obsrve: 2}}
)"));
  CHECK(over.where.line == 3);
  CHECK(over.keyPath == "components.f.params.obsrve");
  CHECK(over.hint == "did you mean 'observe'?");
}

TEST_CASE("a type's own checks refuse out-of-range values at their place") {
  testing::SceneDir dir;
  const auto d = only(load(dir, R"(schema_version: 1
components:
  s: {type: spring_mass, params: {mass: -5, stiffness: 1, dt: 0.1}}
)"));
  CHECK(d.where.line == 3);
  CHECK(d.keyPath == "components.s.params.mass");
  CHECK_THAT(d.message, Catch::Contains("must be > 0 kg"));
}

TEST_CASE("the report block: plots and static levels, and its mistakes") {
  testing::SceneDir dir;
  const auto ok = load(dir, R"(schema_version: 1
components:
  genr: {type: generator, params: {period: 1.0}}
report:
  plots: ['crane.*.tension', 'block.roll']
  static: {crane.hoist.tension: 4.5e6, crane.aux.tension: 1000}
)");
  INFO(ok.diagnostics.report());
  REQUIRE(ok.scene);
  CHECK(ok.scene->report.plots == std::vector<std::string>{"crane.*.tension", "block.roll"});
  REQUIRE(ok.scene->report.staticLevels.size() == 2);
  CHECK(ok.scene->report.staticLevels[0] == std::pair<std::string, double>{"crane.hoist.tension", 4.5e6});
  const auto bad = load(dir, R"(schema_version: 1
components:
  genr: {type: generator, params: {period: 1.0}}
report:
  plot: ['x']
  static: {crane.hoist.tension: heavy}
)");
  REQUIRE(bad.diagnostics.errorCount() == 2);
  const auto& d = bad.diagnostics.all();
  CHECK(d[0].keyPath == "report.plot");
  CHECK(d[0].hint == "did you mean 'plots'?");
  CHECK(d[1].keyPath == "report.static.crane.hoist.tension");
  CHECK(d[1].where.line == 6);
  CHECK_THAT(d[1].message, Catch::Contains("expected a number") && Catch::Contains("'heavy'"));
}

TEST_CASE("NaN and infinities are refused at the door wherever a number is read, with the place") {
  // (the default example, one number replaced at a time) => exit 1 with file:line:col and key
  std::ifstream in(std::string(YARDSIM_SOURCE_DIR) + "/examples/double_pendulum/scene.yaml");
  const std::string base((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::vector<std::pair<std::string, std::string>> edits{
      {"dt: 0.002", "dt: .nan"},                    // a type parameter
      {"target_deg: 45", "target_deg: .inf"},       // an actor parameter
      {"start_at: 0}", "start_at: -.inf}"},         // another
      {"speed_deg: 6.0", "speed_deg: .nan"},        // a scene parameter, used through $speed_deg
      {"until: 30", "until: .nan"},                 // the run settings
      {"interval: 0.05", "interval: .inf"}};
  testing::SceneDir dir;
  for (const auto& [from, to] : edits) {
    std::string text = base;
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
    const auto r = scene::loadScene(dir.write("s.yaml", text));
    INFO(to << "\n" << r.diagnostics.report());
    CHECK_FALSE(r.scene);
    CHECK(r.diagnostics.report().find("s.yaml:") != std::string::npos);
  }
}

TEST_CASE("an include whose name the file system cannot take is a located error") {
  // (fuzzer finding, scene_loader_fuzz) std::filesystem::weakly_canonical threw on a name longer
  // than the file system allows
  testing::SceneDir dir;
  const auto r = scene::loadScene(dir.write(
      "s.yaml",
      "schema_version: 1\ncomponents:\n  a: {include: " + std::string(300, 'x') + "/part.yaml}\n"));
  INFO(r.diagnostics.report());
  REQUIRE_FALSE(r.scene);
  REQUIRE(r.diagnostics.errorCount() == 1);
  CHECK(r.diagnostics.all().front().keyPath == "components.a.include");
  CHECK(r.diagnostics.all().front().where.line == 3);
  CHECK_THAT(r.diagnostics.all().front().message, Catch::Contains("cannot read"));
}
