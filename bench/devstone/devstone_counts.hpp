#pragma once
// The DEVStone variants and the closed-form transition counts (Glinsky & Wainer 2005;
// Risco-Martín et al. 2017), free of any simulator: shared by yardsim's DEVStone models and the
// peers' harnesses in bench/peers/ (which check their counts against the same forms).
#include <cstdint>
#include <string_view>

namespace yardsim::bench::devstone {

enum class Variant { LI, HI, HO, HOmod };

// ("LI" | "HI" | "HO" | "HOmod") => variant; throws std::invalid_argument otherwise
Variant parseVariant(std::string_view name);
std::string_view variantName(Variant v);

struct Counts {
  std::uint64_t atomics = 0;
  std::uint64_t internal = 0;
  std::uint64_t external = 0;
};

// (variant, depth, width) => the closed-form counts of internal and external transitions
Counts expected(Variant v, int depth, int width);

}  // namespace yardsim::bench::devstone
