#pragma once
// Bending stiffness of a lumped-mass line (lumped_line.hpp): a discrete elastic rod whose energy
// sits at the inner nodes. At inner node i (1 .. N - 1) the two adjacent segments' directions
// a = (r_i - r_(i-1)) / |.| and b = (r_(i+1) - r_i) / |.| turn by the angle theta_i, cos theta_i =
// a . b, and the node stores
//   E_i = (EI / l) (1 - cos theta_i)                                              (J)
// with l the unstretched segment length (m) and EI the bending stiffness (N m^2). For small angles
// the curvature is kappa = theta / l and E_i = EI theta^2 / (2 l) = (EI kappa^2 / 2) l: the
// continuous rod's energy per length over the node's length. The bending moment at the node is
// dE_i/dtheta = (EI / l) sin theta_i (-> EI kappa). The node forces are the exact negative
// gradient of E = sum_i E_i (so the energy balance closes), f = (EI / l) d(a . b)/dr:
//   f_(i-1) -= k g_a,  f_i += k (g_a - g_b),  f_(i+1) += k g_b,
//   g_a = (I - a a^T) b / |d_a|,  g_b = (I - b b^T) a / |d_b|,  k = EI / l,
// so node i's force depends on nodes i - 2 .. i + 2 (a 5-node stencil). The ends are pinned: no
// energy at nodes 0 and N, no moment there. A segment of zero length stores none. World frame, SI
// units. Allocation-free.
#include <Eigen/Core>

#include "dynamics/spatial.hpp"

namespace yardsim::forces {

// (r: 3 x nodes, world, m; k = EI / l, N m) => the bending energy sum_inner k (1 - a . b), J
double bendingEnergy(const Eigen::Matrix3Xd& r, double k);

// (r, k) => f += -dE/dr, N (f sized like r)
void addBendingForces(const Eigen::Matrix3Xd& r, double k, Eigen::Matrix3Xd& f);

// (r, k, add(i, j, K)) => for every inner node's energy, its contributions K = df_i/dr_j (N/m)
// to the force Jacobian, i and j within one node of it (so |i - j| <= 2): f = k grad(a . b), the
// Hessian of a . b in d_a = r_i - r_(i-1) and d_b = r_(i+1) - r_i is
//   H_aa = -[(a.b) P_a + a g_a^T |d_a| + g_a a^T |d_a|] / |d_a|^2,  H_ab = P_a P_b / (|d_a| |d_b|),
//   H_bb = -[(a.b) P_b + b g_b^T |d_b| + g_b b^T |d_b|] / |d_b|^2,  H_ba = H_ab^T,
// P_x = I - x x^T, mapped to the nodes by d_a = r_i - r_(i-1), d_b = r_(i+1) - r_i
template <class Add>
void bendingJacobian(const Eigen::Matrix3Xd& r, double k, Add&& add) {
  using dynamics::Matrix3;
  using dynamics::Vector3;
  const Eigen::Index n = r.cols() - 1;
  for (Eigen::Index i = 1; i < n; ++i) {
    const Vector3 da = r.col(i) - r.col(i - 1), db = r.col(i + 1) - r.col(i);
    const double la = da.norm(), lb = db.norm();
    if (!(la > 0.0) || !(lb > 0.0)) continue;
    const Vector3 a = da / la, b = db / lb;
    const double c = a.dot(b);
    const Matrix3 Pa = Matrix3::Identity() - a * a.transpose();
    const Matrix3 Pb = Matrix3::Identity() - b * b.transpose();
    const Vector3 ga = Pa * b, gb = Pb * a;  // |d_a| g_a and |d_b| g_b
    Matrix3 H[2][2];
    H[0][0] = -(c * Pa + a * ga.transpose() + ga * a.transpose()) / (la * la);
    H[1][1] = -(c * Pb + b * gb.transpose() + gb * b.transpose()) / (lb * lb);
    H[0][1] = Pa * Pb / (la * lb);
    H[1][0] = H[0][1].transpose();
    // (segment x in {a, b}) => its nodes and signs: d_a = r_i - r_(i-1), d_b = r_(i+1) - r_i
    const int node[2][2] = {{static_cast<int>(i - 1), static_cast<int>(i)},
                            {static_cast<int>(i), static_cast<int>(i + 1)}};
    const double sign[2] = {-1.0, 1.0};
    for (int x = 0; x < 2; ++x)
      for (int y = 0; y < 2; ++y)
        for (int s = 0; s < 2; ++s)
          for (int t = 0; t < 2; ++t)
            add(node[x][s], node[y][t], Matrix3(k * sign[s] * sign[t] * H[x][y]));
  }
}

}  // namespace yardsim::forces
