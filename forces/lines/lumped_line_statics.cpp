#include "forces/lines/lumped_line_statics.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/SparseCore>

#include "dynamics/integrators/bordered_band_lu.hpp"
#include "forces/lines/lumped_line_bending.hpp"

namespace yardsim::forces {

using dynamics::Matrix3;
using dynamics::Vector3;

namespace {

constexpr double kStart = -std::numeric_limits<double>::infinity();  // t: the start's length

// (line, r) => the conservative forces on the inner nodes at the start's segment length (a
// winch's before its first set-point), stacked (3 (N - 1))
Eigen::VectorXd residual(const LumpedLine& line, const Eigen::Matrix3Xd& r, Eigen::Matrix3Xd& f) {
  line.conservativeForces(r, kStart, f);
  const int inner = line.nodes() - 2;
  Eigen::VectorXd out(3 * inner);
  for (int i = 0; i < inner; ++i) out.segment<3>(3 * i) = f.col(i + 1);
  return out;
}

// (line, r) => K = -d(residual)/d(inner positions): the segments' tangent stiffness, the
// bending's and the bed's; a band matrix (3x3 blocks within one node, two with bending)
Eigen::SparseMatrix<double> stiffness(const LumpedLine& line, const Eigen::Matrix3Xd& r) {
  const LumpedLineProperties& p = line.properties();
  const int n = p.segments, inner = n - 1;
  const double l = line.segmentLength();
  std::vector<Eigen::Triplet<double>> t;
  auto add = [&t](int bi, int bj, const Matrix3& k) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) t.emplace_back(3 * bi + a, 3 * bj + b, k(a, b));
  };
  // (every node) => its diagonal block present, so that the regularisation below reaches it
  for (int i = 0; i < inner; ++i) add(i, i, Matrix3::Zero());
  for (int s = 0; s < n; ++s) {
    // (taut segment from node s to s + 1) => EA/l u u^T + T/|d| (I - u u^T)
    // (a slack segment) => 1e-3 of the axial stiffness along it: Newton's matrix stays regular
    // while a guess has slack segments on the bed, and the step still pulls them taut
    const Vector3 d = r.col(s + 1) - r.col(s);
    const double len = d.norm(), strain = len / l - 1.0;
    if (!(len > 0.0)) continue;
    const Vector3 u = d / len;
    const Matrix3 uu = u * u.transpose();
    const Matrix3 k =
        strain > 0.0 ? Matrix3(p.ea / l * uu + p.ea * strain / len * (Matrix3::Identity() - uu))
                     : Matrix3(1e-3 * p.ea / l * uu);
    const int a = s - 1, b = s;  // inner indices of nodes s and s + 1 (-1 or inner: held)
    if (a >= 0) add(a, a, k);
    if (b < inner) add(b, b, k);
    if (a >= 0 && b < inner) {
      add(a, b, -k);
      add(b, a, -k);
    }
  }
  // (EI > 0) => minus the bending forces' Jacobian among the inner nodes
  if (p.ei > 0.0)
    bendingJacobian(r, p.ei / l, [&](int i, int j, const Matrix3& k) {
      if (i >= 1 && i <= inner && j >= 1 && j <= inner) add(i - 1, j - 1, -k);
    });
  if (p.seabed)
    for (int i = 0; i < inner; ++i)
      if (r(2, i + 1) < p.seabedZ)
        t.emplace_back(3 * i + 2, 3 * i + 2, p.bedStiffness * p.diameter * line.nodeLength(i + 1));
  Eigen::SparseMatrix<double> K(3 * inner, 3 * inner);
  K.setFromTriplets(t.begin(), t.end());
  K.makeCompressed();
  return K;
}

}  // namespace

bool lumpedLineStatics(const LumpedLine& line, Eigen::Matrix3Xd& r) {
  const LumpedLineProperties& p = line.properties();
  const int inner = line.nodes() - 2;
  if (inner <= 0) return true;
  const double tol = 1e-9 * std::abs(line.weightPerLength()) * p.length;
  Eigen::Matrix3Xd f(3, line.nodes()), trial(3, line.nodes());
  Eigen::VectorXd res = residual(line, r, f);
  double energy = line.potentialEnergy(r, kStart);
  for (int it = 0; it < 500; ++it) {
    if (res.lpNorm<Eigen::Infinity>() <= tol) return true;
    // (K dx = residual) => a step that lowers the residual or the energy (Armijo), halved up to
    // 30 times: the residual alone stalls where a node rests on the bed's kink under a stiff
    // line's bending; (K, a band matrix) => factorised in O(nodes)
    // (dynamics/integrators/bordered_band_lu.hpp)
    Eigen::SparseMatrix<double> K = stiffness(line, r);
    const double shift = 1e-9 * K.diagonal().cwiseAbs().maxCoeff() + 1e-12;
    for (int i = 0; i < K.rows(); ++i) K.coeffRef(i, i) += shift;
    dynamics::BorderedBandLu lu;
    if (!lu.analyse(K) || !lu.factorise(K)) return false;
    Eigen::VectorXd dx;
    lu.solve(res, dx);
    if (!dx.allFinite()) return false;
    double scale = 1.0;
    const double before = res.norm(), slope = res.dot(dx);  // slope: -dV/ds along dx at s = 0
    bool accepted = false;
    for (int k = 0; k < 30 && !accepted; ++k, scale *= 0.5) {
      trial = r;
      for (int i = 0; i < inner; ++i) trial.col(i + 1) += scale * dx.segment<3>(3 * i);
      const Eigen::VectorXd next = residual(line, trial, f);
      const double e = line.potentialEnergy(trial, kStart);
      accepted = next.norm() < before || (slope > 0.0 && e <= energy - 1e-4 * scale * slope);
      if (accepted) {
        r = trial;
        res = next;
        energy = e;
      }
    }
    if (!accepted) return false;
  }
  return res.lpNorm<Eigen::Infinity>() <= tol;
}

}  // namespace yardsim::forces
