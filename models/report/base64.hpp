#pragma once
// Base64 (RFC 4648, with padding): how the report embeds binary arrays and replay.glb.
#include <cstddef>
#include <string>

namespace yardsim::models {

// (bytes) => their base64 text appended to out
void appendBase64(std::string& out, const void* data, std::size_t bytes);

}  // namespace yardsim::models
