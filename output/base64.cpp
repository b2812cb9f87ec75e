#include "output/base64.hpp"

#include <algorithm>

namespace yardsim::output {

void appendBase64(std::string& out, const void* data, std::size_t bytes) {
  // (three bytes) => four characters of 6 bits each; a last one or two bytes padded with '='
  static const char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* p = static_cast<const unsigned char*>(data);
  std::size_t at = out.size();
  out.resize(at + 4 * ((bytes + 2) / 3));
  char* o = out.data() + at;
  std::size_t i = 0;
  for (; i + 3 <= bytes; i += 3, o += 4) {
    const unsigned v = unsigned{p[i]} << 16 | unsigned{p[i + 1]} << 8 | unsigned{p[i + 2]};
    o[0] = kDigits[v >> 18];
    o[1] = kDigits[(v >> 12) & 63];
    o[2] = kDigits[(v >> 6) & 63];
    o[3] = kDigits[v & 63];
  }
  if (i < bytes) {
    const unsigned v = unsigned{p[i]} << 16 | (i + 1 < bytes ? unsigned{p[i + 1]} << 8 : 0U);
    o[0] = kDigits[v >> 18];
    o[1] = kDigits[(v >> 12) & 63];
    o[2] = i + 1 < bytes ? kDigits[(v >> 6) & 63] : '=';
    o[3] = '=';
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
