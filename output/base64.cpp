#include "output/base64.hpp"

#include <algorithm>
#include <cstdint>

namespace yardsim::output {

void appendBase64(std::string& out, const void* data, std::size_t bytes) {
  static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* p = static_cast<const std::uint8_t*>(data);
  out.reserve(out.size() + (bytes + 2) / 3 * 4);
  std::size_t i = 0;
  // (three bytes) => four characters
  for (; i + 3 <= bytes; i += 3) {
    const std::uint32_t v = (std::uint32_t{p[i]} << 16) | (std::uint32_t{p[i + 1]} << 8) | p[i + 2];
    for (int s = 18; s >= 0; s -= 6) out += kAlphabet[(v >> s) & 63];
  }
  // (one or two bytes left) => padded
  if (const std::size_t rest = bytes - i) {
    std::uint32_t v = std::uint32_t{p[i]} << 16;
    if (rest == 2) v |= std::uint32_t{p[i + 1]} << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += rest == 2 ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
}

void appendFloat32Json(std::string& out, const std::vector<double>& values) {
  std::vector<float> f(values.size());
  std::transform(values.begin(), values.end(), f.begin(), [](double v) { return static_cast<float>(v); });
  out += '"';
  appendBase64(out, f.data(), f.size() * sizeof(float));
  out += '"';
}

}  // namespace yardsim::output
