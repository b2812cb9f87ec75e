#pragma once
// The multibody model's DTSS state (a plain value) and how it travels in a checkpoint
// (devs/checkpoint_archive.hpp): Eigen vectors as lists of their exact doubles, the set-points
// field by field. The codec is declared with the state, before any model derives from it.
#include <ostream>
#include <string>
#include <tuple>
#include <vector>

#include <Eigen/Core>

#include "devs/checkpoint_archive.hpp"
#include "devs/trace_format.hpp"
#include "mechanics/set_points.hpp"

namespace yardsim::models {

// The DTSS state, a plain value: configuration q and velocity v (joint coordinates, SI), the
// set-points in force (joint drives, actor loads, winch jobs with every rope's winch pieces), the
// work of the non-conservative forces and each rope part's peak tension.
struct MultibodyState {
  Eigen::VectorXd q, v;
  mechanics::SetPoints setPoints;
  double work = 0.0;                // J: integral of the power of non-conservative forces
  std::vector<double> peakTension;  // N per rope part: the largest tension at any step so far
  std::vector<double> peakTime;     // s: when each rope's peak was reached
};
// (state) => "q=[q0,q1,...]" appended to out, each coordinate (rad or m) as printf's "%g" prints
// it (six significant digits); operator<< prints the same text whatever the stream's precision
void appendStateText(std::string& out, const MultibodyState& s);
std::ostream& operator<<(std::ostream& os, const MultibodyState& s);

}  // namespace yardsim::models

namespace yardsim::devs {

// The multibody state in a trace: the JSON string of its text (appendStateText), written straight
// into the record without a string stream (the trace writes one at every step)
template <>
struct TraceFormat<models::MultibodyState> {
  static void write(std::string& out, const models::MultibodyState& s);
};

// A dense column vector (dynamic or fixed size): its length, then its coefficients.
template <class Scalar, int Rows>
struct StateCodec<Eigen::Matrix<Scalar, Rows, 1>> {
  using V = Eigen::Matrix<Scalar, Rows, 1>;
  static void save(CheckpointWriter& w, const V& v) {
    w.list(static_cast<std::size_t>(v.size()));
    for (Eigen::Index i = 0; i < v.size(); ++i) w.f64(static_cast<double>(v[i]));
  }
  static void load(CheckpointReader& r, V& v) {
    const auto n = static_cast<Eigen::Index>(r.list());
    if constexpr (Rows == Eigen::Dynamic)
      v.resize(n);
    else if (n != Rows)
      throw CheckpointError("a vector of " + std::to_string(n) + " values where " +
                            std::to_string(Rows) + " were expected");
    for (Eigen::Index i = 0; i < n; ++i) v[i] = static_cast<Scalar>(r.f64());
  }
};

template <>
struct StateCodec<mechanics::JointDrive> : FieldCodec<mechanics::JointDrive> {
  static auto fields(auto& s) {
    return std::tie(s.active, s.reported, s.start, s.target, s.speed, s.t0, s.actor, s.prescribed);
  }
};
template <>
struct StateCodec<forces::Winch::SetPoint> : FieldCodec<forces::Winch::SetPoint> {
  static auto fields(auto& s) { return std::tie(s.t, s.l0, s.rate, s.accel, s.jerk); }
};
template <>
struct StateCodec<mechanics::WinchJob> : FieldCodec<mechanics::WinchJob> {
  static auto fields(auto& s) { return std::tie(s.active, s.tEnd, s.actor, s.pieces); }
};
template <>
struct StateCodec<mechanics::ActorLoad> : FieldCodec<mechanics::ActorLoad> {
  static auto fields(auto& s) { return std::tie(s.force, s.moment); }
};
template <>
struct StateCodec<mechanics::SetPoints> : FieldCodec<mechanics::SetPoints> {
  static auto fields(auto& s) { return std::tie(s.drives, s.loads, s.winches); }
};
template <>
struct StateCodec<models::MultibodyState> : FieldCodec<models::MultibodyState> {
  static auto fields(auto& s) {
    return std::tie(s.q, s.v, s.setPoints, s.work, s.peakTension, s.peakTime);
  }
};

}  // namespace yardsim::devs
