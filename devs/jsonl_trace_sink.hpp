#pragma once
// JSON Lines trace: one object per line,
//   {"t":1.5,"seq":7,"model":"gpt.ef.genr","kind":"out","port":"out","value":3}
// "port" and "value" appear only on records that have them.
#include "devs/trace_record.hpp"

namespace yardsim::devs {

class JsonlTraceSink final : public RecordSink {
 public:
  explicit JsonlTraceSink(TraceStream stream, bool states = true)
      : RecordSink(std::move(stream), states) {}

 protected:
  void write(const TraceRecord& r) override;

 private:
  std::string line_;
  // the last record's model path and kind, and its text from ",\"model\":" to the kind's closing quote
  std::string modelPath_, kind_, middle_;
};

}  // namespace yardsim::devs
