#pragma once
// Locating the zero of a state-event function inside one step, by the Illinois variant of
// regula falsi (superlinear, bracket always kept). The function is evaluated by re-advancing
// the model from the start of the step, so no interpolant is needed.
#include <cmath>

#include "devs/time.hpp"

namespace yardsim::dtss {

using devs::Time;

// Direction of a crossing that counts as a state event.
enum class Crossing { Rising, Falling, Both };

// (g at the ends of a step, direction) => whether g crosses zero in the step that way.
// A function that starts exactly at zero does not count (it was the previous event).
inline bool crosses(double g0, double g1, Crossing dir) {
  const bool rising = g0 < 0.0 && g1 >= 0.0;
  const bool falling = g0 > 0.0 && g1 <= 0.0;
  return dir == Crossing::Rising ? rising : dir == Crossing::Falling ? falling : rising || falling;
}

// (g on [a, b] with g(a), g(b) of opposite signs or g(b) == 0, tolerance) => time tc after the
// crossing (g(tc) has the sign of g(b) or is zero) with tc - t_true < tol.
template <class G>
Time locateCrossing(G&& g, Time a, double ga, Time b, double gb, Time tol) {
  int side = 0;
  for (int it = 0; it < 200 && b - a > tol; ++it) {
    Time c = (a * gb - b * ga) / (gb - ga);
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    const double gc = g(c);
    if (gc == 0.0 || (gc > 0.0) != (ga > 0.0)) {  // the zero is in [a, c]
      b = c;
      gb = gc;
      if (side == -1) ga *= 0.5;  // a kept twice: halve g(a) so the bracket keeps shrinking
      side = -1;
    } else {
      a = c;
      ga = gc;
      if (side == 1) gb *= 0.5;
      side = 1;
    }
  }
  return b;
}

}  // namespace yardsim::dtss
