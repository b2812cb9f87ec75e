// The channels of the multibody model (docs/scenes.md): joints, bodies, ropes, equalizers, body
// loads, floating providers and the energy balance, read from the committed state.
#include <limits>

#include "dynamics/kinematics.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/rotation.hpp"
#include "forces/provider_outputs.hpp"
#include "forces/wind_load.hpp"
#include "models/multibody/multibody_model.hpp"

namespace yardsim::models {

void MultibodyModel::channels(std::vector<Channel>& out) const {
  const auto& m = system_.model();
  for (int i = 1; i < m.nbodies; ++i) {
    const std::string& j = system_.description().jointNames[static_cast<std::size_t>(i)];
    const bool linear = m.joints[i].type == dynamics::JointType::Prismatic;
    for (int k = 0; k < m.jointNq[i] && m.jointNq[i] == m.jointNv[i]; ++k) {
      const std::string suffix = m.jointNq[i] == 1 ? "" : std::to_string(k);
      const int iq = m.idxQ[i] + k, iv = m.idxV[i] + k;
      out.push_back(
          {j + ".q" + suffix, linear ? "m" : "rad", [this, iq] { return state().x.q[iq]; }});
      out.push_back(
          {j + ".v" + suffix, linear ? "m/s" : "rad/s", [this, iv] { return state().x.v[iv]; }});
      out.push_back({j + ".a" + suffix, linear ? "m/s^2" : "rad/s^2",
                     [this, iv] { return acceleration()[iv]; }});
    }
    if (m.nc == 0 && m.jointNv[i] < 6)  // (joint) => magnitude of the force it transmits
      out.push_back(
          {j + ".reaction", "N", [this, i] { return jointForces()[i].tail<3>().norm(); }});
    const std::string& b = m.names[i];
    const char* axes[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k)
      out.push_back(
          {b + "." + axes[k], "m", [this, i, k] { return kinematicsOf(state().x).X_WB[i].p[k]; }});
    const char* angles[3] = {"roll", "pitch", "yaw"};
    for (int k = 0; k < 3; ++k)
      out.push_back({b + "." + angles[k], "rad", [this, i, k] {
                       return dynamics::bodyEulerAngles(kinematicsOf(state().x), i)[k];
                     }});
  }
  for (std::size_t r = 0; r < system_.ropes().size(); ++r) {
    const std::string& n = system_.ropes()[r]->name();
    auto stage = [this] {
      const auto& s = state();
      return forces::Stage{s.tx, system_.model(), kinematicsOf(s.x), s.x.q, s.x.v};
    };
    out.push_back(
        {n + ".tension", "N", [this, r, stage] { return system_.ropes()[r]->tension(stage()); }});
    out.push_back(
        {n + ".length", "m", [this, r, stage] { return system_.ropes()[r]->length(stage()); }});
    out.push_back({n + ".unstretched_length", "m",
                   [this, r] { return system_.ropes()[r]->unstretchedLength(state().tx); }});
    out.push_back({n + ".peak_tension", "N", [this, r] { return state().x.peakTension[r]; }});
    const forces::Rope& rope = *system_.ropes()[r];
    if (rope.branchCount() > 1)  // (an equalizer) => each branch's length too
      for (int j = 0; j < rope.branchCount(); ++j)
        out.push_back({n + ".branch" + std::to_string(j) + ".length", "m",
                       [&rope, stage, j] { return rope.branchLength(stage(), j); }});
  }
  for (std::size_t k = 0; k < system_.bodyLoads().size(); ++k) {
    const forces::BodyLoad& l = *system_.bodyLoads()[k];
    const char* comps[6] = {"fx", "fy", "fz", "mx", "my", "mz"};
    for (int c = 0; c < 6; ++c)
      out.push_back({l.name() + "." + comps[c], c < 3 ? "N" : "N m", [this, &l, c] {
                       const auto s = l.at(state().tx);
                       return c < 3 ? s.force[c] : s.moment[c - 3];
                     }});
  }
  floatingChannels(out);
  for (const auto& c :
       system_.contributed()) {  // (providers of registered readers) => energy, power
    const forces::ForceProvider* p = c.get();
    out.push_back(
        {p->name() + ".energy", "J", [this, p] { return p->potentialEnergy(committedStage(p)); }});
    out.push_back({p->name() + ".power", "W", [this, p] { return p->power(committedStage(p)); }});
    // (outputs the provider declares) => <name>.<output> (or <output> when global), read with
    // its scratch
    if (const auto* o = dynamic_cast<const forces::ProviderOutputs*>(p))
      for (const forces::ProviderOutput& v : o->outputs())
        out.push_back({(v.global ? "" : p->name() + ".") + v.name, v.unit,
                       [this, p, &v] { return v.read(committedStage(p)); }});
  }
  // (system-wide quantities) => under the model's own name when element names are paths
  const std::string own = opt_.elementPaths ? path() + "." : "";
  out.push_back({own + "energy", "J", [this] { return energy(); }});
  out.push_back({own + "work", "J", [this] { return state().x.work; }});
  out.push_back({own + "energy_balance", "J", [this] { return energy() - state().x.work; }});
  // (a wind with gusts) => its speed at the reference height, mean plus gust, m/s (one series
  // per scene; a steady wind has no such channel: its speed is the `speed` key)
  for (const auto& fp : system_.flows())
    if (const auto* w = dynamic_cast<const forces::WindLoad*>(fp.get()); w && w->field().gusts()) {
      const forces::WindField* field = &w->field();
      out.push_back({own + "wind_speed", "m/s", [this, field] {
                       return field->speedAt(field->properties().referenceHeight) + field->gust(state().tx);
                     }});
      break;
    }
  if (m.nc > 0)
    out.push_back({own + "loop_residual", "m", [this] {
                     return dynamics::loopResidualNorm(system_.model(), ws_.data.view, state().x.q);
                   }});
}

const forces::HydrostaticReport& MultibodyModel::hydrostaticReport(std::size_t k) const {
  // (committed state) => the report, recomputed when the time or q changed
  const auto& s = state();
  const std::size_t n = system_.hydrostatics().size();
  if (ws_.reports.size() != n) {
    ws_.reports.assign(n, {});
    ws_.reportTime.assign(n, std::numeric_limits<double>::quiet_NaN());
    ws_.reportQ.assign(n, Eigen::VectorXd());
  }
  const Eigen::VectorXd& q = ws_.reportQ[k];
  if (ws_.reportTime[k] != s.tx || q.size() != s.x.q.size() || q != s.x.q) {
    const forces::Hydrostatics& h = *system_.hydrostatics()[k];
    ws_.reports[k] = h.report(committedStage(&h));
    ws_.reportTime[k] = s.tx;
    ws_.reportQ[k] = s.x.q;
  }
  return ws_.reports[k];
}

void MultibodyModel::floatingChannels(std::vector<Channel>& out) const {
  const char* xyz[3] = {"x", "y", "z"};
  for (std::size_t hk = 0; hk < system_.hydrostatics().size(); ++hk) {
    const forces::Hydrostatics* h = system_.hydrostatics()[hk].get();
    const std::string& n = h->name();
    auto rep = [this, hk]() -> const forces::HydrostaticReport& { return hydrostaticReport(hk); };
    out.push_back({n + ".draft", "m", [rep] { return rep().draft; }});
    out.push_back({n + ".heel", "rad", [rep] { return rep().heel; }});
    out.push_back({n + ".trim", "rad", [rep] { return rep().trim; }});
    out.push_back({n + ".displacement", "kg", [rep] { return rep().displacement; }});
    out.push_back({n + ".volume", "m^3", [rep] { return rep().submerged.volume; }});
    out.push_back(
        {n + ".waterplane_area", "m^2", [rep] { return rep().submerged.waterplaneArea; }});
    out.push_back({n + ".gm_t", "m", [rep] { return rep().gmTransverse; }});
    out.push_back({n + ".gm_l", "m", [rep] { return rep().gmLongitudinal; }});
    // (force, moment about the world origin) => world axes, moment about the body's centre of mass
    const int b = h->body();
    for (int k = 0; k < 3; ++k)
      out.push_back({n + ".f" + xyz[k], "N", [rep, k] { return rep().submerged.force[k]; }});
    for (int k = 0; k < 3; ++k)
      out.push_back({n + ".m" + xyz[k], "N m", [this, rep, b, k] {
                       const auto& r = rep().submerged;
                       const auto& I = system_.model().inertias[b];
                       const dynamics::Vector3 G = kinematicsOf(state().x).X_WB[b].actPoint(I.com);
                       return (r.moment - G.cross(r.force))[k];
                     }});
    out.push_back({n + ".wave_elevation", "m", [this, h, b] {
                     const dynamics::Vector3 p = kinematicsOf(state().x).X_WB[b].p;
                     return h->sea().elevation(p.x(), p.y(), state().tx);
                   }});
  }
  for (const auto& fp : system_.flows()) {
    const forces::FlowLoad* f = fp.get();
    auto load = [this, f] { return f->load(committedStage()); };
    out.push_back({f->name() + ".fx", "N", [load] { return load().force.x(); }});
    out.push_back({f->name() + ".fy", "N", [load] { return load().force.y(); }});
    out.push_back({f->name() + ".mz", "N m", [load] { return load().yawMoment; }});
    out.push_back({f->name() + ".speed", "m/s", [load] { return load().speed; }});
    out.push_back({f->name() + ".angle", "rad", [load] { return load().angle; }});
  }
  const char* dof[6] = {"fx", "fy", "fz", "mx", "my", "mz"};
  for (const auto& dp : system_.dampers()) {
    const forces::LinearQuadraticDamping* d = dp.get();
    for (std::size_t k = 0; k < 6; ++k)
      out.push_back({d->name() + "." + dof[k], k < 3 ? "N" : "N m",
                     [this, d, k] { return d->load(committedStage())[k]; }});
  }
}

}  // namespace yardsim::models
