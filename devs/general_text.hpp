#pragma once
// printf's "%g" text of a double (six significant digits), for the trace's state texts.
#include <cstddef>
#include <string>

namespace yardsim::devs {

// Longest text writeGeneral6 writes ("-1.23457e-308"), with room to spare.
inline constexpr std::size_t kGeneral6TextSize = 24;

// (number, a buffer of kGeneral6TextSize chars) => the end of printf's "%g" text of it written
// from buf (six significant digits; "nan", "inf"), the same bytes as std::to_chars(general, 6), in
// a fraction of its time for most values
char* writeGeneral6(char* buf, double value);
// (number) => the same text appended to out
void appendGeneral6(std::string& out, double value);

}  // namespace yardsim::devs
