#include "output/report_writer.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "scene/assembler.hpp"
#include "output/report_bundle.hpp"
#include "run/runner.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
namespace fs = std::filesystem;

namespace {
std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
// (base64) => bytes (a decoder of its own, so the writer's encoder is checked against it)
std::string unbase64(const std::string& s) {
  std::string out;
  int bits = 0, acc = 0;
  for (char c : s) {
    int v = c >= 'A' && c <= 'Z' ? c - 'A' : c >= 'a' && c <= 'z' ? c - 'a' + 26
          : c >= '0' && c <= '9' ? c - '0' + 52 : c == '+' ? 62 : c == '/' ? 63 : -1;
    if (v < 0) continue;
    acc = (acc << 6) | v;
    if ((bits += 6) >= 8) out += static_cast<char>((acc >> (bits -= 8)) & 0xff);
  }
  return out;
}
}  // namespace

TEST_CASE("the peak of every tension channel and its ratio to the static value") {
  output::Timeseries ts;
  ts.columns = {{"time", "s", {}}, {"c.hoist.tension", "N", {}}, {"c.hoist.length", "m", {}},
                {"c.aux.tension", "N", {}}};
  for (int k = 0; k <= 1000; ++k) {
    const double t = 0.01 * k;
    ts.columns[0].values.push_back(t);
    ts.columns[1].values.push_back(1e5 * (1.0 + 0.3 * std::sin(t)));
    ts.columns[2].values.push_back(1e9);
    ts.columns[3].values.push_back(k == 500 ? NAN : 10.0 - t);
  }
  const auto peaks = output::ropePeaks(ts, {{"c.hoist.tension", 1e5}});
  REQUIRE(peaks.size() == 2);
  CHECK(peaks[0].channel == "c.hoist.tension");
  CHECK(peaks[0].peak == Approx(1.3e5).epsilon(1e-6));
  CHECK(peaks[0].time == Approx(M_PI / 2).margin(0.01));
  CHECK(peaks[0].ratio() == Approx(1.3).epsilon(1e-6));
  CHECK(peaks[1].channel == "c.aux.tension");
  CHECK(peaks[1].peak == 10.0);
  CHECK_FALSE(peaks[1].staticValue);
}

TEST_CASE("a rope's running maximum over every step gives the peak between samples") {
  output::Timeseries ts;
  ts.columns = {{"time", "s", {0, 1, 2, 3}}, {"c.hoist.tension", "N", {10, 12, 11, 10}},
                {"c.hoist.peak_tension", "N", {10, 12, 13.5, 13.5}}};
  const auto peaks = output::ropePeaks(ts, {});
  REQUIRE(peaks.size() == 1);
  CHECK(peaks[0].peak == 13.5);
  CHECK(peaks[0].time == 2.0);  // the first sample after the step that reached it
}

TEST_CASE("actor spans come from the started and finished outputs of the trace") {
  testing::SceneDir dir;
  const auto trace = dir.write("trace.jsonl", R"({"t":0,"seq":1,"model":"a","kind":"state","value":"waiting"}
{"t":1,"seq":4,"model":"a","kind":"out","port":"started","value":"a"}
{"t":1,"seq":5,"model":"b","kind":"in","port":"trigger","value":"a"}
{"t":2,"seq":6,"model":"b","kind":"out","port":"started","value":"b"}
{"t":3,"seq":7,"model":"a","kind":"out","port":"finished","value":"a"}
{"t":4,"seq":8,"model":"d","kind":"out","port":"started","value":"d"}
)");
  const auto spans = output::actorSpans(trace, {{"a", "joint_actor", -1, -1}, {"b", "wire_actor", -1, -1},
                                                {"c", "body_actor", -1, -1}});
  REQUIRE(spans.size() == 4);
  CHECK((spans[0].start == 1.0 && spans[0].end == 3.0));
  CHECK((spans[1].start == 2.0 && spans[1].end == -1.0));  // never finished
  CHECK((spans[2].start == -1.0 && spans[2].kind == "body_actor"));  // never started
  CHECK((spans[3].path == "d" && spans[3].kind == "actor" && spans[3].start == 4.0));
}

