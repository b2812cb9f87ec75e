#include "devs/jsonl_trace_sink.hpp"

namespace yardsim::devs {

void JsonlTraceSink::write(const TraceRecord& r) {
  line_.assign("{\"t\":");
  appendJsonNumber(line_, r.t);
  line_ += ",\"seq\":";
  appendJsonInteger(line_, r.seq);
  // (model path, kind) => ,"model":<its JSON string>,"kind":"<kind>", made again only when either
  // differs from the last record's (the kinds out, in, int, ext, conf and state need no escape)
  if (r.model != modelPath_ || r.kind != kind_) {
    modelPath_.assign(r.model);
    kind_.assign(r.kind);
    middle_.assign(",\"model\":");
    appendJsonString(middle_, r.model);
    middle_ += ",\"kind\":\"";
    middle_ += r.kind;
    middle_ += '"';
  }
  line_ += middle_;
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
