#include "forces/body_load.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dynamics/kinematics.hpp"

namespace yardsim::forces {

using dynamics::Vector3;

BodyLoad::BodyLoad(std::string name, const dynamics::Model& model, int body, const Vector3& p_B,
                   LoadFrame frame)
    : ForceProvider(std::move(name)), body_(body), p_B_(p_B), frame_(frame) {
  if (body_ < 1 || body_ >= model.nbodies)
    throw std::invalid_argument("body load '" + this->name() + "': body " + std::to_string(body_) +
                                " is the world or outside the model's " +
                                std::to_string(model.nbodies) + " bodies");
  if (!p_B_.allFinite())
    throw std::invalid_argument("body load '" + this->name() + "': the point is not finite");
}

void BodyLoad::setTimeSeries(std::vector<LoadSample> samples) {
  // (samples) => finite, times non-decreasing
  if (samples.empty())
    throw std::invalid_argument("body load '" + name() + "': an empty time series");
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const LoadSample& x = samples[i];
    if (!std::isfinite(x.t) || !x.force.allFinite() || !x.moment.allFinite())
      throw std::invalid_argument("body load '" + name() + "': sample " + std::to_string(i) +
                                  " is not finite");
    if (i > 0 && x.t < samples[i - 1].t)
      throw std::invalid_argument("body load '" + name() + "': sample " + std::to_string(i) +
                                  " at t = " + std::to_string(x.t) +
                                  " s is earlier than the one before it");
  }
  samples_ = std::move(samples);
}

void BodyLoad::setTable(const std::vector<std::array<double, 7>>& rows) {
  std::vector<LoadSample> samples;
  samples.reserve(rows.size());
  for (const auto& r : rows)
    samples.push_back({r[0], Vector3(r[1], r[2], r[3]), Vector3(r[4], r[5], r[6])});
  setTimeSeries(std::move(samples));
}

void BodyLoad::set(double t, const Vector3& force, const Vector3& moment) {
  // (t, F, M) => history up to t kept (with its value just before t), then a step to (F, M)
  if (!std::isfinite(t) || !force.allFinite() || !moment.allFinite())
    throw std::invalid_argument("body load '" + name() +
                                "': an event with a non-finite time or load");
  const LoadSample before = at(t);  // stamped with time t
  samples_.erase(std::upper_bound(samples_.begin(), samples_.end(), t,
                                  [](double x, const LoadSample& s) { return x < s.t; }),
                 samples_.end());
  samples_.push_back(before);
  samples_.push_back({t, force, moment});
}

double BodyLoad::nextBreak(double t) const {
  const auto next = std::upper_bound(samples_.begin(), samples_.end(), t,
                                     [](double x, const LoadSample& s) { return x < s.t; });
  return next == samples_.end() ? std::numeric_limits<double>::infinity() : next->t;
}

LoadSample BodyLoad::at(double t, bool leftLimit) const {
  // (t) => linear between the samples around t; held outside
  if (samples_.empty()) return {t, Vector3::Zero(), Vector3::Zero()};
  const auto next = leftLimit
                        ? std::lower_bound(samples_.begin(), samples_.end(), t,
                                           [](const LoadSample& s, double x) { return s.t < x; })
                        : std::upper_bound(samples_.begin(), samples_.end(), t,
                                           [](double x, const LoadSample& s) { return x < s.t; });
  if (next == samples_.begin()) return {t, samples_.front().force, samples_.front().moment};
  if (next == samples_.end()) return {t, samples_.back().force, samples_.back().moment};
  const LoadSample& a = *(next - 1);
  const LoadSample& b = *next;
  const double w = (t - a.t) / (b.t - a.t);  // b.t > t >= a.t (left limit: b.t >= t > a.t)
  return {t, (1.0 - w) * a.force + w * b.force, (1.0 - w) * a.moment + w * b.moment};
}

void BodyLoad::worldLoad(const Stage& s, Vector3& f_W, Vector3& m_W) const {
  // (t, frame, R_WB) => F and M in the world
  const LoadSample x = at(s.t, s.t > s.stepStart);
  if (frame_ == LoadFrame::World) {
    f_W = x.force;
    m_W = x.moment;
  } else {
    const dynamics::Matrix3& R_WB = s.data.X_WB[body_].R;
    f_W = R_WB * x.force;
    m_W = R_WB * x.moment;
  }
}

void BodyLoad::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                          Eigen::VectorXd& /*tau*/) const {
  // (F_W, M_W, p_W) => spatial force about the world origin [p_W x F_W + M_W; F_W]
  Vector3 f_W, m_W;
  worldLoad(s, f_W, m_W);
  const Vector3 p_W = dynamics::pointPosition(s.data, body_, p_B_);
  dynamics::Force F;
  F.head<3>() = p_W.cross(f_W) + m_W;
  F.tail<3>() = f_W;
  f.addWorldFrame(body_, F);
}

double BodyLoad::doPower(const Stage& s) const {
  Vector3 f_W, m_W;
  worldLoad(s, f_W, m_W);
  const Vector3 omega_W = s.data.X_WB[body_].R * s.data.V_B[body_].head<3>();
  return f_W.dot(dynamics::pointVelocity(s.data, body_, p_B_)) + m_W.dot(omega_W);
}

}  // namespace yardsim::forces
