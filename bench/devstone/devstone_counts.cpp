#include "devstone_counts.hpp"

#include <stdexcept>
#include <string>

namespace yardsim::bench::devstone {

Variant parseVariant(std::string_view name) {
  if (name == "LI") return Variant::LI;
  if (name == "HI") return Variant::HI;
  if (name == "HO") return Variant::HO;
  if (name == "HOmod") return Variant::HOmod;
  throw std::invalid_argument("unknown DEVStone variant '" + std::string(name) +
                              "' (expected LI, HI, HO or HOmod)");
}

std::string_view variantName(Variant v) {
  switch (v) {
    case Variant::LI:
      return "LI";
    case Variant::HI:
      return "HI";
    case Variant::HO:
      return "HO";
    case Variant::HOmod:
      return "HOmod";
  }
  return "?";
}

Counts expected(Variant v, int depth, int width) {
  const std::uint64_t d = static_cast<std::uint64_t>(depth);
  const std::uint64_t w = static_cast<std::uint64_t>(width);
  Counts c;
  switch (v) {
    case Variant::LI:
      c.atomics = (w - 1) * (d - 1) + 1;
      c.internal = (w - 1) * (d - 1) + 1;
      break;
    case Variant::HI:
    case Variant::HO:
      c.atomics = (w - 1) * (d - 1) + 1;
      c.internal = (w * w - w) / 2 * (d - 1) + 1;
      break;
    case Variant::HOmod:
      c.atomics = (w - 1 + (w - 1) * w / 2) * (d - 1) + 1;
      c.internal = 1;
      for (std::uint64_t k = 1; k < d; ++k)
        c.internal += (1 + (k - 1) * (w - 1)) * (w - 1) * w / 2 + (w - 1) * (w + (k - 1) * (w - 1));
      break;
  }
  c.external = c.internal;
  return c;
}

}  // namespace yardsim::bench::devstone
