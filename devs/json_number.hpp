#pragma once
// A JSON number written into a buffer: the trace's times and values (appendJsonNumber,
// devs/trace_format.hpp, writes the same text into a string).
#include <cstddef>

namespace yardsim::devs {

// Longest text writeJsonNumber writes (writeShortest's), with room to spare.
inline constexpr std::size_t kJsonNumberSize = 32;

// (number, a buffer of kJsonNumberSize chars) => the end of its JSON text written from buf: the
// shortest round-trip digits (writeShortest), "null" for a non-finite value (JSON has none). The
// last few numbers' texts are kept, so a time written several times in a row is converted once.
char* writeJsonNumber(char* buf, double value);

}  // namespace yardsim::devs
