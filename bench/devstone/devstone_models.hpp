#pragma once
// DEVStone synthetic benchmark models (Glinsky & Wainer 2005; Risco-Martín et al. 2017,
// "A revised DEVStone"): LI, HI, HO and HOmod of depth d and width w, with no dummy work,
// fed by one seed event at t = 0. Each atomic, on input, becomes active with ta = 0, emits
// one message and becomes passive; the default PDEVS confluent rule (internal, then
// external) counts as one of each.
#include <memory>

#include "devs/coupled.hpp"
#include "devstone_counts.hpp"

namespace yardsim::bench::devstone {

// (variant, depth, width) => root model: the seeder coupled to the DEVStone structure
std::unique_ptr<devs::Coupled> build(Variant v, int depth, int width);
// (root from build, after a run) => transition counts summed over the DEVStone atomics
Counts count(const devs::Coupled& root);

}  // namespace yardsim::bench::devstone
