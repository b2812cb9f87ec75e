#include "devs/general_text.hpp"

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
char* general6Slow(char* buf, double value) {
  const auto [end, ec] =
      std::to_chars(buf, buf + kGeneral6TextSize, value, std::chars_format::general, 6);
  return ec == std::errc() ? end : buf;
}

}  // namespace

void appendGeneral6(std::string& out, double value) {
  char buf[kGeneral6TextSize];
  out.append(buf, writeGeneral6(buf, value));
}

char* writeGeneral6(char* buf, double value) {
  const double a = std::fabs(value);
  if (a == 0.0) {  // "0", "-0"
    if (std::signbit(value)) *buf++ = '-';
    *buf = '0';
    return buf + 1;
  }
  if (!(a >= 1e-38 && a < 1e38)) return general6Slow(buf, value);  // tiny, huge, nan, inf
  // (a) => its decimal exponent x and the six digits n = round(a 10^(5 - x)), 1e5 <= n < 1e6;
  // the binary exponent's estimate of x (floor(E log10 2), a in [2^E, 2^(E+1)), from the bits)
  // is off by at most one, corrected by the range of y
  const int e2 = static_cast<int>(std::bit_cast<std::uint64_t>(a) >> 52) - 1023;
  int x = (e2 * 1233) >> 12;  // floor(e2 log10 2) within one (an arithmetic shift floors)
  double y = scale10(a, 5 - x);
  if (y < 1e5) y = scale10(a, 5 - --x);
  if (y >= 1e6) y = scale10(a, 5 - ++x);
  // (y within 3 ulps, < 1e-9, of a 10^(5 - x)) => rounded as printf rounds the exact value,
  // unless y is too near a half to tell. Near the ends of the range either exponent gives the
  // same text (99999.99... at x and 999999.9... at x - 1 both round to 1 followed by zeros at x).
  if (y < 99999.9 || y >= 1000000.1) return general6Slow(buf, value);
  auto n = static_cast<std::uint32_t>(y);  // floor: y > 0
  const double fraction = y - n;           // exact: y < 2^20
  if (std::fabs(fraction - 0.5) < 1e-6) return general6Slow(buf, value);
  n += fraction > 0.5 ? 1 : 0;
  if (n == 1000000) {
    n = 100000;
    ++x;
  }
  char digits[12] = {};  // six digits, then room for the fixed case's copy of five past its point
  std::memcpy(digits, kPairs + 2 * (n / 10000), 2);
  std::memcpy(digits + 2, kPairs + 2 * (n / 100 % 100), 2);
  std::memcpy(digits + 4, kPairs + 2 * (n % 100), 2);
  int last = 5;  // the last digit kept: trailing zeros go
  while (last > 0 && digits[last] == '0') --last;
  char* p = buf;
  if (value < 0) *p++ = '-';
  if (x < -4 || x >= 6) {
    // (scientific) => d[.ddddd]e+XX, the exponent in at least two digits (below 38 here)
    *p++ = digits[0];
    if (last > 0) {
      *p++ = '.';
      std::memcpy(p, digits + 1, 5);
      p += last;
    }
    *p++ = 'e';
    *p++ = x < 0 ? '-' : '+';
    std::memcpy(p, kPairs + 2 * (x < 0 ? -x : x), 2);
    p += 2;
  } else if (x >= 0) {
    // (fixed, x + 1 integer digits) => ddd[.ddd]
    std::memcpy(p, digits, 6);
    p += x + 1;
    if (last > x) {
      *p = '.';
      std::memcpy(p + 1, digits + x + 1, 5);
      p += last - x + 1;
    }
  } else {
    // (fixed, below 1) => 0.000ddd
    std::memcpy(p, "0.0000", 6);
    p += 1 - x;
    std::memcpy(p, digits, 6);
    p += last + 1;
  }
  return p;
}

}  // namespace yardsim::devs
