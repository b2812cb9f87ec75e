#pragma once
// Simulation time: seconds as double; +infinity is "passive, no internal event scheduled".
#include <limits>

namespace yardsim::devs {

using Time = double;
inline constexpr Time kInfinity = std::numeric_limits<Time>::infinity();

}  // namespace yardsim::devs
