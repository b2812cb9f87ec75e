#include "devs/trace_state_head.hpp"

#include <charconv>
#include <cstring>
#include <string_view>

#include "devs/json_number.hpp"

namespace yardsim::devs {

void appendStateHead(std::string& out, Time t, std::uint64_t steps) {
  // (t, steps) => the head's text in a local buffer (the pieces' lengths are known: fixed-size
  // copies), then appended once
  constexpr std::string_view kOpen = "{\"t\":", kSteps = ",\"steps\":", kX = ",\"x\":";
  char buf[kOpen.size() + kJsonNumberSize + kSteps.size() + 20 + kX.size()];  // 20 digits at most
  char* p = buf;
  std::memcpy(p, kOpen.data(), kOpen.size());
  p = writeJsonNumber(p + kOpen.size(), t);
  std::memcpy(p, kSteps.data(), kSteps.size());
  p += kSteps.size();
  p = std::to_chars(p, p + 20, steps).ptr;
  std::memcpy(p, kX.data(), kX.size());
  out.append(buf, static_cast<std::size_t>(p + kX.size() - buf));
}

}  // namespace yardsim::devs
