#pragma once
// JSON Lines trace: one object per line,
//   {"t":1.5,"seq":7,"model":"gpt.ef.genr","kind":"out","port":"out","value":3}
// "port" and "value" appear only on records that have them.
#include <cstdint>

#include "devs/trace_record.hpp"

namespace yardsim::devs {

class JsonlTraceSink final : public RecordSink {
 public:
  explicit JsonlTraceSink(TraceStream stream, bool states = true)
      : RecordSink(std::move(stream), states) {}

 protected:
  void write(const TraceRecord& r) override;

 private:
  // (seq) => its digits in seqText_: the last record's text counted up by one in place when seq
  // follows it, written anew otherwise (a restored run's first record)
  void setSequence(std::uint64_t seq);

  // the last model's path, and ,"model":<its JSON string>,"kind":" (the text between a record's
  // sequence number and its kind)
  std::string modelPath_, modelJson_;
  std::string portJson_;       // scratch: a record's port as a JSON string
  char seqText_[24] = {};      // the last record's sequence number in decimal digits
  std::size_t seqLength_ = 0;  // 0: none yet
  std::uint64_t lastSeq_ = 0;  // the last record's sequence number
};

}  // namespace yardsim::devs
