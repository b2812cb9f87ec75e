#pragma once
// The path of a rope through points fixed on bodies: its first end, frictionless sheaves, its
// last end. Length is the sum of the segment lengths; a uniform tension T pulls each point
// along the rope: an end by T u toward its neighbour, a sheave by T (u_prev + u_next) (unit
// vectors from the point toward the previous and the next point). Shared by the wire rope and
// the equalizer. The path itself is immutable; update() writes the world-frame points into a
// PathPoints the caller sized with points() once: update() and applyTension() do not allocate.
#include <string>
#include <vector>

#include "dynamics/data.hpp"
#include "dynamics/external_forces.hpp"
#include "dynamics/model.hpp"

namespace yardsim::forces {

// A point fixed on a body: body index (0 = the world / ground) and p_B, the point in the body
// frame, m.
struct Attachment {
  int body = 0;
  dynamics::Vector3 p_B = dynamics::Vector3::Zero();
};

// Length of a path (m) and its rate of change (m/s).
struct PathMeasure {
  double length = 0.0;
  double rate = 0.0;
};

// A path's points and segment directions in the world frame at one stage (a scratch).
struct PathPoints {
  std::vector<dynamics::Vector3> p_W;  // one per point, m
  std::vector<dynamics::Vector3>
      u_W;  // one per segment: point i toward i + 1 (zero if zero length)
};

class RopePath {
 public:
  // (model, points: first end, sheaves..., last end, owner name for messages) => a path; throws
  // std::invalid_argument for fewer than 2 points, a body index outside the model or a
  // non-finite point. The model is used for these checks only.
  RopePath(const dynamics::Model& model, std::vector<Attachment> points, const std::string& owner);

  // (data after forwardKinematics(q, v)) => length and dL/dt; touches no buffer
  PathMeasure measure(const dynamics::Data& data) const;
  // () => a PathPoints sized for this path
  PathPoints makePoints() const;
  // (data after forwardKinematics(q, v)) => the same, and p_W, u_W written into out
  PathMeasure update(const dynamics::Data& data, PathPoints& out) const;
  // (T, points from update()) => T u on the ends and T (u_prev + u_next) on the sheaves, added
  // to f as world-frame point forces (the world, body 0, is skipped)
  void applyTension(double tension, const PathPoints& at, dynamics::ExternalForces& f) const;

  const std::vector<Attachment>& points() const { return points_; }
  int size() const { return static_cast<int>(points_.size()); }

 private:
  // (data, visit(i, p_W of point i, u_W of segment i - 1 or none)) => length and rate: the one
  // walk along the path that measure() and update() share
  template <class Visit>
  PathMeasure walk(const dynamics::Data& data, Visit&& visit) const;

  std::vector<Attachment> points_;
};

}  // namespace yardsim::forces
