#include "studies/work_precision.hpp"

#include "mechanics/build.hpp"
#include "studies/work_precision_reference.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "devs/simulator.hpp"
#include "dtss/grid.hpp"
#include "scene/assembler.hpp"
#include "models/channels.hpp"
#include "scene/integrator_reader.hpp"
#include "scene/mechanical_systems.hpp"
#include "models/multibody/multibody_model.hpp"
#include "mechanics/stiffness_estimate.hpp"

namespace yardsim::studies {

using mechanics::buildMechanics;
using mechanics::estimateStiffness;
using models::Channel;
using models::Diagnostics;
using models::MultibodyModel;
using models::collectChannels;
using scene::Scene;
using scene::assemble;
using scene::parseIntegratorSpec;
namespace {

// (scene, run) => the scene's integrator set to the run's (restored on destruction): its
// method, its step (an adaptive run steps from grid point to grid point), its tolerance and
// the entry's other integrator keys, read like the scene's own `integrator:` block
class IntegratorOverride {
 public:
  IntegratorOverride(Scene& s, const WpRun& r, double gridStep)
      : s_(s), spec_(s.integratorSpec), method_(s.integrator), dt_(s.dt) {
    YAML::Node n = r.extra && r.extra.IsMap() ? YAML::Clone(r.extra) : YAML::Node(YAML::NodeType::Map);
    n["method"] = r.method;
    if (r.rtol > 0) n["rtol"] = r.rtol;
    Diagnostics d;
    dynamics::IntegratorSpec spec = parseIntegratorSpec(n, s.file.string(), d);
    if (d.hasErrors()) throw std::invalid_argument("wp: " + r.label + " " + r.param() + ": " + d.report());
    spec.dt = r.dt > 0 ? r.dt : gridStep;
    s.integratorSpec = spec;
    s.integrator = spec.method;
    s.dt = spec.dt;
  }
  ~IntegratorOverride() {
    s_.integratorSpec = spec_;
    s_.integrator = method_;
    s_.dt = dt_;
  }
  IntegratorOverride(const IntegratorOverride&) = delete;
  IntegratorOverride& operator=(const IntegratorOverride&) = delete;

