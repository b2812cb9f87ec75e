#pragma once
// Chrome Trace Event JSON (opens in Perfetto or chrome://tracing): one track (tid) per atomic
// named by its path; steps of discrete-time (DTSS) atomics as complete spans from the previous
// transition to this one; other transitions and every output message as instants.
// Timestamps are microseconds of simulation time. The file is a JSON object
// {"traceEvents":[...],"displayTimeUnit":"ms"} closed by close() or the destructor.
#include <array>
#include <cstdint>

#include "devs/json_number.hpp"
#include "devs/trace_record.hpp"

namespace yardsim::devs {

class ChromeTraceSink final : public Listener {
 public:
  explicit ChromeTraceSink(TraceStream stream);
  ~ChromeTraceSink() override;

  void onStart(Time t, std::span<AtomicBase* const> atomics) override;
  void onOutput(Time t, const AtomicBase& m, const PortBase& port) override;
  void onTransition(Time t, const AtomicBase& m, Transition kind, Time e) override;
  void onEnd(Time t) override;
  // () => the closing brackets written; later hooks are ignored
  void close();

 private:
  void setHead(std::string_view phase, std::string_view name, const AtomicBase& m);
  void begin(std::string_view phase, std::string_view name, Time t, const AtomicBase& m);
  void finish();
  void step(Time start, Time e, const AtomicBase& m);
  char* writeDuration(char* p, Time e);

  // A step duration's bits and its text in microseconds (a fixed step's few roundings of dt)
  struct DurationText {
    std::uint64_t bits = 0;
    unsigned char length = 0;  // 0: empty
    char text[kJsonNumberSize] = {};
  };

  TraceStream stream_;
  std::string ev_;
  // the last event head's phase, name and model, and its text up to "ts": (a DTSS model's steps
  // repeat one head)
  std::string headPhase_, headName_;
  const AtomicBase* headModel_ = nullptr;
  std::string head_;
  bool headStep_ = false;  // head_ is a DTSS step's ("X", "step") of headModel_
  std::array<DurationText, 4> durations_;
  std::size_t nextDuration_ = 0;  // the entry replaced next
  bool first_ = true;
  bool closed_ = false;
};

}  // namespace yardsim::devs
