// TraceStream (devs/trace_record.hpp): a borrowed stream is flushed at every run call's end; a
// file of its own, flushed at most every 0.2 s there, still holds every record once its sink is
// gone, whatever the run calls.
#include "devs/trace_record.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <streambuf>
#include <string>

#include "devs/chrome_trace_sink.hpp"
#include "devs/jsonl_trace_sink.hpp"
#include "devs/simulator.hpp"
#include "support/gpt_builders.hpp"

using namespace yardsim;

namespace {
// A stream buffer that keeps what it is given and counts its flushes (sync)
struct CountingBuffer : std::stringbuf {
  int syncs = 0;
  int sync() override {
    ++syncs;
    return std::stringbuf::sync();
  }
};

// (file) => its bytes
std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

TEST_CASE("a borrowed trace stream is flushed at the end of every run call") {
  auto gpt = testing::makeGpt({1.0, 1.5, 10.0});
  devs::Simulator sim(*gpt);
  CountingBuffer buffer;
  std::ostream os(&buffer);
  devs::JsonlTraceSink sink{devs::TraceStream(os)};
  sim.addListener(sink);
  for (int k = 1; k <= 25; ++k) sim.runUntil(0.5 * k);
  CHECK(buffer.syncs == 25);
  CHECK_FALSE(buffer.str().empty());
}

TEST_CASE("a trace file holds every record once its sink is gone, after many run calls") {
  // the same records through a file of the sink's own and through a string, the run cut into
  // many short run calls (each ends with a flush request the file may defer)
  const auto dir = std::filesystem::temp_directory_path() / "yardsim_trace_record_test";
  std::filesystem::create_directories(dir);
  auto gpt = testing::makeGpt({1.0, 1.5, 10.0});
  devs::Simulator sim(*gpt);
  std::ostringstream jsonl, chrome;
  {
    devs::JsonlTraceSink fileSink{devs::TraceStream(dir / "trace.jsonl")};
    devs::ChromeTraceSink chromeFile{devs::TraceStream(dir / "trace.json")};
    devs::JsonlTraceSink textSink{devs::TraceStream(jsonl)};
    devs::ChromeTraceSink chromeText{devs::TraceStream(chrome)};
    for (devs::Listener* l :
         std::initializer_list<devs::Listener*>{&fileSink, &chromeFile, &textSink, &chromeText})
      sim.addListener(*l);
    for (int k = 1; k <= 40; ++k) sim.runUntil(0.25 * k);
  }
  CHECK(jsonl.str().size() > 1000);
  CHECK(contents(dir / "trace.jsonl") == jsonl.str());
  CHECK(contents(dir / "trace.json") == chrome.str());
  std::filesystem::remove_all(dir);
}

TEST_CASE("a borrowed trace stream holds each record as soon as its hook returns") {
  // (hooks called one by one, no run call's end) => the stream has every line so far
  std::ostringstream text;
  devs::JsonlTraceSink sink{devs::TraceStream(text)};
  auto gpt = testing::makeGpt({1.0, 1.5, 10.0});
  devs::Simulator sim(*gpt);  // flattened: the atomics have their places
  REQUIRE(!sim.atomics().empty());
  const devs::AtomicBase* genr = sim.atomics().front();
  devs::Listener& l = sink;
  for (int k = 1; k <= 5; ++k) {
    l.onTransition(k, *genr, devs::Transition::Internal, 1.0);
    const std::string now = text.str();
    CHECK(std::count(now.begin(), now.end(), '\n') == 2 * k - 1);
    CHECK(now.ends_with("\"kind\":\"int\"}\n"));
    l.onState(k, *genr);
    const std::string after = text.str();
    CHECK(std::count(after.begin(), after.end(), '\n') == 2 * k);
    CHECK(after.find("\"kind\":\"state\",\"value\":\"", after.rfind("{\"t\":")) !=
          std::string::npos);
  }
}

TEST_CASE("a trace file's chunks keep every byte in order, across chunks and beyond one") {
  // pieces of 1 byte to more than a whole chunk, and text written to the stream itself (a
  // header) between them, through a file of its own: the file is their concatenation
  const auto dir = std::filesystem::temp_directory_path() / "yardsim_trace_chunk_test";
  std::filesystem::create_directories(dir);
  std::string expected;
  {
    devs::TraceStream stream(dir / "chunks.txt");
    stream.out() << "head\n";
    expected += "head\n";
    std::size_t size = 1;
    for (int k = 0; k < 60; ++k) {
      std::string piece(size, static_cast<char>('a' + k % 26));
      piece.back() = '\n';
      if (k % 2) {
        stream.put(piece);
      } else {
        char* p = stream.room(piece.size() + 100);  // more room asked than used
        std::memcpy(p, piece.data(), piece.size());
        stream.wrote(p + piece.size());
      }
      expected += piece;
      if (k == 30) {
        stream.out() << "middle\n";
        expected += "middle\n";
      }
      size = size * 3 / 2 + 1;
      if (size > 3 * devs::TraceStream::kChunkBytes / 2) size = 7;
    }
    stream.flushAtRunEnd();
  }
  CHECK(expected.size() > 3 * devs::TraceStream::kChunkBytes);
  CHECK(contents(dir / "chunks.txt") == expected);
  std::filesystem::remove_all(dir);
}
