#pragma once
// The immutable description of a multibody system: a tree of bodies, each attached to its
// parent by a joint with its placement, gravity, and loop-closure constraints. Made by
// ModelBuilder (model_builder.hpp), which checks it. Body 0 is the world; parent[i] < i.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/joint.hpp"
#include "dynamics/spatial.hpp"

namespace yardsim::dynamics {

/// Components of a loop constraint, in the constraint frame F on body A; rows are stacked in the
/// order rot x, rot y, rot z, trans x, trans y, trans z (those present).
enum ConstraintAxis : std::uint8_t {
  kRotX = 1,
  kRotY = 2,
  kRotZ = 4,
  kTransX = 8,
  kTransY = 16,
  kTransZ = 32,
};
/// The origins of F and G coincide (a ball-joint cut).
inline constexpr std::uint8_t kPointConstraint = kTransX | kTransY | kTransZ;
/// Origins coincide and the z axes are aligned (a revolute cut about z).
inline constexpr std::uint8_t kAxisConstraint = kPointConstraint | kRotX | kRotY;
/// Origin of G on F's z axis and z axes aligned (a cylindrical cut along z).
inline constexpr std::uint8_t kCylinderConstraint = kTransX | kTransY | kRotX | kRotY;
/// F and G coincide (a weld cut).
inline constexpr std::uint8_t kWeldConstraint = 63;
/// Origins coincide in F's x-y plane (a revolute cut of a mechanism that moves in that plane).
inline constexpr std::uint8_t kPlanarPointConstraint = kTransX | kTransY;

/// A cut joint closing a loop: frame F fixed on body A, frame G fixed on body B.
struct LoopConstraint {
  std::string name;
  int bodyA = 0;
  int bodyB = 0;
  Transform X_AF;  ///< pose of F in A
  Transform X_BG;  ///< pose of G in B
  std::uint8_t mask = kPointConstraint;
  int dim = 0;  ///< number of rows (bits set in mask)
  int row = 0;  ///< first row in the stacked constraint vector
};

struct Model {
  int nbodies = 1;  ///< including the world (index 0)
  int nq = 0;
  int nv = 0;
  int nc = 0;  ///< total loop-constraint rows
  Vector3 gravity{0.0, 0.0, -9.81};

  std::vector<std::string> names;     ///< names[0] = "world"
  std::vector<int> parent;            ///< parent[0] = -1
  std::vector<Joint> joints;          ///< joints[0] unused
  std::vector<Transform> X_PJ;        ///< pose of the joint frame in the parent body frame
  std::vector<SpatialInertia> inertias;
  std::vector<Matrix6> inertiaMatrices;  ///< 6x6 body inertia about the body origin, body frame
  /// Constant added mass of a body in a fluid: a symmetric positive semidefinite 6x6 about the body
  /// origin in the body frame, ordered [angular; linear] like every spatial matrix here (zero for
  /// a body without one). It adds to the body inertia on the left-hand side (ABA, CRBA, RNEA,
  /// kinetic energy, momentum) but not to its weight: gravity acts on the rigid mass only.
  std::vector<Matrix6> addedMass;
  std::vector<char> hasAddedMass;  ///< addedMass[i] is not zero (char: cheaper to read than bool)
  std::vector<std::string> geometry;  ///< optional geometry reference per body
  std::vector<int> idxQ;              ///< first configuration index of body i's joint
  std::vector<int> idxV;              ///< first velocity index of body i's joint
  std::vector<int> jointNq;
  std::vector<int> jointNv;
  std::vector<int> dofBody;           ///< body owning each velocity index
  std::vector<int> nvSubtree;         ///< velocity count of the subtree rooted at body i (contiguous from idxV[i])
  /// The dof tree, per velocity index k: lambda(k), the previous dof of the same joint or else the
  /// last dof of the nearest ancestor body that has one (-1 at a root); the mass matrix's entry
  /// (k, j) can be non-zero only when j is k, an ancestor or a descendant of k.
  std::vector<int> dofParent;
  /// The dofs in the subtree of dof k, itself included (contiguous from k).
  std::vector<int> dofSubtree;
  std::vector<char> placementRotated;  ///< false when X_PJ[i] is a pure translation
  /// 0, 1, 2 when body i's joint is revolute or prismatic about the joint frame's x, y or z axis
  /// (components exactly +0 and 1), else -1: the kernels special-case these joints
  std::vector<signed char> jointAxis;
  /// inertias[i].inertiaCom is diagonal (the kernels then scale instead of multiplying by it)
  std::vector<char> inertiaDiagonal;
  bool euclidean = true;              ///< no spherical or free joint: nq = nv and dq/dt = v
  std::vector<LoopConstraint> loops;

  /// Index of a body by name, or -1.
  int bodyIndex(std::string_view name) const;
  /// Total mass of all bodies.
  double totalMass() const;
};

}  // namespace yardsim::dynamics
