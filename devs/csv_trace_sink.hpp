#pragma once
// Compact CSV trace: header "t,seq,model,kind,port,value", one row per record; value is the
// JSON text of the message or state, quoted CSV-style when it holds commas or quotes.
#include "devs/trace_record.hpp"

namespace yardsim::devs {

class CsvTraceSink final : public RecordSink {
 public:
  explicit CsvTraceSink(TraceStream stream, bool states = true);

 protected:
  void write(const TraceRecord& r) override;

 private:
  std::string line_;
};

// (field) => field appended to out, quoted with doubled quotes when it needs to be
void appendCsvField(std::string& out, std::string_view field);

}  // namespace yardsim::devs
