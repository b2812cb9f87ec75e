#include "dynamics/aba.hpp"

#include <Eigen/LU>

#include "dynamics/checks.hpp"
#include "dynamics/flatten.hpp"
#include "dynamics/kinematics.hpp"

namespace yardsim::dynamics {

namespace {

// (symmetric positive definite D, 6 x 6) => its L D L^T factors in place: L's strict lower
// triangle (unit diagonal implied) and D's pivots on the diagonal; the upper triangle is not read
inline void ldltInPlace6(Eigen::Map<Matrix6> A) {
  for (int j = 0; j < 6; ++j) {
    double dj = A(j, j);
    for (int k = 0; k < j; ++k) dj -= A(j, k) * A(j, k) * A(k, k);
    A(j, j) = dj;
    const double inv = 1.0 / dj;
    for (int i = j + 1; i < 6; ++i) {
      double aij = A(i, j);
      for (int k = 0; k < j; ++k) aij -= A(i, k) * A(j, k) * A(k, k);
      A(i, j) = aij * inv;
    }
  }
}

// (ldltInPlace6's factors of D, b) => D^-1 b: forward, diagonal and backward substitution
inline Vector6 ldltSolve6(const Eigen::Map<const Matrix6> F, Vector6 b) {
  for (int i = 1; i < 6; ++i)
    for (int k = 0; k < i; ++k) b[i] -= F(i, k) * b[k];
  for (int i = 0; i < 6; ++i) b[i] /= F(i, i);
  for (int i = 4; i >= 0; --i)
    for (int k = i + 1; k < 6; ++k) b[i] -= F(k, i) * b[k];
  return b;
}

// (free joint at the root: IA_W[i], PA_W[i]) => U = IA S, D = S^T U factored as L D L^T in
// Dinv's buffer (the root hands nothing to a parent, so only D^-1 (u - U^T a) is needed: one
// solve instead of the inverse, a twelfth of its cost), u = tau - S^T PA
inline void abaFreeRootBackward(Data& d, int i, int iv, const Eigen::VectorXd& tau) {
  const Eigen::Map<const Matrix6> S(d.S_W.col(iv).data());
  Eigen::Map<Matrix6> U(d.U[i].data());
  Eigen::Map<Matrix6> F(d.Dinv[i].data());
  U.noalias() = d.IA_W[i] * S;
  F.noalias() = S.transpose() * U;
  ldltInPlace6(F);
  Eigen::Map<Vector6>(d.u[i].data()).noalias() = tau.segment<6>(iv) - S.transpose() * d.PA_W[i];
}

// (free joint at the root, its factors, a = A_W[0] + C_W[i]) => ddq of the joint, A_W[i]
inline void abaFreeRootForward(Data& d, int i, int iv, const Motion& a) {
  const Eigen::Map<const Matrix6> S(d.S_W.col(iv).data());
  const Eigen::Map<const Matrix6> U(d.U[i].data());
  const Eigen::Map<const Vector6> u(d.u[i].data());
  auto qdd = d.ddq.segment<6>(iv);
  qdd = ldltSolve6(Eigen::Map<const Matrix6>(d.Dinv[i].data()), u - U.transpose() * a);
  d.A_W[i] = a + S * qdd;
}

// (body i with an NV-dof joint, IA_W[i], PA_W[i], c = C_W[i]) => U = IA S, D^-1 = (S^T U)^-1,
// u = tau - S^T PA, and the articulated inertia and bias handed to the parent p (p = 0: none);
// fixed-size maps of Data's buffers, without the heap temporaries of the dynamic-size code below
// (Eigen's dynamic-size inverse takes its LU's workspace from malloc at every call): for the free
// joint (NV = 6) the same doubles, for NV = 2, 3 the same to round-off (3.6e-13 relative in ddq)
template <int NV>
inline void abaJointBackward(Data& d, int i, int p, int iv, const Eigen::VectorXd& tau) {
  const Eigen::Map<const Eigen::Matrix<double, 6, NV>> S(d.S_W.col(iv).data());
  Eigen::Map<Eigen::Matrix<double, 6, NV>> U(d.U[i].data());
  Eigen::Map<Eigen::Matrix<double, NV, NV>> Dinv(d.Dinv[i].data());
  Eigen::Map<Eigen::Matrix<double, NV, 1>> u(d.u[i].data());
  U.noalias() = d.IA_W[i] * S;
  // (as Eigen's dynamic-size inverse does; its fixed-size one would use closed forms for NV <= 4)
  Dinv = Eigen::PartialPivLU<Eigen::Matrix<double, NV, NV>>(S.transpose() * U).inverse();
  u.noalias() = tau.segment<NV>(iv) - S.transpose() * d.PA_W[i];
  if (p == 0) return;
  const Motion& c = d.C_W[i];
  const Eigen::Matrix<double, NV, 1> w = Dinv * (u - U.transpose() * c);
  d.PA_W[p] += d.PA_W[i] + d.IA_W[i] * c + U * w;
  d.IA_W[p] += d.IA_W[i];
  d.IA_W[p].noalias() -= U * Dinv * U.transpose();
}

// (body i with a 1-dof joint, IA_W[i], PA_W[i], c = C_W[i], tau_i) => U = IA s, D^-1 = 1 / s^T U,
// u = tau_i - s^T PA, and pa = PA + Ia c + U D^-1 u, Ia = IA - U D^-1 U^T added to the parent p
// (p = 0: none). The products IA s and IA c in one pass over IA's columns, in the order of Eigen's
// fixed-size products (column by column, the first a product), and IA_W[p] + IA - (D^-1 U) U^T in
// one pass over the parent's: the same doubles as the separate products and updates, without
// reading IA and the parent's twice (Data's stores may alias them, so the compiler does not)
inline void abaOneDofBackward(Data& d, int i, int p, int iv, double tau) {
  const Motion s = d.S_W.col(iv);
  const Motion& c = d.C_W[i];
  const Matrix6& IA = d.IA_W[i];
  Vector6 U = IA.col(0) * s[0];
  Vector6 IAc = IA.col(0) * c[0];
  for (int k = 1; k < 6; ++k) {
    U += IA.col(k) * s[k];
    IAc += IA.col(k) * c[k];
  }
  const double Dinv = 1.0 / s.dot(U);
  const double ui = tau - s.dot(d.PA_W[i]);
  d.U[i].col(0) = U;
  d.Dinv[i](0, 0) = Dinv;
  d.u[i][0] = ui;
  if (p == 0) return;
  d.PA_W[p] += d.PA_W[i] + IAc + U * (Dinv * (ui - U.dot(c)));
  const Vector6 DU = Dinv * U;
  Matrix6& IAp = d.IA_W[p];
  for (int k = 0; k < 6; ++k) IAp.col(k) = (IAp.col(k) + IA.col(k)) - DU * U[k];
}

// (body i with an NV-dof joint, a = A_W[parent] + C_W[i]) => ddq of the joint, A_W[i]
template <int NV>
inline void abaJointForward(Data& d, int i, int iv, const Motion& a) {
  const Eigen::Map<const Eigen::Matrix<double, 6, NV>> S(d.S_W.col(iv).data());
  const Eigen::Map<const Eigen::Matrix<double, 6, NV>> U(d.U[i].data());
  const Eigen::Map<const Eigen::Matrix<double, NV, NV>> Dinv(d.Dinv[i].data());
  const Eigen::Map<const Eigen::Matrix<double, NV, 1>> u(d.u[i].data());
  auto qdd = d.ddq.segment<NV>(iv);
  qdd.noalias() = Dinv * (u - U.transpose() * a);
  d.A_W[i] = a + S * qdd;
}

// (q, v, tau, fext; with kPlaced, d.X_PB and d.X_WB already hold q's placements) => ddq
// flatten (YARDSIM_FLATTEN): inline every Eigen helper into the three passes (GCC otherwise leaves
// 6x6 products as calls)
template <bool kPlaced>
YARDSIM_FLATTEN const Eigen::VectorXd& abaPasses(const Model& m, Data& d, const Eigen::VectorXd& q,
                                                 const Eigen::VectorXd& v,
                                                 const Eigen::VectorXd& tau,
                                                 const ExternalForces* fext) {
  // (q, v) => X_WB, S_W, V_W, C_W = V_W x S_W v_i (+ X c_J), IA = I_W, PA = V_W x* I_W V_W -
  // F_ext_W
  for (int i = 1; i < m.nbodies; ++i) {
    const int p = m.parent[i];
    if constexpr (!kPlaced) {
      placeBody(m, d, i, q);
    }
    const Transform& X = d.X_WB[i];
    const int nv = m.jointNv[i];
    const int iv = m.idxV[i];
    Motion vJ;
    if (nv == 1) {
      const Motion s = worldSubspaceColumn(m, d, i);
      d.S_W.col(iv) = s;
      vJ = s * v[iv];
    } else {
      for (int k = 0; k < nv; ++k) d.S_W.col(iv + k) = X.actMotion(d.S[i].col(k));
      vJ = d.S_W.middleCols(iv, nv) * v.segment(iv, nv);
      d.C_W[i] = m.joints[i].constantSubspace()
                     ? Motion::Zero()
                     : X.actMotion(jointBias(m.joints[i], q.data() + m.idxQ[i], v.data() + iv));
    }
    d.V_W[i] = d.V_W[p] + vJ;
    if (nv == 1) {
      d.C_W[i] = crossMotion(d.V_W[i], vJ);  // the 1-dof joints' S is constant: no c_J
    } else {
      d.C_W[i] += crossMotion(d.V_W[i], vJ);
    }
    d.IA_W[i] = m.inertiaDiagonal[i] ? m.inertias[i].matrixIn<true>(X) : m.inertias[i].matrixIn(X);
    if (d.hasAddedMass[i]) {
      // (A_B) => A_W on the left-hand side; gravity, folded into the base acceleration -g, must
      // not act on it: its share A_W (0, -g) goes back as an external force
      const Matrix6 A_W = actInertia(X, d.addedMass[i]);
      d.IA_W[i] += A_W;
      d.PA_W[i] = crossForce(d.V_W[i], d.IA_W[i] * d.V_W[i]) + A_W.rightCols<3>() * m.gravity;
    } else {
      d.PA_W[i] = crossForce(d.V_W[i], d.IA_W[i] * d.V_W[i]);
    }
    if (fext != nullptr) d.PA_W[i] -= X.actForce(fext->bodyFrame(i)) + fext->worldFrame(i);
  }
  // (IA, PA) => U = IA S, D^-1, u = tau - S^T PA; articulated inertia and bias added to the parent
  for (int i = m.nbodies - 1; i >= 1; --i) {
    const int nv = m.jointNv[i];
    const int p = m.parent[i];
    const int iv = m.idxV[i];
    const Motion& c = d.C_W[i];
    if (nv == 1) {
      abaOneDofBackward(d, i, p, iv, tau[iv]);
    } else if (nv == 6 && p == 0) {
      abaFreeRootBackward(d, i, iv, tau);
    } else if (nv == 6) {
      abaJointBackward<6>(d, i, p, iv, tau);
    } else if (nv == 3) {
      abaJointBackward<3>(d, i, p, iv, tau);
    } else if (nv == 2) {
      abaJointBackward<2>(d, i, p, iv, tau);
    } else if (nv > 0) {
      const auto S = d.S_W.middleCols(iv, nv);
      d.U[i].noalias() = d.IA_W[i] * S;
      d.Dinv[i] = (S.transpose() * d.U[i]).inverse();
      d.u[i].noalias() = tau.segment(iv, nv) - S.transpose() * d.PA_W[i];
      if (p == 0) continue;
      const Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 6, 1> w =
          d.Dinv[i] * (d.u[i] - d.U[i].transpose() * c);
      d.PA_W[p] += d.PA_W[i] + d.IA_W[i] * c + d.U[i] * w;
      d.IA_W[p] += d.IA_W[i];
      d.IA_W[p].noalias() -= d.U[i] * d.Dinv[i] * d.U[i].transpose();
    } else {
      if (p == 0) continue;
      d.PA_W[p] += d.PA_W[i] + d.IA_W[i] * c;
      d.IA_W[p] += d.IA_W[i];
    }
  }
  // (IA, PA, U, D, u) => ddq, A_W (including -g)
  d.A_W[0].head<3>().setZero();
  d.A_W[0].tail<3>() = -m.gravity;
  for (int i = 1; i < m.nbodies; ++i) {
    const int nv = m.jointNv[i];
    const int iv = m.idxV[i];
    const Motion a = d.A_W[m.parent[i]] + d.C_W[i];
    if (nv == 1) {
      const double qdd = d.Dinv[i](0, 0) * (d.u[i][0] - d.U[i].col(0).dot(a));
      d.ddq[iv] = qdd;
      d.A_W[i] = a + d.S_W.col(iv) * qdd;
    } else if (nv == 6 && m.parent[i] == 0) {
      abaFreeRootForward(d, i, iv, a);
    } else if (nv == 6) {
      abaJointForward<6>(d, i, iv, a);
    } else if (nv == 3) {
      abaJointForward<3>(d, i, iv, a);
    } else if (nv == 2) {
      abaJointForward<2>(d, i, iv, a);
    } else if (nv > 0) {
      auto qdd = d.ddq.segment(iv, nv);
      qdd.noalias() = d.Dinv[i] * (d.u[i] - d.U[i].transpose() * a);
      d.A_W[i] = a + d.S_W.middleCols(iv, nv) * qdd;
    } else {
      d.A_W[i] = a;
    }
  }
  return d.ddq;
}

}  // namespace

const Eigen::VectorXd& aba(const Model& m, Data& d, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v, const Eigen::VectorXd& tau,
                           const ExternalForces* fext) {
  YARDSIM_DYNAMICS_CHECK(m, d, q, &v, &tau, "aba");
  return abaPasses<false>(m, d, q, v, tau, fext);
}

const Eigen::VectorXd& abaAfterKinematics(const Model& m, Data& d, const Eigen::VectorXd& q,
                                          const Eigen::VectorXd& v, const Eigen::VectorXd& tau,
                                          const ExternalForces* fext) {
  YARDSIM_DYNAMICS_CHECK(m, d, q, &v, &tau, "abaAfterKinematics");
  return abaPasses<true>(m, d, q, v, tau, fext);
}

}  // namespace yardsim::dynamics
