#include "forces/linear_quadratic_damping.hpp"

#include <cmath>
#include <stdexcept>

namespace yardsim::forces {

using dynamics::Vector3;

LinearQuadraticDamping::LinearQuadraticDamping(std::string name, const dynamics::Model& model,
                                               int body, const Vector3& p_B,
                                               const DampingCoefficients& c)
    : ForceProvider(std::move(name)), body_(body), p_B_(p_B), c_(c) {
  const std::string me = "damping '" + this->name() + "': ";
  if (body_ < 1 || body_ >= model.nbodies)
    throw std::invalid_argument(me + "body " + std::to_string(body_) +
                                " is the world or outside the model");
  if (!p_B_.allFinite()) throw std::invalid_argument(me + "the point is not finite");
  for (int i = 0; i < 6; ++i)
    if (!(c_.linear[i] >= 0) || !(c_.quadratic[i] >= 0) || !std::isfinite(c_.linear[i]) ||
        !std::isfinite(c_.quadratic[i]))
      throw std::invalid_argument(me + "coefficient " + std::to_string(i) +
                                  " must be finite and >= 0");
}

std::array<double, 6> LinearQuadraticDamping::velocity(const Stage& s) const {
  // (V body frame [omega; v_O]) => v at the point and omega, body axes
  const dynamics::Motion& V = s.data.V_B[body_];
  const Vector3 w = V.head<3>();
  const Vector3 v = V.tail<3>() + w.cross(p_B_);
  return {v.x(), v.y(), v.z(), w.x(), w.y(), w.z()};
}

std::array<double, 6> LinearQuadraticDamping::load(const Stage& s) const {
  const std::array<double, 6> u = velocity(s);
  std::array<double, 6> f{};
  for (std::size_t i = 0; i < 6; ++i)
    f[i] = -(c_.linear[i] * u[i] + c_.quadratic[i] * std::abs(u[i]) * u[i]);
  return f;
}

void LinearQuadraticDamping::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                                        Eigen::VectorXd& /*tau*/) const {
  // (force at the point, moment) => spatial force about the body origin, body frame
  const std::array<double, 6> l = load(s);
  const Vector3 force(l[0], l[1], l[2]), moment(l[3], l[4], l[5]);
  dynamics::Force F_B;
  F_B << moment + p_B_.cross(force), force;
  f.addBodyFrame(body_, F_B);
}

double LinearQuadraticDamping::doPower(const Stage& s) const {
  const std::array<double, 6> u = velocity(s), l = load(s);
  double p = 0.0;
  for (std::size_t i = 0; i < 6; ++i) p += l[i] * u[i];
  return p;
}

}  // namespace yardsim::forces
