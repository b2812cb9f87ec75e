#pragma once
// A force and a moment on one body, applied at a point fixed on the body and given in the world
// or the body frame, following a piecewise-linear time series and/or step changes set by events
// at exact times (wind or wave loads applied by actors until the dedicated providers exist).
// Not conservative: power = F . v_point + M . omega.
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "forces/force_provider.hpp"

namespace yardsim::forces {

// The frame in which a load's F and M are given: fixed in the world, or turning with the body.
enum class LoadFrame { World, Body };

// One sample of a load history: time (s), force (N) and moment (N m) in the load's frame.
struct LoadSample {
  double t = 0.0;
  dynamics::Vector3 force = dynamics::Vector3::Zero();
  dynamics::Vector3 moment = dynamics::Vector3::Zero();
};

class BodyLoad final : public ForceProvider {
 public:
  // (name, model (for checks only), body index >= 1, p_B: point of application in the body
  // frame, m, frame of F and M) => a zero load; throws std::invalid_argument naming it for a
  // body outside the model, the world, or a non-finite point
  BodyLoad(std::string name, const dynamics::Model& model, int body, const dynamics::Vector3& p_B,
           LoadFrame frame);

  // (samples, times non-decreasing; two equal times make a step) => the load follows them,
  // linear in between, held at the first value before and the last after; replaces any
  // previous history. Throws std::invalid_argument if empty, unordered or not finite.
  void setTimeSeries(std::vector<LoadSample> samples);
  // (rows t, fx, fy, fz, mx, my, mz) => the same as setTimeSeries
  void setTable(const std::vector<std::array<double, 7>>& rows);
  // (t, F, M) => from exactly t on the load is (F, M), held; the history before t is kept and
  // any sample after t is dropped (so an event overrides the rest of a time series). Throws
  // std::invalid_argument when t, F or M is not finite.
  void set(double t, const dynamics::Vector3& force, const dynamics::Vector3& moment);

  // (t) => F and M in the load's frame at t: right-continuous at steps, or the value just before
  // a step with leftLimit. A stage later than its Stage::stepStart sees the left limit, so a
  // step that ends exactly on a jump integrates the value before it.
  LoadSample at(double t, bool leftLimit = false) const;
  // (t) => the first sample time after t (a kink or a jump, to be landed on), or +inf
  double nextBreak(double t) const;
  int body() const { return body_; }
  const dynamics::Vector3& point() const { return p_B_; }
  LoadFrame frame() const { return frame_; }

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  // F_W . v_W(point) + M_W . omega_W, W
  double doPower(const Stage& s) const override;

 private:
  // (stage) => F and M in the world frame at s.t
  void worldLoad(const Stage& s, dynamics::Vector3& f_W, dynamics::Vector3& m_W) const;

  int body_;
  dynamics::Vector3 p_B_;
  LoadFrame frame_;
  std::vector<LoadSample> samples_;  // empty: zero load
};

}  // namespace yardsim::forces
