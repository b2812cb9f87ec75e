#pragma once
// DEVStone synthetic benchmark models (Glinsky & Wainer 2005; Risco-Martín et al. 2017,
// "A revised DEVStone"): LI, HI, HO and HOmod of depth d and width w, with no dummy work,
// fed by one seed event at t = 0. Each atomic, on input, becomes active with ta = 0, emits
// one message and becomes passive; the default PDEVS confluent rule (internal, then
// external) counts as one of each.
#include <cstdint>
#include <memory>
#include <string_view>

#include "devs/coupled.hpp"

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

// (variant, depth, width) => root model: the seeder coupled to the DEVStone structure
std::unique_ptr<devs::Coupled> build(Variant v, int depth, int width);
// (root from build, after a run) => transition counts summed over the DEVStone atomics
Counts count(const devs::Coupled& root);
// (variant, depth, width) => the closed-form counts of internal and external transitions
Counts expected(Variant v, int depth, int width);

}  // namespace yardsim::bench::devstone
