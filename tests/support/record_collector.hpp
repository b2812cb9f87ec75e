#pragma once
// Test support: a trace sink that keeps every record in memory, built on the same
// RecordSink base as the JSON Lines and CSV sinks.
#include <sstream>
#include <string>
#include <vector>

#include "devs/trace_record.hpp"

namespace yardsim::testing {

struct Record {
  double t;
  std::uint64_t seq;
  std::string model, kind, port, value;
  bool operator==(const Record&) const = default;
};

class RecordCollector final : public devs::RecordSink {
 public:
  explicit RecordCollector(bool states = true) : RecordSink(devs::TraceStream(sink_), states) {}
  std::vector<Record> records;

  // (kind) => the records of that kind
  std::vector<Record> ofKind(const std::string& kind) const {
    std::vector<Record> out;
    for (const auto& r : records)
      if (r.kind == kind) out.push_back(r);
    return out;
  }

 protected:
  void write(const devs::TraceRecord& r) override {
    records.push_back({r.t, r.seq, std::string(r.model), std::string(r.kind), std::string(r.port),
                       std::string(r.value)});
  }

 private:
  std::ostringstream sink_;
};

}  // namespace yardsim::testing
