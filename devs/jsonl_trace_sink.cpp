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

void JsonlTraceSink::setSequence(std::uint64_t seq) {
  if (seqLength_ != 0 && seq == lastSeq_ + 1 && seq != 0) {
    // (the last number's digits) => one added to them: trailing nines to zeros, the carry into the
    // digit before them or, when all were nines, a new leading one
    char* d = seqText_ + seqLength_;
    while (d != seqText_ && d[-1] == '9') *--d = '0';
    if (d != seqText_) {
      ++d[-1];
    } else {
      std::memmove(seqText_ + 1, seqText_, seqLength_++);
      seqText_[0] = '1';
    }
  } else {
    seqLength_ =
        static_cast<std::size_t>(std::to_chars(seqText_, seqText_ + 20, seq).ptr - seqText_);
  }
  lastSeq_ = seq;
}

void JsonlTraceSink::write(const TraceRecord& r) {
  // (model path) => ,"model":<its JSON string>,"kind":" made once per run of records from one model
  if (r.model != modelPath_) {
    modelPath_.assign(r.model);
    modelJson_.assign(",\"model\":");
    appendJsonString(modelJson_, r.model);
    modelJson_ += ",\"kind\":\"";
  }
  // (port) => its JSON string (escaped: its length is known only then)
  portJson_.clear();
  if (!r.port.empty()) appendJsonString(portJson_, r.port);
  setSequence(r.seq);
  // (record) => its line written straight into the stream's chunk: room for the longest line
  // first: the fixed pieces {"t": ,"seq": " ,"port": ,"value": }\n (32 chars; 36 allowed), the
  // number's kJsonNumberSize and the sequence number's whole buffer (both copied whole), then the
  // pieces
  const std::size_t most = 36 + kJsonNumberSize + sizeof seqText_ + modelJson_.size() +
                           r.kind.size() + portJson_.size() + r.value.size();
  char* const start = stream().room(most);
  char* p = put(start, "{\"t\":");
  p = writeJsonNumber(p, r.t);
  p = put(p, ",\"seq\":");
  std::memcpy(p, seqText_, sizeof seqText_);  // a fixed-size copy; the digits' end kept
  p += seqLength_;
  p = put(p, modelJson_);
  // (kind: out, in, int, ext, conf or state) => quoted as it is, none needs an escape
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
