#include "run/profile.hpp"

#include <cstdio>

namespace yardsim::run {

std::int64_t steadyNanoseconds() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

std::string formatProfile(const PhaseTimes& p) {
  const double total = p.read + p.validation + p.stiffness + p.build + p.simulate + p.output;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "profile: read %.3g s, validation %.3g s, stiffness guard %.3g s, build %.3g s, "
                "simulate %.3g s, "
                "output %.3g s (%.1f %% of the run), total %.3g s",
                p.read, p.validation, p.stiffness, p.build, p.simulate, p.output,
                total > 0.0 ? 100.0 * p.output / total : 0.0, total);
  return buf;
}

}  // namespace yardsim::run
