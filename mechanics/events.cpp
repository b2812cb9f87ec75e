#include "mechanics/events.hpp"

#include <algorithm>
#include <limits>

#include "dynamics/kinematics.hpp"

namespace yardsim::mechanics {

std::vector<EventSlot> eventTable(const System& s) {
  using K = EventSlot::Kind;
  std::vector<EventSlot> table;
  const int nb = s.model().nbodies, nr = static_cast<int>(s.ropes().size());
  table.push_back({K::None, 0, false});
  for (int i = 1; i < nb; ++i) table.push_back({K::DriveReached, i, false});
  for (int r = 0; r < nr; ++r) table.push_back({K::OverMbl, r, false});
  for (int r = 0; r < nr; ++r) table.push_back({K::SlackTaut, r, true});
  for (int w = 0; w < static_cast<int>(s.watches().size()); ++w)
    table.push_back({K::WatchCrossed, w, false});
  for (int e = 0; e < static_cast<int>(s.providerEvents().size()); ++e)
    table.push_back(
        {K::Provider, e, !s.providerEvents()[static_cast<std::size_t>(e)]->falling.empty()});
  return table;
}

void eventFunctions(const System& s, Data& d, const SetPoints& sp, const Eigen::VectorXd& q,
                    const Eigen::VectorXd& v, double t, std::span<double> g) {
  const auto& m = s.model();
  // (drive) => > 0 once the joint is within tolerance of its target, on the side it comes from
  g[0] = -1.0;
  for (int i = 1; i < m.nbodies; ++i) {
    const JointDrive& j = sp.drives[i];
    if (!j.active || j.reported || j.prescribed) {
      g[i] = -1.0;
      continue;
    }
    const double dir = j.target >= j.start ? 1.0 : -1.0;
    g[i] = dir * (q[m.idxQ[i]] - j.target) + s.servo().tolerance;
  }
  // (ropes with a minimum breaking load) => > 0 once the tension exceeds it
  const auto& ropes = s.ropes();
  if (ropes.empty() && s.watches().empty() && s.providerEvents().empty()) return;
  const dynamics::Data& kin = d.scratchKinematics(s, q, v);
  const forces::Stage stage{t, m, kin, q, v};
  const std::size_t nb = static_cast<std::size_t>(m.nbodies), nr = ropes.size();
  for (std::size_t r = 0; r < nr; ++r) {
    const auto& mbl = ropes[r]->properties().breakingLoad;
    g[nb + r] = mbl ? ropes[r]->tension(stage) - *mbl : -1.0;
    // (rope) => its stretch: > 0 taut, < 0 slack
    g[nb + nr + r] = ropes[r]->length(stage) - ropes[r]->unstretchedLength(t);
  }
  // (watches) => > 0 once the quantity is past its threshold in the watched direction
  const auto& specs = s.description().watches;
  for (std::size_t w = 0; w < s.watches().size(); ++w) {
    const double value = watched(s, w, kin, q, v, t);
    g[nb + 2 * nr + w] = specs[w].above ? value - specs[w].threshold : specs[w].threshold - value;
  }
  // (provider events) => their own functions
  const std::size_t first = nb + 2 * nr + s.watches().size();
  for (std::size_t e = 0; e < s.providerEvents().size(); ++e)
    g[first + e] = s.providerEvents()[e]->g(stage);
}

EventReport reportStateEvent(const System& s, Data& d, const SetPoints& sp,
                             const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                             const EventSlot& e) {
  const auto& model = s.model();
  const auto& ropes = s.ropes();
  const auto k = static_cast<std::size_t>(e.index);
  using K = EventSlot::Kind;
  if (e.kind == K::DriveReached)
    return {s.description().jointNames[k], sp.drives[k].actor, "reached", q[model.idxQ[e.index]]};
  // (state) => its kinematics, the quantity at the event
  const dynamics::Data& kin = d.scratchKinematics(s, q, v);
  const forces::Stage stage{t, model, kin, q, v};
  switch (e.kind) {
    case K::WatchCrossed:
      return {s.description().watches[k].name, "", "crossed", watched(s, k, kin, q, v, t)};
    case K::SlackTaut: {  // (direction of the crossing) => lengthening through L0: taut;
                          // shortening: slack
      const bool taut = ropes[k]->lengthRate(stage) >= ropes[k]->payoutRate(t);
      return {ropes[k]->name(), "", taut ? "taut" : "slack", ropes[k]->length(stage)};
    }
    case K::OverMbl:
      return {ropes[k]->name(), "", "over_mbl", ropes[k]->tension(stage)};
    case K::Provider: {  // (the sign of g just past the event) => rising or falling
      const forces::ProviderEvent& p = *s.providerEvents()[k];
      const bool rising = p.falling.empty() || p.g(stage) > 0;
      return {p.element, "", rising ? p.rising : p.falling, p.value(stage),
              p.detail ? p.detail(stage) : std::string()};
    }
    default:
      return {};
  }
}

void reportTimeEvents(const System& s, const SetPoints& sp, const Eigen::VectorXd&, double t,
                      std::vector<EventReport>& out) {
  const auto& winches = s.winches();
  for (std::size_t k = 0; k < sp.winches.size(); ++k)
    if (sp.winches[k].active && sp.winches[k].tEnd <= t)
      out.push_back({winches[k].name, sp.winches[k].actor, "done", winches[k].winch->length(t)});
  for (int i = 1; i < s.model().nbodies; ++i) {
    const JointDrive& j = sp.drives[static_cast<std::size_t>(i)];
    if (j.active && j.prescribed && !j.reported && j.tEnd() <= t)
      out.push_back(
          {s.description().jointNames[static_cast<std::size_t>(i)], j.actor, "reached", j.target});
  }
}

double nextTimeEvent(const System& s, const SetPoints& sp, double t) {
  double next = std::numeric_limits<double>::infinity();
  for (std::size_t r = 0; r < sp.winches.size(); ++r)  // (a job's end, and its profile's breaks)
    if (const WinchJob& w = sp.winches[r]; w.active && w.tEnd > t)
      next = std::min({next, w.tEnd, s.winches()[r].winch->nextBreak(t)});
  for (const auto& d : sp.drives)
    if (d.active && d.prescribed && !d.reported && d.tEnd() > t) next = std::min(next, d.tEnd());
  for (const auto& l : s.bodyLoads()) next = std::min(next, l->nextBreak(t));  // kinks and jumps
  return next;
}

double watched(const System& s, std::size_t w, const dynamics::Data& kin, const Eigen::VectorXd& q,
               const Eigen::VectorXd& v, double t) {
  const WatchRef& r = s.watches()[w];
  using K = WatchRef::Kind;
  switch (r.kind) {
    case K::Q:
      return q[r.index];
    case K::V:
      return v[r.index];
    case K::Position:
      return kin.X_WB[static_cast<std::size_t>(r.index)].p[r.axis];
    case K::Angle:
      return dynamics::bodyEulerAngles(kin, r.index)[r.axis];
    case K::Tension:
      return s.ropes()[static_cast<std::size_t>(r.index)]->tension({t, s.model(), kin, q, v});
    case K::Length:
      return s.ropes()[static_cast<std::size_t>(r.index)]->length({t, s.model(), kin, q, v});
  }
  return 0.0;
}

}  // namespace yardsim::mechanics
