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

// An output stream that is either borrowed or a file this object opened (and flushes). Sinks
// write their records into its chunk (room(), then wrote()): a file's chunk goes to the file when
// full (kChunkBytes) and when the stream is flushed or gone, a borrowed stream's after every
// record.
class TraceStream {
 public:
  // Bytes a file's chunk holds before they go to the file (BufferedFile's size: one write each).
  static constexpr std::size_t kChunkBytes = BufferedFile::kBufferBytes;

  explicit TraceStream(std::ostream& os) : os_(&os) {}
  // (path) => file opened for writing, with a large buffer (BufferedFile); throws
  // std::runtime_error naming the path otherwise
  explicit TraceStream(const std::filesystem::path& path);
  TraceStream(TraceStream&& o) noexcept;
  TraceStream& operator=(TraceStream&&) = delete;
  // () => the chunk's bytes written to the stream (the file closes after)
  ~TraceStream();
  // () => the stream, every record written so far in it
  std::ostream& out() {
    drain();
    return *os_;
  }
  // (at most n bytes to write) => where to write them, in the chunk; wrote() says where they end
  char* room(std::size_t n) {
    if (n > capacity_ - used_) makeRoom(n);
    return chunk_.get() + used_;
  }
  // (the end of what was written from room()) => kept; a borrowed stream's written to it at once
  void wrote(const char* end) {
    used_ = static_cast<std::size_t>(end - chunk_.get());
    if (!file_) drain();
  }
  // (text) => written, as room() and wrote() would
  void put(std::string_view text);
  // (a run call's end) => flushed: a borrowed stream every time, a file of its own when 0.2 s of
  // wall time or more have passed since its last flush (the runner ends a run call at every
  // recorded row; the file's destructor writes the rest, also when a run fails)
  void flushAtRunEnd();

 private:
  // () => the chunk's bytes written to the stream, the chunk emptied
  void drain();
  // (n bytes to write) => the chunk emptied, and made larger when it holds fewer than n
  void makeRoom(std::size_t n);

  std::unique_ptr<BufferedFile> file_;
  std::ostream* os_;
  std::unique_ptr<char[]> chunk_;
  std::size_t used_ = 0, capacity_ = 0;
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
  TraceStream& stream() { return stream_; }
  // (text) => appended to the stream through its chunk
  void emit(const std::string& text) { stream_.put(text); }

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
