#include "devs/jsonl_trace_sink.hpp"

#include <charconv>
#include <cstring>

#include "devs/json_number.hpp"

namespace yardsim::devs {

namespace {
// (text of a known length) => copied to p; the end after it
char* put(char* p, std::string_view text) {
  std::memcpy(p, text.data(), text.size());
  return p + text.size();
}
}  // namespace

void JsonlTraceSink::write(const TraceRecord& r) {
  // (model path) => its JSON string, escaped once per run of records from one model
  if (r.model != modelPath_) {
    modelPath_.assign(r.model);
    modelJson_.clear();
    appendJsonString(modelJson_, r.model);
  }
  // (port) => its JSON string (escaped: its length is known only then)
  portJson_.clear();
  if (!r.port.empty()) appendJsonString(portJson_, r.port);
  // (record) => its line written straight into the stream's chunk: room for the longest line
  // first ({"t":,"seq":,"model":,"kind":"","port":,"value":}\n: 50 chars), then the pieces
  const std::size_t most = 50 + kJsonNumberSize + 20 + modelJson_.size() + r.kind.size() +
                           portJson_.size() + r.value.size();
  char* const start = stream().room(most);
  char* p = put(start, "{\"t\":");
  p = writeJsonNumber(p, r.t);
  p = put(p, ",\"seq\":");
  p = std::to_chars(p, p + 20, r.seq).ptr;  // 20 digits at most
  p = put(p, ",\"model\":");
  p = put(p, modelJson_);
  // (kind: out, in, int, ext, conf or state) => quoted as it is, none needs an escape
  p = put(p, ",\"kind\":\"");
  p = put(p, r.kind);
  *p++ = '"';
  if (!r.port.empty()) {
    p = put(p, ",\"port\":");
    p = put(p, portJson_);
  }
  if (!r.value.empty()) {
    p = put(p, ",\"value\":");
    p = put(p, r.value);
  }
  p = put(p, "}\n");
  stream().wrote(p);
}

}  // namespace yardsim::devs
