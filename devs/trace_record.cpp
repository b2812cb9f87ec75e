#include "devs/trace_record.hpp"

#include <stdexcept>

namespace yardsim::devs {

TraceStream::TraceStream(const std::filesystem::path& path)
    : file_(std::make_unique<BufferedFile>(path)), os_(&file_->stream()) {
  if (!*os_) throw std::runtime_error("cannot open trace file '" + path.string() + "'");
}

void TraceStream::flushAtRunEnd() {
  if (file_) {
    const auto now = std::chrono::steady_clock::now();
    if (now - lastFlush_ < std::chrono::milliseconds(200)) return;
    lastFlush_ = now;
  }
  os_->flush();
}

std::string_view transitionName(Transition kind) {
  switch (kind) {
    case Transition::Internal: return "int";
    case Transition::External: return "ext";
    case Transition::Confluent: return "conf";
  }
  return "?";
}

void RecordSink::messages(Time t, const AtomicBase& m, const PortBase& port,
                          std::string_view kind) {
  for (std::size_t i = 0; i < port.size(); ++i) {
    value_.clear();
    port.writeValue(value_, i);
    write({t, seq_++, m.path(), kind, port.name(), value_});
  }
}

void RecordSink::onOutput(Time t, const AtomicBase& m, const PortBase& port) {
  messages(t, m, port, "out");
}

void RecordSink::onInput(Time t, const AtomicBase& m, const PortBase& port) {
  messages(t, m, port, "in");
}

void RecordSink::onTransition(Time t, const AtomicBase& m, Transition kind, Time /*e*/) {
  write({t, seq_++, m.path(), transitionName(kind), {}, {}});
}

void RecordSink::onState(Time t, const AtomicBase& m) {
  if (!states_) return;
  value_.clear();
  m.writeState(value_);
  write({t, seq_++, m.path(), "state", {}, value_});
}

void RecordSink::onEnd(Time /*t*/) {
  stream_.flushAtRunEnd();
}

}  // namespace yardsim::devs
