#include "devs/json_number.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "devs/shortest_text.hpp"

namespace yardsim::devs {

namespace {

// The last few numbers written and their text: a trace writes one time several times in a row
// (a transition's record, the state's record and the time inside the state), and the shortest
// round-trip conversion costs some 300 instructions. Keyed by the bits, so -0.0 and 0.0 (equal
// as doubles, written "-0" and "0") stay apart; the least recently used entry is replaced, so
// that a number written at every step (a fixed step's duration) stays; one cache per thread
// (initial-exec: the library is linked, not opened with dlopen, so no __tls_get_addr per use).
struct NumberCache {
  static constexpr std::size_t kSize = 4;
  std::uint64_t bits[kSize] = {};
  char text[kSize][kJsonNumberSize] = {};
  unsigned char length[kSize] = {};  // 0: empty
  ShortestDecimal decimal[kSize];    // the digits of a positive number below 1e15, else m = 0
  std::uint64_t used[kSize] = {};    // when each entry was last written or hit (0: never)
  std::uint64_t clock = 0;
};
[[gnu::tls_model("initial-exec")]] thread_local NumberCache tCache;

static_assert(kJsonNumberSize >= kShortestTextSize);

}  // namespace

char* writeJsonNumber(char* buf, double value) {
  if (!std::isfinite(value)) {
    std::memcpy(buf, "null", 4);
    return buf + 4;
  }
  const auto bits = std::bit_cast<std::uint64_t>(value);
  NumberCache& c = tCache;
  std::size_t oldest = 0;
  for (std::size_t i = 0; i < NumberCache::kSize; ++i) {
    if (c.length[i] != 0 && c.bits[i] == bits) {
      c.used[i] = ++c.clock;
      // (hit) => the whole entry copied (a fixed size: no length-dependent copy), its length kept
      std::memcpy(buf, c.text[i], kJsonNumberSize);
      return buf + c.length[i];
    }
    if (c.used[i] < c.used[oldest]) oldest = i;
  }
  // (value) => its shortest round-trip form, kept in the cache in place of the oldest entry
  ShortestDecimal decimal;
  char* end = writeShortest(buf, value, decimal);
  const auto n = static_cast<std::size_t>(end - buf);
  if (n == 0) return end;
  std::memcpy(c.text[oldest], buf, kJsonNumberSize);
  c.decimal[oldest] = decimal;
  c.bits[oldest] = bits;
  c.length[oldest] = static_cast<unsigned char>(n);
  c.used[oldest] = ++c.clock;
  return end;
}

char* writeJsonMicroseconds(char* buf, double seconds) {
  const double us = seconds * 1e6;
  // (the kept digits m 10^e of seconds) => m 10^(e + 6), when it is a whole number below 1e15
  // (< 2^53) and exactly the product: its text from them, no conversion
  const auto bits = std::bit_cast<std::uint64_t>(seconds);
  const NumberCache& c = tCache;
  for (std::size_t i = 0; i < NumberCache::kSize; ++i) {
    if (c.length[i] == 0 || c.bits[i] != bits || c.decimal[i].significand == 0) continue;
    std::uint64_t m = c.decimal[i].significand;
    int e = c.decimal[i].exponent + 6;
    while (m % 10 == 0) {  // (trailing zeros) => off the digits: the shortest's own
      m /= 10;
      ++e;
    }
    if (e < 0 || e > 15 || m >= kPowersOfTen[15 - e]) break;
    const std::uint64_t whole = m * kPowersOfTen[e];  // < 1e15 < 2^53: exact as a double
    if (static_cast<double>(whole) != us) break;
    return writeDecimal(buf, m, e);
  }
  return writeJsonNumber(buf, us);
}

}  // namespace yardsim::devs
