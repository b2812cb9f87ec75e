// The 3D replay of the multibody model (docs/report.md): its bodies with their shapes, its ropes
// and lines as polylines (wire ropes through their paths, lines with mass through their nodes,
// catenary lines through markers on their profile), then one pose per body per recorded frame.
#include <array>

#include "dynamics/rotation.hpp"
#include "forces/lines/catenary_line.hpp"
#include "forces/lines/lumped_rope_over_sheave.hpp"
#include "forces/provider_outputs.hpp"
#include "models/multibody/multibody_model.hpp"

namespace yardsim::models {

namespace {

// segments of a catenary line's drawn profile: its markers are the inner points 1 .. n - 1
constexpr int kProfileSegments = 20;

}  // namespace

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
  // (a provider's point, model body b) => the replay's body and point
  auto at = [first](const forces::Attachment& a) {
    return std::pair{a.body > 0 ? first + a.body - 1 : -1, a.p_B};
  };
  // (lumped line) => its anchor, inner nodes and fairlead appended to a polyline
  auto nodes = [&](const forces::LumpedLineProvider& l, ReplayRope& r) {
    r.points.push_back(at(l.anchor()));
    for (int i = 1; i < l.line().properties().segments; ++i)
      r.points.emplace_back(first + l.nodeBody(i) - 1, dynamics::Vector3::Zero());
    r.points.push_back(at(l.fairlead()));
  };
  // (lines with mass, catenary lines) => polylines through their nodes or their profile markers
  for (const forces::ForceProvider* p : system_.providers()) {
    if (const auto* l = forces::providerAs<forces::LumpedLineProvider>(*p)) {
      nodes(*l, out.ropes.emplace_back(ReplayRope{prefix + p->name(), {}}));
    } else if (const auto* s = forces::providerAs<forces::LumpedRopeOverSheave>(*p)) {
      ReplayRope& r = out.ropes.emplace_back(ReplayRope{prefix + p->name(), {}});
      nodes(s->spanA(), r);  // (the first end to p, the sheave, q to the last end)
      r.points.push_back(at(s->overSheave().path().points()[1]));
      nodes(s->spanB(), r);
    } else if (const auto* c = forces::providerAs<forces::CatenaryLine>(*p)) {
      ReplayRope& r = out.ropes.emplace_back(ReplayRope{prefix + p->name(), {at(c->anchor())}});
      for (int k = 1; k < kProfileSegments; ++k) {
        r.points.emplace_back(static_cast<int>(out.bodies.size()), dynamics::Vector3::Zero());
        out.bodies.push_back({});
        out.bodies.back().name = prefix + p->name() + ".profile" + std::to_string(k);
        out.bodies.back().marker = true;
      }
      r.points.push_back(at(c->fairlead()));
    }
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
  // (catenary lines, in replayBodies' order) => their profile markers' positions
  std::size_t marker = firstBody + static_cast<std::size_t>(system_.model().nbodies - 1);
  for (const forces::ForceProvider* p : system_.providers())
    if (const auto* c = forces::providerAs<forces::CatenaryLine>(*p)) {
      const auto points = c->profile(committedStage(p), kProfileSegments);
      for (int k = 1; k < kProfileSegments; ++k) {
        const dynamics::Vector3& x = points[static_cast<std::size_t>(k)];
        out.bodies[marker++].translation.push_back(
            {static_cast<float>(x[0]), static_cast<float>(x[1]), static_cast<float>(x[2])});
      }
    }
}

}  // namespace yardsim::models
