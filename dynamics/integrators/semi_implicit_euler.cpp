#include "dynamics/integrators/semi_implicit_euler.hpp"

#include "dynamics/configuration.hpp"

namespace yardsim::dynamics {

SemiImplicitEuler::SemiImplicitEuler(const Model& model) : model_(model), a_(model.nv) {}

void SemiImplicitEuler::step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v, double h) {
  // (t, q, v) => a; v += h a; q = q (+) h v
  evaluate(system, t, q, v, a_);
  v += h * a_;
  integrate(model_, q, v, h, q);
  t += h;
  ++stats_.steps;
  system.afterStep(t, q, v);
}

}  // namespace yardsim::dynamics
