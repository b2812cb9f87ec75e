#pragma once
// Located state events of a force provider (a clearance watch falling below its threshold, two
// bodies touching, a contact set's onset and release): a provider that implements
// ProviderEvents declares them, and the mechanical system adds one event function per entry to
// its event table after the built-in ones (mechanics/events.hpp). The stepper locates the zero
// crossing of g like any other; the report names the element, the kind and a value (SI) with an
// optional detail (the pair, witness points).
#include <functional>
#include <string>
#include <vector>

#include "forces/force_provider.hpp"

namespace yardsim::forces {

struct ProviderEvent {
  std::string element;  // the event's element, e.g. "<provider>.<watch>"
  std::string rising;   // the kind reported when g rises through 0 ("touched")
  std::string falling;  // the kind when g falls through 0; "" => only rising crossings count
  // (stage, kinematics in its data, no scratch) => > 0 past the event; continuous in the state
  std::function<double(const Stage&)> g;
  // (stage at the event) => the value reported (SI) and the detail ("" for none)
  std::function<double(const Stage&)> value;
  std::function<std::string(const Stage&)> detail;
};

class ProviderEvents {
 public:
  virtual ~ProviderEvents() = default;
  // () => the events, in the order of their event functions
  virtual const std::vector<ProviderEvent>& events() const = 0;
};

}  // namespace yardsim::forces
