#include "devs/chrome_trace_sink.hpp"

namespace yardsim::devs {
namespace {
constexpr double kMicro = 1e6;  // seconds => microseconds
}

ChromeTraceSink::ChromeTraceSink(TraceStream stream) : stream_(std::move(stream)) {
  stream_.out() << "{\"displayTimeUnit\":\"ms\",\"traceEvents\":[\n";
}

ChromeTraceSink::~ChromeTraceSink() { close(); }

void ChromeTraceSink::close() {
  if (closed_) return;
  closed_ = true;
  stream_.out() << "\n]}\n";
  stream_.out().flush();
}

// (phase, name, t, model) => the common head of one event object in ev_; the text before the
// time made again only when the phase, name or model differ from the last event's
void ChromeTraceSink::begin(std::string_view phase, std::string_view name, Time t,
                            const AtomicBase& m) {
  if (&m != headModel_ || phase != headPhase_ || name != headName_) {
    headModel_ = &m;
    headPhase_.assign(phase);
    headName_.assign(name);
    head_.assign("{\"ph\":\"");
    head_ += phase;  // X, i or M: no escapes
    head_ += "\",\"name\":";
    appendJsonString(head_, name);
    head_ += ",\"pid\":1,\"tid\":";
    appendJsonInteger(head_, static_cast<std::uint64_t>(m.simIndex()) + 1);
    head_ += ",\"ts\":";
  }
  ev_.assign(first_ ? "" : ",\n");
  first_ = false;
  ev_ += head_;
  appendJsonNumber(ev_, t * kMicro);
}

void ChromeTraceSink::finish() {
  ev_ += '}';
  stream_.out().rdbuf()->sputn(ev_.data(), static_cast<std::streamsize>(ev_.size()));
}

void ChromeTraceSink::onStart(Time /*t*/, std::span<AtomicBase* const> atomics) {
  if (closed_) return;
  for (const AtomicBase* a : atomics) {
    begin("M", "thread_name", 0.0, *a);
    ev_ += ",\"args\":{\"name\":";
    appendJsonString(ev_, a->path());
    ev_ += '}';
    finish();
  }
}

void ChromeTraceSink::onOutput(Time t, const AtomicBase& m, const PortBase& port) {
  if (closed_) return;
  for (std::size_t i = 0; i < port.size(); ++i) {
    begin("i", port.name(), t, m);
    ev_ += ",\"s\":\"t\",\"cat\":\"out\",\"args\":{\"value\":";
    port.writeValue(ev_, i);
    ev_ += '}';
    finish();
  }
}

void ChromeTraceSink::onTransition(Time t, const AtomicBase& m, Transition kind, Time e) {
  if (closed_) return;
  if (m.kind() == "dtss" && kind != Transition::External && e > 0.0) {
    begin("X", "step", t - e, m);
    ev_ += ",\"cat\":\"dtss\",\"dur\":";
    appendJsonNumber(ev_, e * kMicro);
  } else {
    begin("i", transitionName(kind), t, m);
    ev_ += ",\"s\":\"t\",\"cat\":\"transition\"";
  }
  finish();
}

void ChromeTraceSink::onEnd(Time /*t*/) {
  stream_.flushAtRunEnd();
}

}  // namespace yardsim::devs
