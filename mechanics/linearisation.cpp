#include "mechanics/linearisation.hpp"

#include <memory>
#include <utility>
#include <vector>

#include "forces/lines/catenary_line.hpp"
#include "forces/provider_outputs.hpp"

namespace yardsim::mechanics {

const forces::ProviderLinearisation* linearisationOf(const forces::ForceProvider& p) {
  if (const auto* direct = dynamic_cast<const forces::ProviderLinearisation*>(&p)) return direct;
  return forces::providerAs<forces::CatenaryLine>(p);
}

void connectLinearisation(const System& s, Data& d) {
  // (providers) => those with a linearisation, with their places in the list (their scratch)
  using Entry = std::pair<const forces::ProviderLinearisation*, std::size_t>;
  auto entries = std::make_shared<std::vector<Entry>>();
  const auto& providers = s.providers();
  for (std::size_t i = 0; i < providers.size(); ++i)
    if (const forces::ProviderLinearisation* l = linearisationOf(*providers[i]))
      if (d.providerScratch[i] != nullptr) entries->emplace_back(l, i);
  if (entries->empty()) {
    d.kernel.setLinearisation(nullptr);
    return;
  }
  // (on, the base state's stage) => each linearised there in its scratch; (off) => released
  d.kernel.setLinearisation([&s, &d, entries](bool on, double t, const Eigen::VectorXd& q,
                                              const Eigen::VectorXd& v, const dynamics::Data& kin) {
    if (!on) {
      for (const auto& [l, i] : *entries) l->release(*d.providerScratch[i]);
      return;
    }
    forces::Stage stage = d.stage(s, t, kin, q, v);
    for (const auto& [l, i] : *entries) {
      stage.scratch = d.providerScratch[i].get();
      l->linearise(stage);
    }
  });
}

}  // namespace yardsim::mechanics
