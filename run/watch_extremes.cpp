#include "run/watch_extremes.hpp"

#include "models/multibody/multibody_model.hpp"

namespace yardsim::run {

WatchExtremes::WatchExtremes(const devs::Model& root, AlarmMonitor& alarms) : alarms_(alarms) {
  collect(root);
}

void WatchExtremes::collect(const devs::Model& m) {
  if (!m.isAtomic()) {
    for (const auto& c : static_cast<const devs::Coupled&>(m).components()) collect(*c);
    return;
  }
  const auto* mb = dynamic_cast<const models::MultibodyModel*>(&m);
  if (mb == nullptr || mb->builtMechanics().watches.empty()) return;
  // (the model's channels, names relative to it) => the one of each watch's quantity
  std::vector<models::Channel> channels;
  mb->channels(channels);
  for (const auto& w : mb->builtMechanics().watches) {
    const std::string local = w.element + "." + w.quantity;
    for (const auto& c : channels)
      if (c.name == local || c.name == mb->path() + "." + local) {
        watches_.push_back({mb, w.name, w.above, c.read});
        break;
      }
  }
}

void WatchExtremes::onTransition(devs::Time t, const devs::AtomicBase& m, devs::Transition,
                                 devs::Time) {
  // (the model's watches at its committed state) => their crossed alarms' worst values
  for (const Watch& w : watches_)
    if (w.model == &m) alarms_.worsen(m.path(), w.name, "crossed", w.above, t, w.read());
}

}  // namespace yardsim::run
