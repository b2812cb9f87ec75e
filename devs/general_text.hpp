#pragma once
// printf's "%g" text of a double (six significant digits), for the trace's state texts.
#include <string>

namespace yardsim::devs {

// (number) => printf's "%g" text of it appended to out (six significant digits; "nan", "inf"),
// the same bytes as std::to_chars(general, 6), in a fraction of its time for most values
void appendGeneral6(std::string& out, double value);

}  // namespace yardsim::devs
