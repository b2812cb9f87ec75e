#include "devs/trace_format.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

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
// as doubles, written "-0" and "0") stay apart; one cache per thread.
struct NumberCache {
  static constexpr std::size_t kSize = 4;
  std::uint64_t bits[kSize] = {};
  char text[kSize][32] = {};
  unsigned char length[kSize] = {};  // 0: empty
  std::size_t next = 0;              // the entry replaced next (round robin)
};
thread_local NumberCache tCache;

}  // namespace

void appendJsonNumber(std::string& out, double value) {
  if (!std::isfinite(value)) {
    out += "null";
    return;
  }
  const auto bits = std::bit_cast<std::uint64_t>(value);
  NumberCache& c = tCache;
  for (std::size_t i = 0; i < NumberCache::kSize; ++i)
    if (c.length[i] != 0 && c.bits[i] == bits) {
      out.append(c.text[i], c.length[i]);
      return;
    }
  // (value) => its shortest round-trip form, kept in the cache
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  const auto n = static_cast<std::size_t>(ec == std::errc() ? end - buf : 0);
  out.append(buf, n);
  if (n == 0) return;
  std::memcpy(c.text[c.next], buf, n);
  c.bits[c.next] = bits;
  c.length[c.next] = static_cast<unsigned char>(n);
  c.next = (c.next + 1) % NumberCache::kSize;
}

namespace {

// 10^0 ... 10^22: every one exact as a double
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// (a > 0, p with |p| <= 44) => a 10^p, within 3 ulps (one or two exact powers, each one rounding)
double scale10(double a, int p) {
  if (p >= 0) return p <= 22 ? a * kPow10[p] : a * kPow10[22] * kPow10[p - 22];
  return -p <= 22 ? a / kPow10[-p] : a / kPow10[22] / kPow10[-p - 22];
}

// (value) => "%g" through std::to_chars: the reference, and the way for values the fast path
// leaves (zero, non-finite, far exponents, a rounding too close to call)
void general6Slow(std::string& out, double value) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::general, 6);
  out.append(buf, ec == std::errc() ? end : buf);
}

}  // namespace

void appendGeneral6(std::string& out, double value) {
  const double a = std::fabs(value);
  if (!(a >= 1e-38 && a < 1e38)) return general6Slow(out, value);  // zero, tiny, huge, nan, inf
  // (a) => its decimal exponent x and the six digits n = round(a 10^(5 - x)), 1e5 <= n < 1e6;
  // the binary exponent's estimate of x is off by at most one, corrected by the range of y
  int e2 = 0;
  std::frexp(a, &e2);
  int x = static_cast<int>(std::floor((e2 - 1) * 0.30102999566398120));
  double y = scale10(a, 5 - x);
  if (y < 1e5) y = scale10(a, 5 - --x);
  if (y >= 1e6) y = scale10(a, 5 - ++x);
  // (y within 3 ulps, < 1e-9, of a 10^(5 - x)) => rounded as printf rounds the exact value,
  // unless y is too near a half or the ends of the range to tell
  const double fraction = y - std::floor(y);
  if (std::fabs(fraction - 0.5) < 1e-6 || y < 1e5 + 1e-6 || y > 1e6 - 1e-6 || y < 1e5 || y >= 1e6)
    return general6Slow(out, value);
  auto n = static_cast<long>(std::floor(y + 0.5));
  if (n == 1000000) {
    n = 100000;
    ++x;
  }
  char digits[6];
  for (int i = 5; i >= 0; --i, n /= 10) digits[i] = static_cast<char>('0' + n % 10);
  int last = 5;  // the last digit kept: trailing zeros go
  while (last > 0 && digits[last] == '0') --last;
  char buf[32];
  char* p = buf;
  if (value < 0) *p++ = '-';
  if (x < -4 || x >= 6) {
    // (scientific) => d[.ddddd]e+XX, the exponent in at least two digits
    *p++ = digits[0];
    if (last > 0) {
      *p++ = '.';
      for (int i = 1; i <= last; ++i) *p++ = digits[i];
    }
    *p++ = 'e';
    *p++ = x < 0 ? '-' : '+';
    const int ex = x < 0 ? -x : x;
    if (ex >= 10)
      *p++ = static_cast<char>('0' + ex / 10);
    else
      *p++ = '0';
    *p++ = static_cast<char>('0' + ex % 10);
  } else if (x >= 0) {
    // (fixed, x + 1 integer digits) => ddd[.ddd]
    for (int i = 0; i <= x; ++i) *p++ = digits[i];
    if (last > x) {
      *p++ = '.';
      for (int i = x + 1; i <= last; ++i) *p++ = digits[i];
    }
  } else {
    // (fixed, below 1) => 0.000ddd
    *p++ = '0';
    *p++ = '.';
    for (int i = 0; i < -x - 1; ++i) *p++ = '0';
    for (int i = 0; i <= last; ++i) *p++ = digits[i];
  }
  out.append(buf, p);
}

}  // namespace yardsim::devs
