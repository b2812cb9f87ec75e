// The 3D replay of the multibody model (docs/report.md): its bodies with their shapes and its
// ropes as polylines, then one pose per body per recorded frame.
#include <array>

#include "dynamics/rotation.hpp"
#include "models/multibody/multibody_model.hpp"

namespace yardsim::models {

void MultibodyModel::replayBodies(Replay& out) const {
  // (bodies, ropes and equalizer branches) => replay bodies named by path, ropes as polylines
  const auto& m = system_.model();
  const std::string prefix = opt_.elementPaths ? "" : path() + ".";
  const auto first = static_cast<int>(out.bodies.size());
  for (int i = 1; i < m.nbodies; ++i) {
    const auto& in = m.inertias[static_cast<std::size_t>(i)];
    out.bodies.push_back(replayShape(system_.description().visuals[static_cast<std::size_t>(i)],
                                     in.mass, in.com, in.inertiaCom));
    out.bodies.back().name = prefix + m.names[static_cast<std::size_t>(i)];
  }
  auto point = [&](const mechanics::MechanicsSpec::Point& p) {
    const int b = m.bodyIndex(p.first);
    return std::pair{b > 0 ? first + b - 1 : -1, p.second};
  };
  for (const auto& r : system_.description().ropes) {
    out.ropes.push_back({prefix + r.name, {}});
    for (const auto& p : r.path) out.ropes.back().points.push_back(point(p));
  }
  for (const auto& e : system_.description().equalizers)
    for (std::size_t j = 0; j < e.branches.size(); ++j) {
      out.ropes.push_back({prefix + e.name + ".branch" + std::to_string(j), {point(e.sheave)}});
      for (const auto& p : e.branches[j]) out.ropes.back().points.push_back(point(p));
    }
}

void MultibodyModel::replayFrame(Replay& out, std::size_t firstBody) const {
  // (committed state) => each body's world pose, quaternions kept on one hemisphere frame to frame
  const dynamics::Data& d = kinematicsOf(state().x);
  for (int i = 1; i < system_.model().nbodies; ++i) {
    ReplayBody& b = out.bodies[firstBody + static_cast<std::size_t>(i - 1)];
    const dynamics::Transform& X = d.X_WB[static_cast<std::size_t>(i)];
    double q[4];  // w, x, y, z
    dynamics::matrixToQuaternion(X.R, q);
    std::array<float, 4> r{static_cast<float>(q[1]), static_cast<float>(q[2]),
                           static_cast<float>(q[3]), static_cast<float>(q[0])};
    if (!b.rotation.empty()) {
      const auto& prev = b.rotation.back();
      if (prev[0] * r[0] + prev[1] * r[1] + prev[2] * r[2] + prev[3] * r[3] < 0)
        for (float& c : r) c = -c;
    }
    b.translation.push_back(
        {static_cast<float>(X.p[0]), static_cast<float>(X.p[1]), static_cast<float>(X.p[2])});
    b.rotation.push_back(r);
  }
}

}  // namespace yardsim::models
