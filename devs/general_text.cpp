#include "devs/general_text.hpp"

#include <charconv>
#include <cmath>

namespace yardsim::devs {

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
  if (a == 0.0) {
    out += std::signbit(value) ? "-0" : "0";
    return;
  }
  if (!(a >= 1e-38 && a < 1e38)) return general6Slow(out, value);  // tiny, huge, nan, inf
  // (a) => its decimal exponent x and the six digits n = round(a 10^(5 - x)), 1e5 <= n < 1e6;
  // the binary exponent's estimate of x is off by at most one, corrected by the range of y
  int e2 = 0;
  std::frexp(a, &e2);
  int x = static_cast<int>(std::floor((e2 - 1) * 0.30102999566398120));
  double y = scale10(a, 5 - x);
  if (y < 1e5) y = scale10(a, 5 - --x);
  if (y >= 1e6) y = scale10(a, 5 - ++x);
  // (y within 3 ulps, < 1e-9, of a 10^(5 - x)) => rounded as printf rounds the exact value,
  // unless y is too near a half to tell. Near the ends of the range either exponent gives the
  // same text (99999.99... at x and 999999.9... at x - 1 both round to 1 followed by zeros at x).
  const double fraction = y - std::floor(y);
  if (std::fabs(fraction - 0.5) < 1e-6 || y < 99999.9 || y >= 1000000.1)
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
