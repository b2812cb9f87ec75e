#pragma once
// Named scalar outputs of a force provider (a spring's force and length, a mooring line's
// fairlead tension): a provider that implements ProviderOutputs declares them, and the multibody
// model makes one channel `<provider>.<output>` of each, read at the committed state with the
// provider's own scratch. ObservedProvider gives outputs to a provider that has none of its own
// (the physics of forces/ stays free of channel concerns): it owns the provider, forwards every
// call to it unchanged (the stage, the scratch, the energy and the power, the winch) and adds the
// outputs.
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "forces/force_provider.hpp"

namespace yardsim::forces {

// One output: its name below the provider's, its unit and how to read it at a stage.
struct ProviderOutput {
  std::string name;  // "force" => the channel <provider>.force
  std::string unit;  // "N", "m", "rad", ...
  std::function<double(const Stage&)> read;
  bool global = false;  // true: the channel is `name` itself, not <provider>.name
};

class ProviderOutputs {
 public:
  virtual ~ProviderOutputs() = default;
  // () => the outputs, in the order their channels are listed
  virtual const std::vector<ProviderOutput>& outputs() const = 0;
};

// A provider P with outputs: built with the provider and a function of it that lists them.
template <class P>
class ObservedProvider final : public ForceProvider, public ProviderOutputs {
 public:
  // (the provider, (provider) => its outputs, reading it through the reference) => the wrapper,
  // named like the provider
  ObservedProvider(std::unique_ptr<P> inner,
                   const std::function<std::vector<ProviderOutput>(const P&)>& list)
      : ForceProvider(inner->name()), inner_(std::move(inner)), outputs_(list(*inner_)) {}

  // () => the provider, its outputs, and its scratch (the wrapper's is the provider's own)
  const P& inner() const { return *inner_; }
  const std::vector<ProviderOutput>& outputs() const override { return outputs_; }
  std::unique_ptr<ProviderScratch> makeScratch() const override { return inner_->makeScratch(); }
  Winch* payoutWinch() override { return inner_->payoutWinch(); }

 protected:
  // (stage with the inner provider's scratch) => its forces, unchanged
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                  Eigen::VectorXd& tau) const override {
    inner_->evaluate(s, f, tau);
  }
  // (stage) => the provider's energy and power, unchanged
  double doPotentialEnergy(const Stage& s) const override { return inner_->potentialEnergy(s); }
  double doPower(const Stage& s) const override { return inner_->power(s); }

 private:
  std::unique_ptr<P> inner_;
  std::vector<ProviderOutput> outputs_;
};

// (provider, (provider) => outputs) => the provider with its outputs, as a ForceProvider
template <class P>
std::unique_ptr<ForceProvider> withOutputs(
    std::unique_ptr<P> inner, const std::function<std::vector<ProviderOutput>(const P&)>& list) {
  return std::make_unique<ObservedProvider<P>>(std::move(inner), list);
}

// (provider) => the P it is, or that it wraps with outputs, or nullptr
template <class P>
const P* providerAs(const ForceProvider& p) {
  if (const auto* direct = dynamic_cast<const P*>(&p)) return direct;
  if (const auto* observed = dynamic_cast<const ObservedProvider<P>*>(&p))
    return &observed->inner();
  return nullptr;
}

}  // namespace yardsim::forces
