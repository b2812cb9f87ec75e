#include "devs/chrome_trace_sink.hpp"

#include <catch2/catch.hpp>
#include <map>
#include <sstream>
#include <yaml-cpp/yaml.h>

#include "devs/simulator.hpp"
#include "support/gpt_builders.hpp"
#include "support/record_collector.hpp"

using namespace yardsim;

TEST_CASE("the Chrome trace is one JSON document with a named track per atomic") {
  auto gpt = testing::makeGpt({1.0, 1.5, 10.0});
  devs::Simulator sim(*gpt);
  std::ostringstream text;
  testing::RecordCollector reference(false);
  {
    devs::ChromeTraceSink sink{devs::TraceStream(text)};
    sim.addListener(sink);
    sim.addListener(reference);
    sim.run();
  }  // the destructor closes the document
  const YAML::Node doc = YAML::Load(text.str());
  const YAML::Node events = doc["traceEvents"];
  REQUIRE(events.IsSequence());

  std::map<int, std::string> tracks;
  std::size_t outputs = 0, transitions = 0;
  for (const auto& ev : events) {
    const auto ph = ev["ph"].as<std::string>();
    const int tid = ev["tid"].as<int>();
    if (ph == "M") {
      CHECK(ev["name"].as<std::string>() == "thread_name");
      tracks[tid] = ev["args"]["name"].as<std::string>();
      continue;
    }
    REQUIRE(ph == "i");
    REQUIRE(tracks.count(tid) == 1);  // every event sits on a declared track
    const double t = ev["ts"].as<double>() * 1e-6;
    if (ev["cat"].as<std::string>() == "out") {
      // matches an "out" record of the same model and time
      const auto outs = reference.ofKind("out");
      CHECK(std::any_of(outs.begin(), outs.end(), [&](const testing::Record& r) {
        return r.model == tracks[tid] && r.t == Approx(t) && r.port == ev["name"].as<std::string>();
      }));
      ++outputs;
    } else {
      ++transitions;
    }
  }
  CHECK(tracks.size() == 3);
  CHECK(tracks[1] == "gpt.ef.genr");
  CHECK(outputs == reference.ofKind("out").size());
  CHECK(transitions == reference.ofKind("int").size() + reference.ofKind("ext").size() +
                           reference.ofKind("conf").size());
}
