#pragma once
// The worst value of each watch crossing (docs/scenes.md, "Alarms"): a `crossed` event is
// located where the watched quantity passes its threshold, so its own value is the threshold.
// This listener reads every watched quantity after every transition of its multibody model
// (the committed state, through the model's channel `<element>.<quantity>`, SI) and moves the
// watch's `crossed` alarm to the largest value seen for an upper limit (`above:`), the smallest
// for a lower one (`below:`), with its time. Sampled at the model's steps and events: the
// extreme between two steps is not interpolated. Nothing is recorded or traced.
#include <functional>
#include <string>
#include <vector>

#include "devs/coupled.hpp"
#include "devs/listener.hpp"
#include "run/alarms.hpp"

namespace yardsim::run {

class WatchExtremes final : public devs::Listener {
 public:
  // (the assembled root, the alarms to update) => a reader per watch of every multibody model
  WatchExtremes(const devs::Model& root, AlarmMonitor& alarms);
  void onTransition(devs::Time t, const devs::AtomicBase& m, devs::Transition kind,
                    devs::Time e) override;
  bool empty() const { return watches_.empty(); }

 private:
  struct Watch {
    const devs::AtomicBase* model;
    std::string name;
    bool above;
    std::function<double()> read;  // SI
  };
  // (model tree) => its multibody models' watches appended
  void collect(const devs::Model& m);
  std::vector<Watch> watches_;
  AlarmMonitor& alarms_;
};

}  // namespace yardsim::run
