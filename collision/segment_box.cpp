#include "collision/segment_box.hpp"

#include <algorithm>
#include <cmath>

namespace yardsim::collision {

using dynamics::Vector3;

// (p, h) => |max(q, 0)| + min(max_i q_i, 0), q = |p| - h
double boxSignedDistance(const Vector3& p_B, const Vector3& h) {
  const Vector3 q = p_B.cwiseAbs() - h;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

// (p, h) => outside: p clamped to the box; inside: p moved onto the face it is nearest to
Vector3 boxSurfacePoint(const Vector3& p_B, const Vector3& h) {
  const Vector3 clamped = p_B.cwiseMax(-h).cwiseMin(h);
  if (clamped != p_B) return clamped;
  const Vector3 gap = h - p_B.cwiseAbs();
  int axis = 0;
  gap.minCoeff(&axis);
  Vector3 out = p_B;
  out[axis] = p_B[axis] >= 0.0 ? h[axis] : -h[axis];
  return out;
}

// (p0, p1, h) => golden-section minimum of the convex f(s) = boxSignedDistance(p0 + s d)
SegmentBoxResult segmentBoxDistance(const Vector3& p0_B, const Vector3& p1_B, const Vector3& h) {
  const Vector3 d = p1_B - p0_B;
  auto f = [&](double s) { return boxSignedDistance(p0_B + s * d, h); };
  constexpr double kInvPhi = 0.6180339887498949;
  double a = 0.0, b = 1.0;
  double x1 = b - kInvPhi * (b - a), x2 = a + kInvPhi * (b - a);
  double f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 80; ++i) {
    if (f1 <= f2) {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - kInvPhi * (b - a);
      f1 = f(x1);
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + kInvPhi * (b - a);
      f2 = f(x2);
    }
  }
  // the ends are candidates too (the search brackets them only in the limit)
  double s = f1 <= f2 ? x1 : x2, best = std::min(f1, f2);
  for (double e : {0.0, 1.0}) {
    const double fe = f(e);
    if (fe < best) {
      best = fe;
      s = e;
    }
  }
  SegmentBoxResult r;
  r.distance = best;
  r.s = s;
  r.onSegment = p0_B + s * d;
  r.onBox = boxSurfacePoint(r.onSegment, h);
  return r;
}

}  // namespace yardsim::collision
