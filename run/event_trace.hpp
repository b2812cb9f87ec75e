#pragma once
// The report's trace (docs/report.md, "A smaller trace"): the `events` sink writes
// OUTDIR/trace.jsonl with the output records only (every message a model sends: actors'
// `started`/`finished`, the multibody models' `event`s, user atomics' `alarm`s, ...), not the
// per-step `int`/`state`/`in` records of the full `jsonl` trace. `--report` adds it when no
// `jsonl` trace is asked for. Same line format as the full trace (devs/jsonl_trace_sink.hpp).
#include "devs/listener.hpp"

namespace yardsim::run {

// (a trace sink) => a listener that hands it the outputs and the end of each run call only
class OutputsOnly final : public devs::Listener {
 public:
  explicit OutputsOnly(devs::Listener& sink) : sink_(sink) {}
  void onStart(devs::Time t, std::span<devs::AtomicBase* const> atomics) override {
    sink_.onStart(t, atomics);
  }
  void onOutput(devs::Time t, const devs::AtomicBase& m, const devs::PortBase& port) override {
    sink_.onOutput(t, m, port);
  }
  void onEnd(devs::Time t) override { sink_.onEnd(t); }

 private:
  devs::Listener& sink_;
};

}  // namespace yardsim::run
