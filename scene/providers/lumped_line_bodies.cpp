#include "scene/providers/lumped_line_bodies.hpp"

namespace yardsim::scene::providers {

using mechanics::MechanicsSpec;

MechanicsSpec::Body lumpedNodeBody(const forces::LumpedNodeBody& node, double diameter) {
  MechanicsSpec::Body b;
  b.name = b.jointName = node.name;
  b.parent = "world";
  b.joint = dynamics::Joint::translation();
  b.X_PJ = dynamics::Transform::identity();
  b.mass = node.mass;
  // (a point mass; the translation joint never turns it) => the inertia of a sphere of the
  // line's diameter, only to keep the body's inertia positive definite
  b.inertia = 0.1 * node.mass * diameter * diameter * dynamics::Matrix3::Identity();
  b.q0 = {node.p_W.x(), node.p_W.y(), node.p_W.z()};
  b.visual.shape = MechanicsSpec::Visual::Shape::Sphere;
  b.visual.size = dynamics::Vector3(diameter, 0.0, 0.0);
  return b;
}

MechanicsSpec::ProviderBodies lumpedLineBodies(const forces::LumpedLineProperties& p) {
  // (full name, ends at q0) => the inner nodes: point masses on translation joints from the world
  return [p](const std::string& name, const std::vector<dynamics::Vector3>& at) {
    const forces::LumpedLine line(p, name);
    std::vector<MechanicsSpec::Body> bodies;
    for (const auto& node : forces::lumpedLineNodes(line, name, at.at(0), at.at(1)))
      bodies.push_back(lumpedNodeBody(node, p.diameter));
    return bodies;
  };
}

}  // namespace yardsim::scene::providers
