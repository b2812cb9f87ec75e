#include "dynamics/integrators/explicit_euler.hpp"

#include "dynamics/configuration.hpp"

namespace yardsim::dynamics {

ExplicitEuler::ExplicitEuler(const Model& model) : model_(model), a_(model.nv) {}

void ExplicitEuler::step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v, double h) {
  // (t, q, v) => a; q = q (+) h v; v += h a
  evaluate(system, t, q, v, a_);
  integrate(model_, q, v, h, q);
  v += h * a_;
  t += h;
  ++stats_.steps;
  system.afterStep(t, q, v);
}

}  // namespace yardsim::dynamics
