#include "devs/shortest_text.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>

namespace yardsim::devs {

namespace {
// 10^0 ... 10^6, exact as doubles
constexpr double kPow10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6};

// (a > 0 with at most six decimals, as n / 10^k) => n's digits with the point k digits from the
// right, "0." and zeros first when n < 10^k
char* writeFixed(char* p, std::uint64_t n, int k) {
  char digits[24];
  int len = 0;
  do {
    digits[len++] = static_cast<char>('0' + n % 10);
    n /= 10;
  } while (n != 0);
  if (len <= k) {  // 0.0ddd
    *p++ = '0';
    *p++ = '.';
    for (int z = len; z < k; ++z) *p++ = '0';
    while (len > 0) *p++ = digits[--len];
    return p;
  }
  for (int i = len - 1; i >= 0; --i) {
    *p++ = digits[i];
    if (i == k && k > 0) *p++ = '.';
  }
  return p;
}

// (whole number 1e5 <= n < 1e9) => whether std::to_chars writes it fixed: its D digits are no
// more than scientific's s digits, point (when s > 1) and "e+0X" (s: D less its trailing zeros)
bool fixedIsShorter(std::uint64_t n) {
  int digits = 0, zeros = 0;
  bool trailing = true;
  for (; n != 0; n /= 10, ++digits) {
    trailing = trailing && n % 10 == 0;
    zeros += trailing;
  }
  const int significant = digits - zeros;
  return digits <= significant + (significant > 1 ? 1 : 0) + 4;
}
}  // namespace

char* writeShortest(char* buf, double value) {
  // (0.001 <= |v| < 1e9) => the fewest decimals k <= 6 whose nearest n = round(|v| 10^k) gives v
  // back as n / 10^k (one correctly rounded division: the double strtod reads from that text).
  // That text is the shortest round trip: a shorter one would have fewer decimals, and its n is
  // the nearest integer to |v| 10^k, which the product finds (|v| 10^k < 2^50: its rounding is
  // below 1/8); and the only one of its length: v's rounding interval (about 2.2e-7 wide below
  // 1e9) holds one multiple of 10^-6 at most. Fixed is std::to_chars' choice there: shorter than
  // scientific with decimals when |v| >= 1, as short or shorter for 0.001 <= |v| < 1 (two zeros
  // after the point at most) and for whole numbers below 1e5; above, when fixedIsShorter
  const double a = std::fabs(value);
  if (a >= 1e-3 && a < 1e9) {
    for (int k = 0; k <= 6; ++k) {
      const double n = std::nearbyint(a * kPow10[k]);
      if (n / kPow10[k] != a) continue;
      if (k == 0 && n >= 1e5 && !fixedIsShorter(static_cast<std::uint64_t>(n))) break;
      char* p = buf;
      if (std::signbit(value)) *p++ = '-';
      return writeFixed(p, static_cast<std::uint64_t>(n), k);
    }
  }
  return std::to_chars(buf, buf + kShortestTextSize, value).ptr;
}

}  // namespace yardsim::devs
