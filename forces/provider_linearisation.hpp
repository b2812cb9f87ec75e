#pragma once
// A force with an analytic linearisation (a quasi-static catenary line, whose force comes from an
// inner Newton solve): the finite-difference Jacobians of the implicit methods' Newton matrices
// and of the stiffness estimate (AccelerationSource::beginLinearisation) ask the provider to
// linearise about the base state, and until release() its evaluate() with that scratch returns
// F(x) = F_0 + dF/dx (x - x_0) instead of solving: each difference then holds the analytic
// derivative, exactly, and costs no solve. The value at the base state is the force itself.
#include "forces/force_provider.hpp"

namespace yardsim::forces {

class ProviderLinearisation {
 public:
  virtual ~ProviderLinearisation() = default;
  // (stage with this provider's scratch) => the scratch holds the linearisation about the stage;
  // throws ForceError as evaluate() would there
  virtual void linearise(const Stage& s) const = 0;
  // (the scratch linearise() wrote) => evaluate() solves again
  virtual void release(ProviderScratch& scratch) const = 0;
};

}  // namespace yardsim::forces
