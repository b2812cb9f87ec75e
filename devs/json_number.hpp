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

// (time in seconds, a buffer of kJsonNumberSize chars) => the end of the JSON text of seconds 1e6
// (the double product, microseconds) written from buf, as writeJsonNumber(buf, seconds * 1e6)
// writes it. When the text of seconds was written lately (its digits kept) and the product is
// exactly those digits six places on, a whole number below 2^53, they are its shortest digits too
// (its rounding interval holds one integer) and the text is made from them: a trace's step times
// are written in seconds (JSON Lines) and in microseconds (Chrome) at one step's distance.
char* writeJsonMicroseconds(char* buf, double seconds);

}  // namespace yardsim::devs
