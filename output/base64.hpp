#pragma once
// Base64 (RFC 4648, with padding; written out here, no libcrypto): how the report embeds binary
// arrays and replay.glb.
#include <cstddef>
#include <string>
#include <vector>

namespace yardsim::output {

// (bytes) => their base64 text appended to out
void appendBase64(std::string& out, const void* data, std::size_t bytes);
// (values) => a JSON string of the base64 of their little-endian float32 form, appended to out
// (how the pages carry large arrays: smaller and faster to parse than JSON numbers)
void appendFloat32Json(std::string& out, const std::vector<double>& values);

}  // namespace yardsim::output
