#include "output/base64.hpp"

#include <openssl/evp.h>

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace yardsim::output {

void appendBase64(std::string& out, const void* data, std::size_t bytes) {
  // (bytes, in chunks libcrypto's int sizes take, multiples of 3) => padded base64, no newlines
  constexpr std::size_t kChunk = 3 * (1u << 28);
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t done = 0; done < bytes || (bytes == 0 && done == 0); done += kChunk) {
    const std::size_t n = std::min(kChunk, bytes - done);
    const std::size_t at = out.size();
    out.resize(at + 4 * ((n + 2) / 3) + 1);  // EVP_EncodeBlock writes a terminating NUL
    const int written = EVP_EncodeBlock(reinterpret_cast<unsigned char*>(out.data() + at), p + done, static_cast<int>(n));
    if (written < 0) throw std::runtime_error("base64: libcrypto's EVP_EncodeBlock failed");
    out.resize(at + static_cast<std::size_t>(written));
    if (bytes == 0) break;
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
