#pragma once
// The time grid of a discrete-time model: t_k = t0 + k h, computed from k (no accumulated
// rounding), and the first grid point strictly after a given time.
#include <cstdint>

#include "devs/time.hpp"

namespace yardsim::dtss {

using devs::Time;

// (step h, index k) => k h, computed as k / (1/h) when 1/h is an integer (h = 0.002, 0.05, ...),
// so that grids of different steps and decimal times agree exactly (599 * 0.05 is not 29.95,
// 599 / 20 is)
Time gridOffset(Time h, std::int64_t k);

struct Grid {
  Time t0;
  Time h;
  // (k) => t0 + k h
  Time at(std::int64_t k) const { return t0 + gridOffset(h, k); }
  // (t) => smallest k with at(k) > t
  std::int64_t indexAfter(Time t) const;
};

}  // namespace yardsim::dtss