 private:
  Scene& s_;
  dynamics::IntegratorSpec spec_;
  std::string method_;
  double dt_;
};

// (channels, name) => the channel of that exact name; throws naming the known ones
const Channel& channelNamed(const std::vector<Channel>& all, const std::string& name) {
  for (const auto& c : all)
    if (c.name == name) return c;
  std::string known;
  for (const auto& c : all) known += (known.empty() ? "" : ", ") + c.name;
  throw std::invalid_argument("wp.channels: no channel '" + name + "' in the scene; it has: " + known);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

WpSeries runOnGrid(Scene& scene, const WpRun& run, const WpSpec& spec) {
  IntegratorOverride override(scene, run, spec.interval);
  auto root = assemble(scene);
  const auto all = collectChannels(*root);
  std::vector<const Channel*> channels;
  for (const auto& name : spec.channels) channels.push_back(&channelNamed(all, name));
  std::vector<const Channel*> residuals;
  for (const auto& c : all)
    if (c.name.size() >= 13 && c.name.compare(c.name.size() - 13, 13, "loop_residual") == 0) residuals.push_back(&c);
  std::vector<const MultibodyModel*> models;
  for (const auto& s : scene.systems)
    if (auto* m = dynamic_cast<const MultibodyModel*>(root->findComponent(s->name))) models.push_back(m);

  WpSeries out;
  // (state at a grid time) => one row of the error channels, and the loop residual
  auto sample = [&] {
    std::vector<double> row;
    for (const auto* c : channels) row.push_back(c->read());
    out.values.push_back(std::move(row));
    for (const auto* c : residuals) out.gMax = std::max(out.gMax, std::abs(c->read()));
  };
  const auto start = std::chrono::steady_clock::now();
  try {
    sample();
    devs::Simulator sim(*root);
    for (std::int64_t k = 1;; ++k) {
      // (events up to the next grid time) => executed, then one sample
      // a step whose time is the grid time up to rounding (k h against j interval) belongs to it
      const double next = std::min(dtss::gridOffset(spec.interval, k), spec.until);
      const double slack = 1e-9 * spec.interval;
      while (sim.nextEventTime() <= next + slack) sim.step();
      if (sim.time() < next) sim.runUntil(next);
      sample();
      if (next >= spec.until) break;
    }
  } catch (const devs::SimulationError& e) {
    out.ok = false;
    out.failure = e.what();
  }
  out.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto* m : models) {
    const dynamics::IntegratorStats& st = m->integratorStats();
    out.steps += static_cast<std::uint64_t>(st.steps);
    out.fEvals += static_cast<std::uint64_t>(st.f_evals);
    out.jacEvals += static_cast<std::uint64_t>(st.jac_evals);
    out.newtonIts += static_cast<std::uint64_t>(st.newton_its);
    out.errFails += static_cast<std::uint64_t>(st.err_fails);
  }
  return out;
}

ErrorNorms errorNorms(const WpSeries& run, const WpSeries& ref) {
  ErrorNorms e;
  const std::size_t n = std::min(run.values.size(), ref.values.size());
  if (n == 0) return e;
  double sum = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    double sq = 0.0;
    for (std::size_t c = 0; c < ref.values[k].size(); ++c) {
      const double d = run.values[k][c] - ref.values[k][c];
      sq += d * d;
    }
    const double ek = std::isfinite(sq) ? std::sqrt(sq) : HUGE_VAL;
    sum += ek * ek;
    e.max = std::max(e.max, ek);
    e.final = ek;
  }
  e.rms = std::sqrt(sum / static_cast<double>(n));
  return e;
}

WpResult workPrecision(Scene& scene, const WpSpec& spec, const std::function<void(const std::string&)>& log) {
  WpResult result;
  result.scene = scene.name;
  for (const auto& s : scene.systems)
    result.omegaMax = std::max(result.omegaMax, estimateStiffness(s->built ? *s->built : buildMechanics(s->spec)).omegaMax);
  // (reference and check) => the solution errors are measured against, and its own accuracy
  auto say = [&](const std::string& m) {
    if (log) log(m);
  };
  say("reference: " + spec.reference.label + " " + spec.reference.param());
  const WpSeries reference = spec.referenceFile.empty() ? runOnGrid(scene, spec.reference, spec)
                                                        : readReferenceSeries(spec.referenceFile, spec);
  if (!reference.ok) throw std::runtime_error("wp.reference failed: " + reference.failure);
  if (!spec.check.method.empty()) {
    say("check: " + spec.check.label + " " + spec.check.param());
    const WpSeries checkRun = runOnGrid(scene, spec.check, spec);
    if (!checkRun.ok) throw std::runtime_error("wp.check failed: " + checkRun.failure);
    result.referenceCheck = errorNorms(checkRun, reference);
  }
  for (const WpRun& run : spec.runs) {
    // (run) => warm-up (its series is measured), then timed repeats
    WpRow row;
    row.run = run;
    row.series = runOnGrid(scene, run, spec);
    row.error = errorNorms(row.series, reference);
    row.status = row.series.ok ? "ok" : "blow-up";
    if (!row.series.ok) row.error = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    const double meanStep = row.series.steps > 0 ? spec.until / static_cast<double>(row.series.steps) : run.dt;
    row.omegaDt = result.omegaMax * (run.dt > 0 ? run.dt : meanStep);
    std::vector<double> walls;
    const int repeats = row.series.ok && row.series.wall < 2.0 ? spec.repeats : 1;
    if (repeats == 1) walls.push_back(row.series.wall);
    else
      for (int i = 0; i < repeats; ++i) walls.push_back(runOnGrid(scene, run, spec).wall);
    row.wallMedian = median(walls);
    row.series.values.clear();
    std::ostringstream s;
    s.precision(3);
    s << run.label << " " << run.param() << ": " << row.status << ", E_rms " << row.error.rms << " m, "
      << row.wallMedian << " s";
    say(s.str());
    result.rows.push_back(std::move(row));
  }
  return result;
}

}  // namespace yardsim::studies
