#pragma once
// SHA-256 (FIPS 180-4, written out here: no libcrypto at start-up) of a byte string, as 64
// lowercase hex digits: the scene fingerprint written into every output's metadata.
#include <string>
#include <string_view>

namespace yardsim::scene {

std::string sha256Hex(std::string_view bytes);

}  // namespace yardsim::scene
