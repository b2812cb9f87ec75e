#pragma once
// A checked builder of Model: bodies may be added in any order (parents by name); build()
// rejects bad input with a ModelError whose message names the offending body or loop.

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/model.hpp"

namespace yardsim::dynamics {

class ModelError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// A rigid body's inertia from mass, centre of mass and inertia about the centre of mass.
SpatialInertia makeInertia(double mass, const Vector3& com, const Matrix3& inertiaCom);
/// A uniform rod of given mass and length along x from the body origin (to x = length).
SpatialInertia rodInertia(double mass, double length);
/// A uniform box with the centre of mass at the body origin.
SpatialInertia boxInertia(double mass, const Vector3& size);

class ModelBuilder {
 public:
  ModelBuilder& setGravity(const Vector3& g);
  /// Adds body `name` attached to `parent` ("world" for the ground) by `joint` whose frame sits at
  /// X_PJ in the parent body frame; the body frame is the joint's child frame.
  ModelBuilder& addBody(const std::string& name, const std::string& parent, const Joint& joint,
                        const Transform& X_PJ, const SpatialInertia& inertia, const std::string& geometry = {});
  /// Gives body `name` a constant added mass A_B: symmetric positive semidefinite 6x6 about the body
  /// origin in the body frame, ordered [angular; linear] (see addedMassAboutOrigin in
  /// dynamics/added_mass.hpp for a matrix in the naval order about another point). Checked by build().
  ModelBuilder& setAddedMass(const std::string& name, const Matrix6& A_B);
  /// Adds a loop-closure (cut joint) between frame F (X_AF on body A) and frame G (X_BG on body B),
  /// constraining the components in `mask` (see ConstraintAxis).
  ModelBuilder& addLoop(const std::string& name, const std::string& bodyA, const Transform& X_AF,
                        const std::string& bodyB, const Transform& X_BG, std::uint8_t mask);
  /// Checks everything and returns the model; throws ModelError.
  Model build() const;

 private:
  struct BodySpec {
    std::string name, parent;
    Joint joint;
    Transform X_PJ;
    SpatialInertia inertia;
    std::string geometry;
  };
  struct LoopSpec {
    std::string name, bodyA, bodyB;
    Transform X_AF, X_BG;
    std::uint8_t mask;
  };
  Vector3 gravity_{0.0, 0.0, -9.81};
  std::vector<BodySpec> bodies_;
  std::vector<LoopSpec> loops_;
  std::vector<std::pair<std::string, Matrix6>> addedMass_;
};

}  // namespace yardsim::dynamics
