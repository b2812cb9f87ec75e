#include "devs/chrome_trace_sink.hpp"

#include <bit>
#include <cstring>

namespace yardsim::devs {
namespace {
constexpr double kMicro = 1e6;  // seconds => microseconds

// (text of a known length) => copied to p; the end after it
char* put(char* p, std::string_view text) {
  std::memcpy(p, text.data(), text.size());
  return p + text.size();
}
}  // namespace

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

// (phase, name, model) => head_, the text of an event object up to its time: made again only when
// the phase, name or model differ from the last event's
void ChromeTraceSink::setHead(std::string_view phase, std::string_view name, const AtomicBase& m) {
  if (&m == headModel_ && phase == headPhase_ && name == headName_) return;
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
  headStep_ = phase == "X" && name == "step";
}

// (phase, name, t, model) => the common head of one event object in ev_
void ChromeTraceSink::begin(std::string_view phase, std::string_view name, Time t,
                            const AtomicBase& m) {
  setHead(phase, name, m);
  ev_.assign(first_ ? "" : ",\n");
  first_ = false;
  ev_ += head_;
  appendJsonNumber(ev_, t * kMicro);
}

// (a DTSS step of model m from start, e long) => its X event written straight into the stream's
// chunk: room for the longest first, then the pieces
void ChromeTraceSink::step(Time start, Time e, const AtomicBase& m) {
  // (the last head a step of m's) => kept without comparing its phase and name again
  if (!headStep_ || &m != headModel_) setHead("X", "step", m);
  constexpr std::string_view kCat = ",\"cat\":\"dtss\",\"dur\":";
  char* p = stream_.room(2 + head_.size() + 2 * kJsonNumberSize + kCat.size() + 1);
  if (!first_) p = put(p, ",\n");
  first_ = false;
  p = put(p, head_);
  p = writeJsonMicroseconds(p, start);  // start * kMicro
  p = put(p, kCat);
  p = writeDuration(p, e);
  *p++ = '}';
  stream_.wrote(p);
}

// (a step's duration e, room for kJsonNumberSize chars at p) => e in microseconds written at p
// (writeJsonNumber), from the last few durations' texts when e is one of them; the end after it
char* ChromeTraceSink::writeDuration(char* p, Time e) {
  const auto bits = std::bit_cast<std::uint64_t>(e);
  for (const DurationText& d : durations_)
    if (d.length != 0 && d.bits == bits) {
      std::memcpy(p, d.text, kJsonNumberSize);
      return p + d.length;
    }
  char* end = writeJsonNumber(p, e * kMicro);
  DurationText& d = durations_[nextDuration_];
  nextDuration_ = (nextDuration_ + 1) % durations_.size();
  d.bits = bits;
  d.length = static_cast<unsigned char>(end - p);
  std::memcpy(d.text, p, d.length);
  return end;
}

void ChromeTraceSink::finish() {
  ev_ += '}';
  stream_.put(ev_);
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
    step(t - e, e, m);
    return;
  }
  begin("i", transitionName(kind), t, m);
  ev_ += ",\"s\":\"t\",\"cat\":\"transition\"";
  finish();
}

void ChromeTraceSink::onEnd(Time /*t*/) {
  stream_.flushAtRunEnd();
}

}  // namespace yardsim::devs
