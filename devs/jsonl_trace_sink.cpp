#include "devs/jsonl_trace_sink.hpp"

namespace yardsim::devs {

void JsonlTraceSink::write(const TraceRecord& r) {
  line_.assign("{\"t\":");
  appendJsonNumber(line_, r.t);
  line_ += ",\"seq\":";
  appendJsonInteger(line_, r.seq);
  line_ += ",\"model\":";
  // (model path) => its JSON string, escaped once per run of records from one model
  if (r.model != modelPath_) {
    modelPath_.assign(r.model);
    modelJson_.clear();
    appendJsonString(modelJson_, r.model);
  }
  line_ += modelJson_;
  // (kind: out, in, int, ext, conf or state) => quoted as it is, none needs an escape
  line_ += ",\"kind\":\"";
  line_ += r.kind;
  line_ += '"';
  if (!r.port.empty()) {
    line_ += ",\"port\":";
    appendJsonString(line_, r.port);
  }
  if (!r.value.empty()) {
    line_ += ",\"value\":";
    line_ += r.value;
  }
  line_ += "}\n";
  emit(line_);
}

}  // namespace yardsim::devs
