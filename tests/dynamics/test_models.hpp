#pragma once
// Models shared by the dynamics tests: random trees with every joint type, planar chains, and
// small helpers. Header-only.

#include <Eigen/Core>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "dynamics/model_builder.hpp"
#include "dynamics/rotation.hpp"

namespace yardsim::dynamics::testing {

// Sizes are reduced under sanitizers, which run an order of magnitude slower.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr int kScale = 4;
#else
inline constexpr int kScale = 1;
#endif

/// prefix followed by i (string literal + std::to_string trips GCC 12's -Wrestrict false positive at -O3).
inline std::string indexed(const char* prefix, int i) {
  std::string s(prefix);
  s.append(std::to_string(i));
  return s;
}

inline Matrix3 randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  q.normalize();
  return q.toRotationMatrix();
}

inline Vector3 randomVector(std::mt19937& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

inline Eigen::VectorXd randomVectorX(std::mt19937& rng, int n, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = u(rng);
  return x;
}

inline SpatialInertia randomInertia(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(1.0, 2.0);
  const Matrix3 R = randomRotation(rng);
  const Matrix3 I = R * Vector3(u(rng), u(rng), u(rng)).asDiagonal() * R.transpose();
  return makeInertia(u(rng), randomVector(rng, 0.5), 0.5 * (I + I.transpose()));
}

inline Joint jointOfType(JointType t, std::mt19937& rng) {
  switch (t) {
    case JointType::Fixed: return Joint::fixed();
    case JointType::Revolute: return Joint::revolute(randomVector(rng).normalized());
    case JointType::Prismatic: return Joint::prismatic(randomVector(rng).normalized());
    case JointType::Cylindrical: return Joint::cylindrical(randomVector(rng).normalized());
    case JointType::Universal: {
      const Matrix3 R = randomRotation(rng);
      return Joint::universal(R.col(0), R.col(1));
    }
    case JointType::Spherical: return Joint::spherical();
    case JointType::Planar: return Joint::planar();
    case JointType::Free: return Joint::free();
    case JointType::Translation: return Joint::translation();
  }
  return Joint::fixed();
}

inline const std::vector<JointType>& allJointTypes() {
  static const std::vector<JointType> types{JointType::Revolute,  JointType::Prismatic, JointType::Cylindrical,
                                            JointType::Universal, JointType::Spherical, JointType::Planar,
                                            JointType::Free,      JointType::Fixed,     JointType::Translation};
  return types;
}

/// A random symmetric positive definite 6x6 of the size of randomInertia's (an added mass: not a
/// rigid-body inertia, every block full).
inline Matrix6 randomAddedMass(std::mt19937& rng) {
  Matrix6 B;
  for (int k = 0; k < 6; ++k) B.col(k) = randomVectorX(rng, 6);
  return B * B.transpose() + 0.1 * Matrix6::Identity();
}

/// A random tree of n bodies whose joints cycle through every joint type (the first is free);
/// with addedMass, every other body (the first included) also carries a random added mass.
inline Model randomTree(std::mt19937& rng, int n, Vector3 gravity = {0.0, 0.0, -9.81}, bool addedMass = false) {
  ModelBuilder b;
  b.setGravity(gravity);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto& types = allJointTypes();
  for (int i = 0; i < n; ++i) {
    const std::string parent = i == 0 ? "world" : indexed("b", static_cast<int>(u(rng) * i));
    const JointType t = i == 0 ? JointType::Free : types[static_cast<std::size_t>(i - 1) % types.size()];
    b.addBody(indexed("b", i), parent, jointOfType(t, rng), Transform{randomRotation(rng), randomVector(rng)},
              randomInertia(rng));
    if (addedMass && i % 2 == 0) b.setAddedMass(indexed("b", i), randomAddedMass(rng));
  }
  return b.build();
}

/// A random tree of n bodies on a free root whose other joints are revolute and prismatic about
/// the x, y or z axis of a translated joint frame (Model::jointAxis >= 0: the kernels' special
/// case; randomTree's random axes and rotated frames take the general path), every fourth about
/// the negative axis (the general path); with addedMass,
/// every other body carries a random added mass; with diagonalInertia, every body's inertia about
/// its centre of mass is diagonal with distinct entries (Model::inertiaDiagonal: the kernels'
/// other special case).
inline Model randomAxisTree(std::mt19937& rng, int n, bool addedMass = false, bool diagonalInertia = false) {
  ModelBuilder b;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    const std::string parent = i == 0 ? "world" : indexed("b", static_cast<int>(u(rng) * i));
    // every fourth axis negative ((-0, -1, -0): the general path, beside the special case)
    const Vector3 axis =
        i % 4 == 3 ? Vector3(-Vector3::Unit(i % 3)) : Vector3(Vector3::Unit(i % 3));
    const Joint j =
        i == 0 ? Joint::free() : (i % 2 ? Joint::revolute(axis) : Joint::prismatic(axis));
    const SpatialInertia inertia =
        diagonalInertia ? makeInertia(1.0 + u(rng), randomVector(rng, 0.5),
                                      Vector3(2.0 + u(rng), 2.5 + u(rng), 3.0 + u(rng)).asDiagonal())
                        : randomInertia(rng);
    b.addBody(indexed("b", i), parent, j, Transform::translation(randomVector(rng)), inertia);
    if (addedMass && i % 2 == 0) b.setAddedMass(indexed("b", i), randomAddedMass(rng));
  }
  return b.build();
}

/// A chain of n revolute links (1 kg, 1 m rods along x) turning about y, gravity along -z.
inline Model planarChain(int n) {
  ModelBuilder b;
  for (int i = 0; i < n; ++i) {
    b.addBody(indexed("link", i), i == 0 ? "world" : indexed("link", i - 1),
              Joint::revolute(Vector3::UnitY()), Transform::translation(Vector3(i == 0 ? 0.0 : 1.0, 0.0, 0.0)),
              rodInertia(1.0, 1.0));
  }
  return b.build();
}

/// max |a - b| / max(1, max |b|)
inline double relativeError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

}  // namespace yardsim::dynamics::testing
