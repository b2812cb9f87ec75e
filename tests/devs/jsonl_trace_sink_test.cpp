#include "devs/jsonl_trace_sink.hpp"

#include <yaml-cpp/yaml.h>
#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>
#include <set>
#include <sstream>

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

TEST_CASE(
    "sequence numbers are every record's, in decimal, across carries and where a run goes on") {
  // (a trace that starts just below a power of ten, or 2^64, and is told to go on elsewhere
  // between run calls, as a restored run is) => each line's "seq" is the record's number's decimal
  // digits, one more than the line before's within a run call
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  for (const std::uint64_t start :
       {std::uint64_t{0}, std::uint64_t{7}, std::uint64_t{95}, std::uint64_t{99995},
        std::uint64_t{99999999999999990ULL}, kMax - 5}) {
    auto gpt = testing::makeGpt({1.0, 1.5, 10.0});
    devs::Simulator sim(*gpt);
    std::ostringstream text;
    devs::JsonlTraceSink sink{devs::TraceStream(text)};
    sim.addListener(sink);
    sink.continueAt(start);
    sim.runUntil(3.0);
    const std::uint64_t firstRun = sink.sequence() - start;   // records in the first run call
    const std::uint64_t jump = start == 0 ? 989 : start / 3;  // not the next number
    sink.continueAt(jump);
    sim.runUntil(6.0);
    const std::uint64_t secondRun = sink.sequence() - jump;
    REQUIRE(firstRun > 10);
    REQUIRE(secondRun > 10);
    std::istringstream lines(text.str());
    std::string line;
    std::uint64_t n = 0;
    while (std::getline(lines, line)) {
      // (line n) => the record's number: start + n in the first run call (mod 2^64), jump + the
      // rest in the second
      const std::uint64_t seq = n < firstRun ? start + n : jump + (n - firstRun);
      const std::string field = ",\"seq\":" + std::to_string(seq) + ",\"model\":";
      CHECK(line.find(field) != std::string::npos);
      ++n;
    }
    CHECK(n == firstRun + secondRun);
  }
}
