#pragma once
// The head of a DTSS state's trace text ({"t":...,"steps":...,"x":), put together in one piece:
// the trace writes one at every step (dtss/state.hpp's TraceFormat).
#include <cstdint>
#include <string>

#include "devs/time.hpp"

namespace yardsim::devs {

// (time of the committed state t (s), steps committed) => {"t":t,"steps":steps,"x": appended to
// out in one append: t as appendJsonNumber writes it, steps in decimal digits
void appendStateHead(std::string& out, Time t, std::uint64_t steps);

}  // namespace yardsim::devs
