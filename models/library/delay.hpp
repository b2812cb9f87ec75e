#pragma once
// Scene type `delay`: forwards every int it receives after `delay` seconds (0: at once, a
// zero-delay feedthrough).
#include <ostream>
#include <vector>

#include "devs/atomic.hpp"

namespace yardsim::models::library {

struct DelayState {
  devs::Time sigma = devs::kInfinity;
  std::vector<int> held;
};
std::ostream& operator<<(std::ostream& os, const DelayState& s);

}  // namespace yardsim::models::library

namespace yardsim::devs {
template <>
struct StateCodec<models::library::DelayState> : FieldCodec<models::library::DelayState> {
  static auto fields(auto& s) { return std::tie(s.sigma, s.held); }
};
}  // namespace yardsim::devs

namespace yardsim::models::library {

class Delay final : public devs::Atomic<DelayState> {
 public:
  Delay(std::string name, devs::Time delay);
  devs::InPort<int>& in = addInPort<int>("in");
  devs::OutPort<int>& out = addOutPort<int>("out");

 protected:
  devs::Time timeAdvance(const DelayState& s) const override { return s.sigma; }
  void output(const DelayState& s) const override;
  void internalTransition(DelayState& s) const override;
  void externalTransition(DelayState& s, devs::Time e) const override;

 private:
  devs::Time delay_;
};

}  // namespace yardsim::models::library
