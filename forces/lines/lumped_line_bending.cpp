#include "forces/lines/lumped_line_bending.hpp"

namespace yardsim::forces {

using dynamics::Vector3;

double bendingEnergy(const Eigen::Matrix3Xd& r, double k) {
  // (inner node) => k (1 - a . b)
  double e = 0.0;
  for (Eigen::Index i = 1; i + 1 < r.cols(); ++i) {
    const Vector3 da = r.col(i) - r.col(i - 1), db = r.col(i + 1) - r.col(i);
    const double la = da.norm(), lb = db.norm();
    if (la > 0.0 && lb > 0.0) e += k * (1.0 - da.dot(db) / (la * lb));
  }
  return e;
}

void addBendingForces(const Eigen::Matrix3Xd& r, double k, Eigen::Matrix3Xd& f) {
  // (inner node) => k g_a on i - 1 (negated), k (g_a - g_b) on i, k g_b on i + 1
  for (Eigen::Index i = 1; i + 1 < r.cols(); ++i) {
    const Vector3 da = r.col(i) - r.col(i - 1), db = r.col(i + 1) - r.col(i);
    const double la = da.norm(), lb = db.norm();
    if (!(la > 0.0) || !(lb > 0.0)) continue;
    const Vector3 a = da / la, b = db / lb;
    const double c = a.dot(b);
    const Vector3 ga = (k / la) * (b - c * a), gb = (k / lb) * (a - c * b);
    f.col(i - 1) -= ga;
    f.col(i) += ga - gb;
    f.col(i + 1) += gb;
  }
}

}  // namespace yardsim::forces
