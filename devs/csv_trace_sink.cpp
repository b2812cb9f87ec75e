#include "devs/csv_trace_sink.hpp"

namespace yardsim::devs {

void appendCsvField(std::string& out, std::string_view field) {
  if (field.find_first_of(",\"\n\r") == std::string_view::npos) {
    out += field;
    return;
  }
  out += '"';
  for (char c : field) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

CsvTraceSink::CsvTraceSink(TraceStream stream, bool states)
    : RecordSink(std::move(stream), states) {
  out() << "t,seq,model,kind,port,value\n";
}

void CsvTraceSink::write(const TraceRecord& r) {
  line_.clear();
  appendJsonNumber(line_, r.t);
  line_ += ',';
  appendJsonInteger(line_, r.seq);
  line_ += ',';
  appendCsvField(line_, r.model);
  line_ += ',';
  line_ += r.kind;
  line_ += ',';
  appendCsvField(line_, r.port);
  line_ += ',';
  appendCsvField(line_, r.value);
  line_ += '\n';
  emit(line_);
}

}  // namespace yardsim::devs
