#include "devs/trace_format.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "devs/shortest_text.hpp"

namespace yardsim::devs {

void appendJsonString(std::string& out, std::string_view text) {
  out += '"';
  // (text) => runs that need no escape appended whole, the escapes one by one
  std::size_t run = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c != '"' && c != '\\' && static_cast<unsigned char>(c) >= 0x20) continue;
    out.append(text.data() + run, i - run);
    run = i + 1;
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default: {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
        out += buf;
      }
    }
  }
  out.append(text.data() + run, text.size() - run);
  out += '"';
}

namespace {

// The last few numbers written and their text: a trace writes one time several times in a row
// (a transition's record, the state's record and the time inside the state), and the shortest
// round-trip conversion costs some 550 instructions. Keyed by the bits, so -0.0 and 0.0 (equal
// as doubles, written "-0" and "0") stay apart; the least recently used entry is replaced, so
// that a number written at every step (a fixed step's duration) stays; one cache per thread
// (initial-exec: the library is linked, not opened with dlopen, so no __tls_get_addr per use).
struct NumberCache {
  static constexpr std::size_t kSize = 4;
  std::uint64_t bits[kSize] = {};
  char text[kSize][32] = {};
  unsigned char length[kSize] = {};  // 0: empty
  std::uint64_t used[kSize] = {};    // when each entry was last written or hit (0: never)
  std::uint64_t clock = 0;
};
[[gnu::tls_model("initial-exec")]] thread_local NumberCache tCache;

}  // namespace

void appendJsonNumber(std::string& out, double value) {
  if (!std::isfinite(value)) {
    out += "null";
    return;
  }
  const auto bits = std::bit_cast<std::uint64_t>(value);
  NumberCache& c = tCache;
  std::size_t oldest = 0;
  for (std::size_t i = 0; i < NumberCache::kSize; ++i) {
    if (c.length[i] != 0 && c.bits[i] == bits) {
      c.used[i] = ++c.clock;
      out.append(c.text[i], c.length[i]);
      return;
    }
    if (c.used[i] < c.used[oldest]) oldest = i;
  }
  // (value) => its shortest round-trip form, kept in the cache in place of the oldest entry
  char buf[kShortestTextSize];
  const auto n = static_cast<std::size_t>(writeShortest(buf, value) - buf);
  out.append(buf, n);
  if (n == 0) return;
  std::memcpy(c.text[oldest], buf, n);
  c.bits[oldest] = bits;
  c.length[oldest] = static_cast<unsigned char>(n);
  c.used[oldest] = ++c.clock;
}

void appendJsonInteger(std::string& out, std::uint64_t value) {
  char buf[24];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, r.ptr);
}

}  // namespace yardsim::devs
