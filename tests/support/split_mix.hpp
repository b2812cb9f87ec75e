#pragma once
// SplitMix64: a small, fast, seeded stream of 64-bit values for tests that sweep many doubles
// (random bit patterns, random magnitudes) reproducibly.
#include <cstdint>

namespace yardsim::test {

struct SplitMix64 {
  std::uint64_t state;
  // () => the next 64-bit value of the stream
  std::uint64_t operator()() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
};

}  // namespace yardsim::test
