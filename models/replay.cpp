#include "models/replay.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace yardsim::models {

using mechanics::MechanicsSpec;

ReplayBody replayShape(const MechanicsSpec::Visual& visual, double mass,
                       const dynamics::Vector3& com, const dynamics::Matrix3& inertia) {
  using Shape = MechanicsSpec::Visual::Shape;
  ReplayBody b;
  b.X_BG = visual.posed ? visual.X_BG : dynamics::Transform::translation(com);
  if (visual.shape == Shape::Mesh && visual.mesh) {  // in the body frame unless posed
    b.shape = Shape::Mesh;
    b.mesh = visual.mesh;
    b.X_BG = visual.posed ? visual.X_BG : dynamics::Transform::identity();
    return b;
  }
  if (visual.shape != Shape::Auto && visual.shape != Shape::Mesh) {
    b.shape = visual.shape;
    b.size = visual.size;
    return b;
  }
  // (mass, inertia about the centre of mass) => the uniform box with the same principal moments:
  // I1 = m (l2^2 + l3^2) / 12, ... so l1^2 = 6 (I2 + I3 - I1) / m, along the principal axes
  b.shape = Shape::Box;
  const Eigen::SelfAdjointEigenSolver<dynamics::Matrix3> eig(inertia);
  const dynamics::Vector3 I = eig.eigenvalues();
  dynamics::Matrix3 axes = eig.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) *= -1.0;
  for (int k = 0; k < 3; ++k) {
    const double sq = mass > 0 ? 6.0 * (I.sum() - 2.0 * I[k]) / mass : 0.0;
    b.size[k] = sq > 0 ? std::sqrt(sq) : 0.0;
  }
  const double largest = b.size.maxCoeff();
  if (!(largest > 0)) b.size.setConstant(0.1);
  else b.size = b.size.cwiseMax(0.02 * largest);
  if (!visual.posed) b.X_BG.R = axes;
  return b;
}

}  // namespace yardsim::models
