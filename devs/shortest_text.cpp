#include "devs/shortest_text.hpp"

#include <fmt/format.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace yardsim::devs {

namespace {
// "00" "01" ... "99": two digits at once
constexpr char kPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// (n > 0) => its number of decimal digits (1 to 20)
int digitCount(std::uint64_t n) {
  // floor(log10(2^bits)): the count or one less
  const int guess = (static_cast<int>(std::bit_width(n)) * 1233) >> 12;
  return guess + (n >= kPowersOfTen[guess] ? 1 : 0);
}

// (n < 10^8) => its eight digits, leading zeros included, at p[0..8)
void writeEight(char* p, std::uint32_t n) {
  const std::uint32_t hi = n / 10000, lo = n % 10000;
  std::memcpy(p, kPairs + 2 * (hi / 100), 2);
  std::memcpy(p + 2, kPairs + 2 * (hi % 100), 2);
  std::memcpy(p + 4, kPairs + 2 * (lo / 100), 2);
  std::memcpy(p + 6, kPairs + 2 * (lo % 100), 2);
}

// (n with len digits) => its digits at p[0..len), in 32-bit pieces of eight
void writeDigits(char* p, std::uint64_t n, int len) {
  char* q = p + len;
  while (len >= 8) {
    q -= 8;
    writeEight(q, static_cast<std::uint32_t>(n % 100000000));
    n /= 100000000;
    len -= 8;
  }
  auto m = static_cast<std::uint32_t>(n);
  for (; len >= 2; len -= 2, m /= 100) {
    q -= 2;
    std::memcpy(q, kPairs + 2 * (m % 100), 2);
  }
  if (len == 1) *--q = static_cast<char>('0' + m);
}

// Dragonbox (fmt's) gives a's shortest digits m and exponent e with a = m 10^e read back, the
// nearest to a of that length, ties to even: the digits the standard asks of std::to_chars. Fixed
// when no longer than scientific; whole numbers fixed are m and e zeros, which is a's exact value
// below 2^53 (its rounding interval holds one integer). Inlined into writeShortest's conversions
// (one call a number) and writeDecimal.
[[gnu::always_inline]] inline char* decimalText(char* p, std::uint64_t m, int e) {
  const int len = digitCount(m);
  const int sci = e + len - 1;  // the scientific exponent
  const int sciAbs = sci < 0 ? -sci : sci;
  const int sciLength = len + (len > 1 ? 1 : 0) + 2 + (sciAbs >= 100 ? 3 : 2);
  const int fixedLength = e >= 0 ? len + e : (sci >= 0 ? len + 1 : len + 1 - sci);
  if (fixedLength <= sciLength) {
    if (e >= 0) {  // ddd000
      writeDigits(p, m, len);
      std::memcpy(p + len, "00000000", 8);  // e <= 5: fixed is no longer than scientific
      return p + len + e;
    }
    if (sci >= 0) {  // dd.ddd: the digits one place on, the leading ones moved back over
      writeDigits(p + 1, m, len);
      std::memmove(p, p + 1, static_cast<std::size_t>(sci + 1));
      p[sci + 1] = '.';
      return p + len + 1;
    }
    *p++ = '0';  // 0.00ddd
    *p++ = '.';
    std::memcpy(p, "0000", 4);  // -sci - 1 <= 3: fixed is no longer than scientific
    p += -sci - 1;
    writeDigits(p, m, len);
    return p + len;
  }
  // d.ddde-XX: the first digit moved before the point
  writeDigits(p + 1, m, len);
  p[0] = p[1];
  if (len > 1) {
    p[1] = '.';
    p += len + 1;
  } else {
    p += 1;
  }
  *p++ = 'e';
  *p++ = sci < 0 ? '-' : '+';
  if (sciAbs >= 100) *p++ = static_cast<char>('0' + sciAbs / 100);
  std::memcpy(p, kPairs + 2 * (sciAbs % 100), 2);
  return p + 2;
}

}  // namespace

char* writeDecimal(char* p, std::uint64_t m, int e) {
  return decimalText(p, m, e);
}

namespace {
// (value, where its decimal goes or null) => writeShortest's text; inlined into both forms, so
// that the time series' numbers do not keep a decimal they never read
[[gnu::always_inline]] inline char* shortest(char* buf, double value, ShortestDecimal* decimal) {
  // (finite non-zero value below 1e15) => Dragonbox; zero, 1e15 and above, nan and inf =>
  // std::to_chars
  if (decimal) *decimal = {};
  const double a = std::fabs(value);
  if (a > 0.0 && a < 1e15) {
    char* p = buf;
    const auto d = fmt::detail::dragonbox::to_decimal(a);
    if (std::signbit(value))
      *p++ = '-';
    else if (decimal)
      *decimal = {d.significand, d.exponent};
    return decimalText(p, d.significand, d.exponent);
  }
  return std::to_chars(buf, buf + kShortestTextSize, value).ptr;
}
}  // namespace

char* writeShortest(char* buf, double value, ShortestDecimal& decimal) {
  return shortest(buf, value, &decimal);
}

char* writeShortest(char* buf, double value) {
  return shortest(buf, value, nullptr);
}

}  // namespace yardsim::devs
