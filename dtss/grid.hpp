#pragma once
// The time grid of a discrete-time model: t_k = t0 + k h, computed from k (no accumulated
// rounding), and the first grid point strictly after a given time.
#include <cstdint>

#include "devs/time.hpp"

namespace yardsim::dtss {

using devs::Time;

struct Grid {
  Time t0;
  Time h;
  // (k) => t0 + k h
  Time at(std::int64_t k) const { return t0 + static_cast<double>(k) * h; }
  // (t) => smallest k with at(k) > t
  std::int64_t indexAfter(Time t) const;
};

}  // namespace yardsim::dtss
