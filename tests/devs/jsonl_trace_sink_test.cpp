#include "devs/jsonl_trace_sink.hpp"

#include <catch2/catch.hpp>
#include <set>
#include <sstream>
#include <yaml-cpp/yaml.h>

#include "devs/simulator.hpp"
#include "support/gpt_builders.hpp"
#include "support/record_collector.hpp"

using namespace yardsim;

TEST_CASE("the JSON Lines trace parses back line by line to the records the simulator made") {
  auto gpt = testing::makeGpt({1.0, 1.5, 10.0});
  devs::Simulator sim(*gpt);
  std::ostringstream text;
  devs::JsonlTraceSink sink{devs::TraceStream(text)};
  testing::RecordCollector reference;
  sim.addListener(sink);
  sim.addListener(reference);
  sim.run();

  std::istringstream lines(text.str());
  std::string line;
  std::size_t n = 0;
  const std::set<std::string> kinds{"out", "in", "int", "ext", "conf", "state"};
  while (std::getline(lines, line)) {
    const YAML::Node j = YAML::Load(line);
    REQUIRE(n < reference.records.size());
    const auto& r = reference.records[n];
    CHECK(j["t"].as<double>() == r.t);
    CHECK(j["seq"].as<std::uint64_t>() == n);
    CHECK(j["model"].as<std::string>() == r.model);
    const auto kind = j["kind"].as<std::string>();
    CHECK(kinds.count(kind) == 1);
    CHECK(kind == r.kind);
    const bool message = kind == "out" || kind == "in";
    CHECK(bool(j["port"]) == message);
    CHECK(bool(j["value"]) == (message || kind == "state"));
    if (message) {
      CHECK(j["port"].as<std::string>() == r.port);
      CHECK(j["value"].as<std::string>() == YAML::Load(r.value).as<std::string>());
    }
    ++n;
  }
  CHECK(n == reference.records.size());
  CHECK(reference.ofKind("out").size() > 10);
  CHECK(reference.ofKind("conf").size() >= 1);  // genr at t = 10: own event and the stop
}
