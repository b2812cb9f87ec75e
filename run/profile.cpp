#include "run/profile.hpp"

#include <cstdio>

#if defined(__x86_64__)
#include <cpuid.h>
#include <x86intrin.h>
#endif

namespace yardsim::run {

std::int64_t steadyNanoseconds() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

std::int64_t timeStampTicks() {
#if defined(__x86_64__)
  return static_cast<std::int64_t>(__rdtsc());
#else
  return steadyNanoseconds();
#endif
}

bool timeStampTicksInvariant() {
#if defined(__x86_64__)
  // (CPUID 0x80000007, advanced power management) => EDX bit 8: the counter is invariant
  static const bool invariant = [] {
    unsigned a = 0, b = 0, c = 0, d = 0;
    return __get_cpuid(0x80000007, &a, &b, &c, &d) != 0 && (d & (1u << 8)) != 0;
  }();
  return invariant;
#else
  return false;
#endif
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
