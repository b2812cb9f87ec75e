#include "mechanics/build.hpp"

#include "dynamics/kinematics.hpp"
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

namespace {

// (bodies, built model) => their names, holds, visuals and given q0, v0 in out
void placeBodies(const std::vector<MechanicsSpec::Body>& bodies, BuiltMechanics& out) {
  const auto& m = out.model;
  for (const auto& b : bodies) {
    const int i = m.bodyIndex(b.name);
    out.jointNames[static_cast<std::size_t>(i)] = b.jointName;
    out.hold[static_cast<std::size_t>(i)] = b.hold ? 1 : 0;
    out.visuals[static_cast<std::size_t>(i)] = b.visual;
    for (std::size_t k = 0; k < b.q0.size(); ++k) out.q0[m.idxQ[i] + static_cast<int>(k)] = b.q0[k];
    for (std::size_t k = 0; k < b.v0.size(); ++k) out.v0[m.idxV[i] + static_cast<int>(k)] = b.v0[k];
  }
}

// (built model) => q0, v0 neutral and at rest; names, holds and visuals defaulted
void resetState(BuiltMechanics& out) {
  const auto& m = out.model;
  out.visuals.assign(static_cast<std::size_t>(m.nbodies), {});
  out.q0 = Eigen::VectorXd::Zero(m.nq);
  out.v0 = Eigen::VectorXd::Zero(m.nv);
  out.jointNames.assign(static_cast<std::size_t>(m.nbodies), "");
  out.hold.assign(static_cast<std::size_t>(m.nbodies), 0);
  for (int i = 1; i < m.nbodies; ++i)
    dynamics::jointNeutral(m.joints[i], out.q0.data() + m.idxQ[i]);
}

// (built mechanics of the declared bodies) => the providers' own bodies (lumped-line nodes) added
// to the builder, placed from their attachments' world points at q0; the bodies added
std::vector<MechanicsSpec::Body> providerBodies(const MechanicsSpec& spec,
                                                const BuiltMechanics& out,
                                                dynamics::ModelBuilder& builder) {
  std::vector<MechanicsSpec::Body> added;
  const auto& m = out.model;
  dynamics::Data data(m);
  bool placed = false;
  for (const auto& p : spec.providers) {
    if (!p.bodies && !p.bodiesInSea) continue;
    if (!placed) dynamics::forwardKinematics(m, data, out.q0, out.v0);
    placed = true;
    std::vector<dynamics::Vector3> at_W;
    for (const auto& [body, p_B] : p.attachments) {
      const int b = body == "world" ? 0 : m.bodyIndex(body);
      if (b < 0)
        throw dynamics::ModelError(p.kind + " '" + p.name + "': unknown body '" + body + "'");
      at_W.push_back(dynamics::pointPosition(data, b, p_B));
    }
    for (auto& b : p.bodiesInSea ? p.bodiesInSea(p.name, at_W, spec) : p.bodies(p.name, at_W)) {
      builder.addBody(b.name, b.parent, b.joint, b.X_PJ,
                      dynamics::makeInertia(b.mass, b.com, b.inertia), b.geometry);
      added.push_back(std::move(b));
    }
  }
  return added;
}

}  // namespace

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
  resetState(out);
  placeBodies(spec.bodies, out);
  // (providers' own bodies, after the declared ones) => the model again with them
  if (const auto added = providerBodies(spec, out, builder); !added.empty()) {
    out.model = builder.build();
    resetState(out);
    placeBodies(spec.bodies, out);
    placeBodies(added, out);
  }
  // (hull meshes, pose at q0) => added mass by the panel solver, then the model again with it
  if (needsHullAddedMass(spec.bodies)) {
    setHullAddedMass(out.model, out.q0, spec, builder);
    out.model = builder.build();
  }
  // (hull meshes with drafts) => their tables, at the attitude of q0
  out.draftAddedMass = draftAddedMassTables(out.model, out.q0, spec);
  return out;
}

}  // namespace yardsim::mechanics
