#pragma once
// Record-per-line trace sinks (JSON Lines, CSV) share this base: it turns the Simulator's
// hooks into records (t, seq, model path, kind, port, value) and hands each to write().
// kind is one of out, in, int, ext, conf, state; port and value are set for out and in
// (one record per message), value alone for state (the state's JSON form).
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

#include "devs/buffered_file.hpp"
#include "devs/listener.hpp"

namespace yardsim::devs {

struct TraceRecord {
  Time t;
  std::uint64_t seq;
  std::string_view model;
  std::string_view kind;
  std::string_view port;   // empty when the record has no port
  std::string_view value;  // JSON text, empty when the record has no value
};

// An output stream that is either borrowed or a file this object opened (and flushes).
class TraceStream {
 public:
  explicit TraceStream(std::ostream& os) : os_(&os) {}
  // (path) => file opened for writing, with a large buffer (BufferedFile); throws
  // std::runtime_error naming the path otherwise
  explicit TraceStream(const std::filesystem::path& path);
  std::ostream& out() { return *os_; }
  // (a run call's end) => flushed: a borrowed stream every time, a file of its own when 0.2 s of
  // wall time or more have passed since its last flush (the runner ends a run call at every
  // recorded row; the file's destructor writes the rest, also when a run fails)
  void flushAtRunEnd();

 private:
  std::unique_ptr<BufferedFile> file_;
  std::ostream* os_;
  std::chrono::steady_clock::time_point lastFlush_ = std::chrono::steady_clock::now();
};

class RecordSink : public Listener {
 public:
  // (stream, whether to emit "state" records)
  RecordSink(TraceStream stream, bool states) : stream_(std::move(stream)), states_(states) {}

  void onOutput(Time t, const AtomicBase& m, const PortBase& port) override;
  void onInput(Time t, const AtomicBase& m, const PortBase& port) override;
  void onTransition(Time t, const AtomicBase& m, Transition kind, Time e) override;
  void onState(Time t, const AtomicBase& m) override;
  void onEnd(Time t) override;
  // () => the sequence number of the next record; (n) => a restored run's trace goes on at n
  std::uint64_t sequence() const { return seq_; }
  void continueAt(std::uint64_t n) { seq_ = n; }

 protected:
  virtual void write(const TraceRecord& r) = 0;
  std::ostream& out() { return stream_.out(); }
  // (text) => appended to the stream through its buffer (no sentry per record)
  void emit(const std::string& text) {
    stream_.out().rdbuf()->sputn(text.data(), static_cast<std::streamsize>(text.size()));
  }

 private:
  void messages(Time t, const AtomicBase& m, const PortBase& port, std::string_view kind);

  TraceStream stream_;
  bool states_;
  std::uint64_t seq_ = 0;
  std::string value_;  // scratch, reused
};

// (transition) => "int", "ext" or "conf"
std::string_view transitionName(Transition kind);

}  // namespace yardsim::devs
