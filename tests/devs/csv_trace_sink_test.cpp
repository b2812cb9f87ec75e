#include "devs/csv_trace_sink.hpp"

#include <catch2/catch.hpp>
#include <sstream>

#include "devs/simulator.hpp"
#include "support/gpt_builders.hpp"
#include "support/record_collector.hpp"

using namespace yardsim;

namespace {
// (one CSV line) => its fields, with RFC 4180 quoting undone
std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}
}  // namespace

TEST_CASE("the CSV trace parses back to the records the simulator made") {
  auto gpt = testing::makeGpt({1.0, 1.5, 10.0});
  devs::Simulator sim(*gpt);
  std::ostringstream text;
  devs::CsvTraceSink sink{devs::TraceStream(text)};
  testing::RecordCollector reference;
  sim.addListener(sink);
  sim.addListener(reference);
  sim.run();

  std::istringstream lines(text.str());
  std::string line;
  REQUIRE(std::getline(lines, line));
  CHECK(line == "t,seq,model,kind,port,value");
  std::size_t n = 0;
  while (std::getline(lines, line)) {
    const auto f = splitCsv(line);
    REQUIRE(f.size() == 6);
    REQUIRE(n < reference.records.size());
    const auto& r = reference.records[n];
    CHECK(std::stod(f[0]) == r.t);
    CHECK(std::stoull(f[1]) == n);
    CHECK(f[2] == r.model);
    CHECK(f[3] == r.kind);
    CHECK(f[4] == r.port);
    CHECK(f[5] == r.value);
    ++n;
  }
  CHECK(n == reference.records.size());
}
