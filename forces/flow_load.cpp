#include "forces/flow_load.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dynamics/kinematics.hpp"

namespace yardsim::forces {

using dynamics::Vector3;

FlowCoefficients::FlowCoefficients(std::vector<double> angles, std::vector<double> cx,
                                   std::vector<double> cy, std::vector<double> cmz)
    : angles_(std::move(angles)), cx_(std::move(cx)), cy_(std::move(cy)), cmz_(std::move(cmz)) {
  const std::size_t n = angles_.size();
  if (n < 2 || cx_.size() != n || cy_.size() != n || cmz_.size() != n)
    throw std::invalid_argument(
        "flow coefficients: at least 2 angles, and cx, cy, cmz of the same length as the angles");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(angles_[i]) || !std::isfinite(cx_[i]) || !std::isfinite(cy_[i]) ||
        !std::isfinite(cmz_[i]))
      throw std::invalid_argument("flow coefficients: entry " + std::to_string(i) +
                                  " is not finite");
    if (i > 0 && !(angles_[i] > angles_[i - 1]))
      throw std::invalid_argument("flow coefficients: the angles must increase strictly");
  }
  const double tol = 1e-9;
  if (std::abs(angles_.front()) > tol)
    throw std::invalid_argument("flow coefficients: the angles must start at 0");
  if (std::abs(angles_.back() - M_PI) < tol)
    mirrored_ = true;
  else if (std::abs(angles_.back() - 2 * M_PI) > tol)
    throw std::invalid_argument(
        "flow coefficients: the angles must end at 180 deg (mirrored) or 360 deg");
}

std::array<double, 3> FlowCoefficients::at(double theta) const {
  double a = std::fmod(theta, 2 * M_PI);
  if (a < 0) a += 2 * M_PI;
  if (angles_.empty()) return {-std::cos(a), -std::sin(a), 0.0};
  // (mirrored table, angle past 180 deg) => the mirror angle, with C_y and C_mz negated
  double sign = 1.0;
  if (mirrored_ && a > M_PI) {
    a = 2 * M_PI - a;
    sign = -1.0;
  }
  const auto hi = std::min(std::upper_bound(angles_.begin(), angles_.end(), a), angles_.end() - 1);
  const auto i = static_cast<std::size_t>(hi - angles_.begin());
  const double w = std::clamp((a - angles_[i - 1]) / (angles_[i] - angles_[i - 1]), 0.0, 1.0);
  auto lerp = [&](const std::vector<double>& c) { return (1.0 - w) * c[i - 1] + w * c[i]; };
  return {lerp(cx_), sign * lerp(cy_), sign * lerp(cmz_)};
}

FlowLoad::FlowLoad(std::string name, const dynamics::Model& model, int body, const Vector3& p_B,
                   const FlowAreas& areas, FlowCoefficients coefficients, double density)
    : ForceProvider(std::move(name)),
      body_(body),
      p_B_(p_B),
      areas_(areas),
      coefficients_(std::move(coefficients)),
      density_(density) {
  const std::string me = "flow load '" + this->name() + "': ";
  if (body_ < 1 || body_ >= model.nbodies)
    throw std::invalid_argument(me + "body " + std::to_string(body_) +
                                " is the world or outside the model");
  if (!p_B_.allFinite()) throw std::invalid_argument(me + "the point is not finite");
  if (!(areas_.frontal >= 0) || !(areas_.lateral >= 0) || !(areas_.length >= 0) ||
      !std::isfinite(areas_.frontal + areas_.lateral + areas_.length))
    throw std::invalid_argument(me + "areas and length must be finite and >= 0");
  if (!(density_ > 0) || !std::isfinite(density_))
    throw std::invalid_argument(me + "the density must be > 0");
}

FlowLoadState FlowLoad::load(const Stage& s) const {
  // (flow at the point minus the point's velocity, horizontal) => relative flow in heading axes
  const dynamics::Transform& X = s.data.X_WB[body_];
  const Vector3 p_W = X.actPoint(p_B_);
  Vector3 u_W = flowVelocity(p_W, s.t) - dynamics::pointVelocity(s.data, body_, p_B_);
  u_W.z() = 0.0;
  const double psi = std::atan2(X.R(1, 0), X.R(0, 0));
  const double c = std::cos(psi), sn = std::sin(psi);
  const double ux = c * u_W.x() + sn * u_W.y(), uy = -sn * u_W.x() + c * u_W.y();
  FlowLoadState r;
  r.speed = std::hypot(ux, uy);
  if (r.speed == 0.0) return r;
  r.angle = std::atan2(-uy, -ux);  // where it comes from
  const std::array<double, 3> C = coefficients_.at(r.angle);
  const double q = 0.5 * density_ * r.speed * r.speed;
  const double fx = q * areas_.frontal * C[0], fy = q * areas_.lateral * C[1];
  r.force = Vector3(c * fx - sn * fy, sn * fx + c * fy, 0.0);
  r.yawMoment = q * areas_.lateral * areas_.length * C[2];
  return r;
}

void FlowLoad::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                          Eigen::VectorXd& /*tau*/) const {
  const FlowLoadState r = load(s);
  const Vector3 p_W = s.data.X_WB[body_].actPoint(p_B_);
  dynamics::Force F_W;
  F_W << p_W.cross(r.force) + Vector3(0.0, 0.0, r.yawMoment), r.force;
  f.addWorldFrame(body_, F_W);
}

double FlowLoad::doPower(const Stage& s) const {
  const FlowLoadState r = load(s);
  const Vector3 omega_W = s.data.X_WB[body_].R * s.data.V_B[body_].head<3>();
  return r.force.dot(dynamics::pointVelocity(s.data, body_, p_B_)) + r.yawMoment * omega_W.z();
}

}  // namespace yardsim::forces
