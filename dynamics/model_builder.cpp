#include "dynamics/model_builder.hpp"

#include <Eigen/Eigenvalues>
#include <bit>
#include <cmath>
#include <map>
#include <sstream>

namespace yardsim::dynamics {

namespace {

constexpr double kTol = 1e-9;

[[noreturn]] void fail(const std::string& what) { throw ModelError("yardsim::dynamics model: " + what); }

bool finite(const Transform& X) { return X.R.allFinite() && X.p.allFinite(); }

bool orthonormal(const Matrix3& R) {
  return (R.transpose() * R - Matrix3::Identity()).cwiseAbs().maxCoeff() < 1e-9 && R.determinant() > 0.0;
}

void checkInertia(const std::string& body, const SpatialInertia& I) {
  const std::string who = "body '" + body + "': ";
  if (!std::isfinite(I.mass) || !I.com.allFinite() || !I.inertiaCom.allFinite()) fail(who + "inertia has a non-finite entry");
  if (!(I.mass > 0.0)) {
    std::ostringstream s;
    s << who << "mass must be positive, got " << I.mass << " kg";
    fail(s.str());
  }
  const Matrix3& J = I.inertiaCom;
  const double scale = J.cwiseAbs().maxCoeff();
  if ((J - J.transpose()).cwiseAbs().maxCoeff() > kTol * std::max(scale, 1e-300)) fail(who + "inertia about the centre of mass is not symmetric");
  const Eigen::SelfAdjointEigenSolver<Matrix3> eig(J, Eigen::EigenvaluesOnly);
  const Vector3 l = eig.eigenvalues();  // ascending
  if (!(l[0] > 0.0)) {
    std::ostringstream s;
    s << who << "inertia about the centre of mass is not positive definite (principal moments " << l.transpose() << ")";
    fail(s.str());
  }
  if (l[0] + l[1] < l[2] * (1.0 - kTol)) {
    std::ostringstream s;
    s << who << "principal moments " << l.transpose() << " violate the triangle inequality (I1 + I2 >= I3)";
    fail(s.str());
  }
}

void checkAddedMass(const std::string& body, const Matrix6& A) {
  const std::string who = "body '" + body + "': added mass ";
  if (!A.allFinite()) fail(who + "has a non-finite entry");
  const double scale = A.cwiseAbs().maxCoeff();
  if ((A - A.transpose()).cwiseAbs().maxCoeff() > 1e-6 * scale) fail(who + "is not symmetric");
  const Eigen::SelfAdjointEigenSolver<Matrix6> eig(0.5 * (A + A.transpose()), Eigen::EigenvaluesOnly);
  if (eig.eigenvalues()[0] < -1e-9 * scale) {
    std::ostringstream s;
    s << who << "is not positive semidefinite (eigenvalues " << eig.eigenvalues().transpose()
      << "); a fluid's kinetic energy cannot be negative";
    fail(s.str());
  }
}

void checkJoint(const std::string& body, Joint& j) {
  const std::string who = "body '" + body + "': ";
  auto unit = [&](Vector3& a, const char* which) {
    const double n = a.norm();
    if (!std::isfinite(n) || n < 1e-12) fail(who + std::string(jointTypeName(j.type)) + " joint " + which + " is zero or not finite");
    a /= n;
  };
  switch (j.type) {
    case JointType::Revolute:
    case JointType::Prismatic:
    case JointType::Cylindrical: unit(j.axis, "axis"); break;
    case JointType::Universal:
      unit(j.axis, "axis1");
      unit(j.axis2, "axis2");
      if (std::abs(j.axis.dot(j.axis2)) > 1e-9) fail(who + "universal joint axes are not orthogonal");
      break;
    default: break;
  }
}

// (joint) => 0, 1, 2 for a revolute or prismatic joint about the unit x, y or z axis (components
// exactly +0 and 1, as the kernels' special case needs), else -1
signed char coordinateAxis(const Joint& j) {
  if (j.type != JointType::Revolute && j.type != JointType::Prismatic) return -1;
  for (int k = 0; k < 3; ++k) {
    const Vector3 e = Vector3::Unit(k);
    bool same = true;
    for (int c = 0; c < 3; ++c) same = same && j.axis[c] == e[c] && !std::signbit(j.axis[c]);
    if (same) return static_cast<signed char>(k);
  }
  return -1;
}

}  // namespace

SpatialInertia makeInertia(double mass, const Vector3& com, const Matrix3& inertiaCom) { return {mass, com, inertiaCom}; }

SpatialInertia rodInertia(double mass, double length) {
  const double t = mass * length * length / 12.0;
  return {mass, Vector3(0.5 * length, 0.0, 0.0), Vector3(1e-6 * t, t, t).asDiagonal()};
}

SpatialInertia boxInertia(double mass, const Vector3& s) {
  const double k = mass / 12.0;
  return {mass, Vector3::Zero(),
          Vector3(k * (s.y() * s.y() + s.z() * s.z()), k * (s.x() * s.x() + s.z() * s.z()), k * (s.x() * s.x() + s.y() * s.y()))
              .asDiagonal()};
}

ModelBuilder& ModelBuilder::setGravity(const Vector3& g) {
  gravity_ = g;
  return *this;
}

ModelBuilder& ModelBuilder::addBody(const std::string& name, const std::string& parent, const Joint& joint,
                                    const Transform& X_PJ, const SpatialInertia& inertia, const std::string& geometry) {
  bodies_.push_back({name, parent, joint, X_PJ, inertia, geometry});
  return *this;
}

ModelBuilder& ModelBuilder::addLoop(const std::string& name, const std::string& bodyA, const Transform& X_AF,
                                    const std::string& bodyB, const Transform& X_BG, std::uint8_t mask) {
  loops_.push_back({name, bodyA, bodyB, X_AF, X_BG, mask});
  return *this;
}

ModelBuilder& ModelBuilder::setAddedMass(const std::string& name, const Matrix6& A_B) {
  addedMass_.emplace_back(name, A_B);
  return *this;
}

Model ModelBuilder::build() const {
  if (!gravity_.allFinite()) fail("gravity is not finite");
  // (specs) => (name -> spec index), duplicates and names refused
  std::map<std::string, int> byName;
  for (int k = 0; k < static_cast<int>(bodies_.size()); ++k) {
    const auto& b = bodies_[k];
    if (b.name.empty()) fail("a body has an empty name");
    if (b.name == "world") fail("body 'world' is reserved for the ground");
    if (!byName.emplace(b.name, k).second) fail("body '" + b.name + "' is defined twice");
  }
  // (specs) => per-body checks, unknown parents
  std::vector<Joint> joints;
  for (const auto& b : bodies_) {
    if (b.parent == b.name) fail("body '" + b.name + "' is its own parent");
    if (b.parent != "world" && !byName.count(b.parent)) fail("body '" + b.name + "': unknown parent '" + b.parent + "'");
    if (!finite(b.X_PJ) || !orthonormal(b.X_PJ.R)) fail("body '" + b.name + "': joint placement is not a proper rigid transform");
    checkInertia(b.name, b.inertia);
    Joint j = b.joint;
    checkJoint(b.name, j);
    joints.push_back(j);
  }
  // (parents) => depth-first order from the world; bodies not reached lie on a cycle
  std::vector<std::vector<int>> children(bodies_.size() + 1);  // index 0 = world
  for (int k = 0; k < static_cast<int>(bodies_.size()); ++k) {
    const int p = bodies_[k].parent == "world" ? 0 : byName.at(bodies_[k].parent) + 1;
    children[p].push_back(k + 1);
  }
  std::vector<int> order;  // spec index + 1
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    if (n != 0) order.push_back(n);
    for (auto it = children[n].rbegin(); it != children[n].rend(); ++it) stack.push_back(*it);
  }
  if (order.size() != bodies_.size()) {
    std::vector<bool> reached(bodies_.size() + 1, false);
    for (int n : order) reached[n] = true;
    for (int k = 0; k < static_cast<int>(bodies_.size()); ++k) {
      if (reached[k + 1]) continue;
      // walk up the parents until a body repeats
      std::string path = bodies_[k].name;
      std::vector<bool> seen(bodies_.size(), false);
      int c = k;
      while (!seen[c]) {
        seen[c] = true;
        c = byName.at(bodies_[c].parent);
        path += " -> " + bodies_[c].name;
      }
      fail("body '" + bodies_[k].name + "' is on a cycle of parents (" + path + "); a tree needs one, use a loop constraint to close a loop");
    }
  }
  // (order) => model arrays
  Model m;
  m.nbodies = static_cast<int>(order.size()) + 1;
  m.gravity = gravity_;
  m.names = {"world"};
  m.parent = {-1};
  m.joints = {Joint::fixed()};
  m.X_PJ = {Transform{}};
  m.inertias = {SpatialInertia{}};
  m.inertiaMatrices = {Matrix6::Zero()};
  m.addedMass = {Matrix6::Zero()};
  m.hasAddedMass = {false};
  m.geometry = {""};
  m.idxQ = {0};
  m.idxV = {0};
  m.jointNq = {0};
  m.jointNv = {0};
  std::vector<int> newIndex(bodies_.size() + 1, 0);
  for (int n : order) {
    const auto& b = bodies_[n - 1];
    const int i = static_cast<int>(m.names.size());
    newIndex[n] = i;
    const int p = b.parent == "world" ? 0 : newIndex[byName.at(b.parent) + 1];
    m.names.push_back(b.name);
    m.parent.push_back(p);
    m.joints.push_back(joints[n - 1]);
    m.X_PJ.push_back(b.X_PJ);
    m.inertias.push_back(b.inertia);
    m.inertiaMatrices.push_back(b.inertia.matrix());
    m.addedMass.push_back(Matrix6::Zero());
    m.hasAddedMass.push_back(false);
    m.geometry.push_back(b.geometry);
    m.idxQ.push_back(m.nq);
    m.idxV.push_back(m.nv);
    m.jointNq.push_back(joints[n - 1].nq());
    m.jointNv.push_back(joints[n - 1].nv());
    for (int k = 0; k < joints[n - 1].nv(); ++k) m.dofBody.push_back(i);
    m.nq += joints[n - 1].nq();
    m.nv += joints[n - 1].nv();
  }
  // (tree) => subtree sizes (depth-first order makes each subtree's velocities contiguous)
  m.nvSubtree = m.jointNv;
  for (int i = m.nbodies - 1; i >= 1; --i) {
    if (m.parent[i] > 0) m.nvSubtree[m.parent[i]] += m.nvSubtree[i];
  }
  m.nvSubtree[0] = m.nv;
  // (tree) => the dof tree: lambda(k) and the dofs below k (tree_cholesky.hpp)
  m.dofParent.assign(static_cast<std::size_t>(m.nv), -1);
  m.dofSubtree.assign(static_cast<std::size_t>(m.nv), 0);
  for (int i = 1; i < m.nbodies; ++i) {
    int p = m.parent[i];
    while (p > 0 && m.jointNv[p] == 0) p = m.parent[p];
    const int last = p > 0 ? m.idxV[p] + m.jointNv[p] - 1 : -1;
    for (int k = 0; k < m.jointNv[i]; ++k) {
      m.dofParent[m.idxV[i] + k] = k == 0 ? last : m.idxV[i] + k - 1;
      m.dofSubtree[m.idxV[i] + k] = m.nvSubtree[i] - k;
    }
  }
  for (int i = 0; i < m.nbodies; ++i) {
    m.placementRotated.push_back(!m.X_PJ[i].R.isIdentity(0.0));
    m.jointAxis.push_back(coordinateAxis(m.joints[i]));
    const Matrix3& Ic = m.inertias[i].inertiaCom;
    m.inertiaDiagonal.push_back(Ic.isDiagonal(0.0));
    if (m.joints[i].type == JointType::Spherical || m.joints[i].type == JointType::Free) m.euclidean = false;
  }
  // (added-mass specs) => checked symmetric 6x6 per body (a second one for a body replaces the first)
  for (const auto& [name, A] : addedMass_) {
    const int i = m.bodyIndex(name);
    if (i < 1) fail("added mass given for unknown body '" + name + "'");
    checkAddedMass(name, A);
    m.addedMass[static_cast<std::size_t>(i)] = 0.5 * (A + A.transpose());
    m.hasAddedMass[static_cast<std::size_t>(i)] = !A.isZero(0.0);
  }
  // (loop specs) => loops with rows
  for (const auto& l : loops_) {
    const std::string who = "loop '" + l.name + "': ";
    const int a = l.bodyA == "world" ? 0 : m.bodyIndex(l.bodyA);
    const int b = l.bodyB == "world" ? 0 : m.bodyIndex(l.bodyB);
    if (a < 0) fail(who + "unknown body '" + l.bodyA + "'");
    if (b < 0) fail(who + "unknown body '" + l.bodyB + "'");
    if (a == b) fail(who + "both ends are on body '" + l.bodyA + "'");
    if (!finite(l.X_AF) || !orthonormal(l.X_AF.R) || !finite(l.X_BG) || !orthonormal(l.X_BG.R))
      fail(who + "frame placement is not a proper rigid transform");
    const std::uint8_t rot = l.mask & 7;
    if (l.mask == 0 || l.mask > 63) fail(who + "constraint mask must select 1 to 6 components");
    if (rot != 0 && rot != (kRotX | kRotY) && rot != 7) fail(who + "rotational components must be none, x-y (axis along z) or all three");
    LoopConstraint c{l.name, a, b, l.X_AF, l.X_BG, l.mask, std::popcount(static_cast<unsigned>(l.mask)), m.nc};
    m.nc += c.dim;
    m.loops.push_back(c);
  }
  return m;
}

}  // namespace yardsim::dynamics
