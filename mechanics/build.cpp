#include "mechanics/build.hpp"

#include "dynamics/model_builder.hpp"
#include "mechanics/added_mass_build.hpp"

namespace yardsim::mechanics {

std::string missingEnvironment(const MechanicsSpec& spec) {
  if (!spec.windLoads.empty() && !spec.wind)
    return "wind load '" + spec.windLoads.front().name +
           "' needs the scene's wind: declare `wind: {speed, ...}` under the root's mechanics";
  if (!spec.currentLoads.empty() && !spec.current)
    return "current load '" + spec.currentLoads.front().name +
           "' needs the scene's current: declare `water: {current: {speed, ...}}` under the root's "
           "mechanics";
  return "";
}

BuiltMechanics buildMechanics(const MechanicsSpec& spec) {
  dynamics::ModelBuilder builder;
  builder.setGravity(spec.gravity);
  for (const auto& b : spec.bodies)
    builder.addBody(b.name, b.parent, b.joint, b.X_PJ,
                    dynamics::makeInertia(b.mass, b.com, b.inertia), b.geometry);
  for (const auto& l : spec.loops)
    builder.addLoop(l.name, l.bodyA, l.X_AF, l.bodyB, l.X_BG, l.mask);
  setGivenAddedMass(spec.bodies, builder);
  BuiltMechanics out{builder.build(), {},         {},           {},  {}, spec.ropes,
                     spec.equalizers, spec.loads, spec.watches, spec};
  out.environment.bodies.clear();
  out.environment.loops.clear();
  out.environment.ropes.clear();
  out.environment.equalizers.clear();
  out.environment.loads.clear();
  out.environment.watches.clear();
  out.environment.providers.clear();
  out.providers = spec.providers;
  const auto& m = out.model;
  out.visuals.resize(static_cast<std::size_t>(m.nbodies));
  out.q0 = Eigen::VectorXd::Zero(m.nq);
  out.v0 = Eigen::VectorXd::Zero(m.nv);
  out.jointNames.assign(static_cast<std::size_t>(m.nbodies), "");
  out.hold.assign(static_cast<std::size_t>(m.nbodies), 0);
  for (int i = 1; i < m.nbodies; ++i)
    dynamics::jointNeutral(m.joints[i], out.q0.data() + m.idxQ[i]);
  for (const auto& b : spec.bodies) {
    const int i = m.bodyIndex(b.name);
    out.jointNames[static_cast<std::size_t>(i)] = b.jointName;
    out.hold[static_cast<std::size_t>(i)] = b.hold ? 1 : 0;
    out.visuals[static_cast<std::size_t>(i)] = b.visual;
    for (std::size_t k = 0; k < b.q0.size(); ++k) out.q0[m.idxQ[i] + static_cast<int>(k)] = b.q0[k];
    for (std::size_t k = 0; k < b.v0.size(); ++k) out.v0[m.idxV[i] + static_cast<int>(k)] = b.v0[k];
  }
  // (hull meshes, pose at q0) => added mass by the panel solver, then the model again with it
  if (needsHullAddedMass(spec.bodies)) {
    setHullAddedMass(out.model, out.q0, spec, builder);
    out.model = builder.build();
  }
  return out;
}

}  // namespace yardsim::mechanics
