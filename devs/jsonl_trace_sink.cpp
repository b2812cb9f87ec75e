#include "devs/jsonl_trace_sink.hpp"

#include <charconv>
#include <cstring>

namespace yardsim::devs {

void JsonlTraceSink::write(const TraceRecord& r) {
  line_.assign("{\"t\":");
  appendJsonNumber(line_, r.t);
  // (seq) => ,"seq":N,"model": put together in a local buffer, appended at once
  char buf[64];
  char* p = buf;
  std::memcpy(p, ",\"seq\":", 7);
  p = std::to_chars(p + 7, buf + 40, r.seq).ptr;  // 20 digits at most
  std::memcpy(p, ",\"model\":", 9);
  line_.append(buf, p + 9);
  // (model path) => its JSON string, escaped once per run of records from one model
  if (r.model != modelPath_) {
    modelPath_.assign(r.model);
    modelJson_.clear();
    appendJsonString(modelJson_, r.model);
  }
  line_ += modelJson_;
  // (kind: out, in, int, ext, conf or state) => quoted as it is, none needs an escape
  if (r.kind.size() <= 16) {
    std::memcpy(buf, ",\"kind\":\"", 9);
    std::memcpy(buf + 9, r.kind.data(), r.kind.size());
    buf[9 + r.kind.size()] = '"';
    line_.append(buf, 10 + r.kind.size());
  } else {
    line_ += ",\"kind\":\"";
    line_ += r.kind;
    line_ += '"';
  }
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
