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
  std::string modelPath_, modelJson_;  // the last model's path and its JSON string
  std::string portJson_;               // scratch: a record's port as a JSON string
};

}  // namespace yardsim::devs
