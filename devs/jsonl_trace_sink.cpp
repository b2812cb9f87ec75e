#include "devs/jsonl_trace_sink.hpp"

namespace yardsim::devs {

void JsonlTraceSink::write(const TraceRecord& r) {
  line_.assign("{\"t\":");
  appendJsonNumber(line_, r.t);
  line_ += ",\"seq\":";
  line_ += std::to_string(r.seq);
  line_ += ",\"model\":";
  appendJsonString(line_, r.model);
  line_ += ",\"kind\":";
  appendJsonString(line_, r.kind);
  if (!r.port.empty()) {
    line_ += ",\"port\":";
    appendJsonString(line_, r.port);
  }
  if (!r.value.empty()) {
    line_ += ",\"value\":";
    line_ += r.value;
  }
  line_ += "}\n";
  out() << line_;
}

}  // namespace yardsim::devs
