#include "devs/trace_format.hpp"

#include <charconv>
#include <cstdint>

#include "devs/json_number.hpp"

namespace yardsim::devs {

void appendJsonString(std::string& out, std::string_view text) {
  out += '"';
  // (text) => runs that need no escape appended whole, the escapes one by one
  std::size_t run = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c != '"' && c != '\\' && static_cast<unsigned char>(c) >= 0x20) continue;
    out.append(text.data() + run, i - run);
    run = i + 1;
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default: {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
        out += buf;
      }
    }
  }
  out.append(text.data() + run, text.size() - run);
  out += '"';
}

void appendJsonNumber(std::string& out, double value) {
  char buf[kJsonNumberSize];
  out.append(buf, writeJsonNumber(buf, value));
}

void appendJsonInteger(std::string& out, std::uint64_t value) {
  char buf[24];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, r.ptr);
}

}  // namespace yardsim::devs