TEST_CASE("report.html of a run: self-contained, with the bundle, the data and replay.glb's bytes") {
  // a 1000 kg block hanging on a rope from the world; the static tension is m g
  testing::SceneDir dir;
  const auto file = dir.write("s.yaml", R"(schema_version: 1
name: hang </script> test
components:
  m:
    type: multibody
    params:
      dt: 0.002
      bodies:
        block:
          parent: world
          joint: {type: prismatic, axis: [0, 0, 1], q0: -0.1}
          mass: 1000
          inertia: [100, 100, 100]
          geometry: {box: [1, 1, 1]}
      ropes:
        hoist:
          path: [{body: world, point: [0, 0, 10]}, {body: block, point: [0, 0, 0.5]}]
          EA: 1.0e8
          L0: 9.5
          damping: 1.0e5
record: {interval: 0.05, channels: ['*']}
report: {plots: ['m.hoist.*', 'm.nothing*'], static: {m.hoist.tension: 9810}}
until: 2
)");
  auto scene = scene::loadSceneOrThrow(file);
  auto root = scene::assemble(*scene);
  const fs::path out = dir.path() / "out";
  run::runScene(*scene, *root, {out, 2.0, {}, {}, 0.1, 2000});
  output::writeReport(out);
  const std::string html = slurp(out / "report.html");
  // (page) => one data element, the bundle inline, nothing fetched from elsewhere
  const std::string open = "<script type=\"application/json\" id=\"yardsim-data\">";
  const auto a = html.find(open);
  REQUIRE(a != std::string::npos);
  const auto b = html.find("</script>", a);
  const std::string json = html.substr(a + open.size(), b - a - open.size());
  CHECK(html.find(std::string(output::reportBundle()).substr(0, 200)) != std::string::npos);
  CHECK(html.find("<script src") == std::string::npos);
  CHECK(html.find("<link") == std::string::npos);
  CHECK(html.find("<title>yardsim report: hang &lt;/script> test</title>") != std::string::npos);
  const YAML::Node d = YAML::Load(json);
  CHECK(d["run"]["scene"].as<std::string>() == "hang </script> test");  // escaped, not closing
  CHECK(unbase64(d["glb"].as<std::string>()) == slurp(out / "replay.glb"));
  // (plots globs) => the hoist channels; the glob that matches nothing is a note
  std::vector<std::string> plotted;
  for (const auto& i : d["plots"]) plotted.push_back(d["series"][i.as<int>()]["name"].as<std::string>());
  CHECK(plotted == std::vector<std::string>{"m.hoist.tension", "m.hoist.length", "m.hoist.unstretched_length",
                                           "m.hoist.peak_tension"});
  CHECK_THAT(d["notes"][0].as<std::string>(), Catch::Contains("'m.nothing*' matches no recorded channel"));
  // (time series) => float32 base64 of the recorded values
  const std::string t = unbase64(d["time"].as<std::string>());
  REQUIRE(t.size() == 41 * 4);
  float last;
  std::memcpy(&last, t.data() + 40 * 4, 4);
  CHECK(last == 2.0f);
  // (peak) => the rope's, compared with m g: above it (the block starts stretched and bounces)
  REQUIRE(d["peaks"].size() == 1);
  CHECK(d["peaks"][0]["static"].as<double>() == 9810.0);
  CHECK(d["peaks"][0]["peak"].as<double>() > 9810.0);
  CHECK(d["run"]["systems"][0]["method"].as<std::string>() == "rk4");
}

TEST_CASE("a folder without a time series is refused with what to do") {
  testing::SceneDir dir;
  CHECK_THROWS_WITH(output::writeReport(dir.path()), Catch::Contains("timeseries.csv' not found"));
}
