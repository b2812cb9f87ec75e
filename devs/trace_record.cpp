#include "devs/trace_record.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace yardsim::devs {

TraceStream::TraceStream(const std::filesystem::path& path)
    : file_(std::make_unique<BufferedFile>(path)), os_(&file_->stream()) {
  if (!*os_) throw std::runtime_error("cannot open trace file '" + path.string() + "'");
}

TraceStream::TraceStream(TraceStream&& o) noexcept
    : file_(std::move(o.file_)),
      os_(o.os_),
      chunk_(std::move(o.chunk_)),
      used_(std::exchange(o.used_, 0)),
      capacity_(std::exchange(o.capacity_, 0)),
      lastFlush_(o.lastFlush_) {}

TraceStream::~TraceStream() {
  drain();
}

void TraceStream::drain() {
  if (used_ == 0) return;
  os_->rdbuf()->sputn(chunk_.get(), static_cast<std::streamsize>(used_));
  used_ = 0;
}

void TraceStream::makeRoom(std::size_t n) {
  drain();
  if (n <= capacity_) return;
  // (a file) => its chunk at full size from the first record; (a borrowed stream) => the largest
  // record so far
  capacity_ = std::max(n, file_ ? kChunkBytes : std::size_t{256});
  chunk_ = std::make_unique_for_overwrite<char[]>(capacity_);
}

void TraceStream::put(std::string_view text) {
  char* p = room(text.size());
  std::memcpy(p, text.data(), text.size());
  wrote(p + text.size());
}

void TraceStream::flushAtRunEnd() {
  if (file_) {
    const auto now = std::chrono::steady_clock::now();
    if (now - lastFlush_ < std::chrono::milliseconds(200)) return;
    lastFlush_ = now;
  }
  drain();
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
