#include "run/run_summary.hpp"

#include <fstream>
#include <stdexcept>

#include "devs/trace_format.hpp"
#include "mechanics/stiffness_estimate.hpp"
#include "models/channels.hpp"
#include "models/multibody/multibody_model.hpp"
#include "run/timeseries_writer.hpp"

namespace yardsim::run {

using models::MultibodyModel;
using scene::Instance;
using scene::Scene;
namespace {

using devs::appendJsonNumber;
using devs::appendJsonString;

// (instance tree) => "{path, kind}" of every actor: an atomic with `started` and `finished` ports
void actors(const Instance& in, std::string& out) {
  if (in.atomic()) {
    if (in.port("started") && in.port("finished")) {
      out += out.back() == '[' ? "{\"path\":" : ",{\"path\":";
      appendJsonString(out, in.path);
      out += ",\"kind\":";
      appendJsonString(out, in.type->name);
      out += "}";
    }
    return;
  }
  for (const auto& c : in.children) actors(*c, out);
}

// (model tree) => "{model, method, dt, water_level}" of every multibody model (water_level:
// where it has a sea)
void systems(const devs::Model& m, std::string& out) {
  if (!m.isAtomic()) {
    for (const auto& c : static_cast<const devs::Coupled&>(m).components()) systems(*c, out);
    return;
  }
  if (const auto* mb = dynamic_cast<const MultibodyModel*>(&m)) {
    out += out.back() == '[' ? "{\"model\":" : ",{\"model\":";
    appendJsonString(out, mb->path());
    out += ",\"method\":";
    appendJsonString(out, mb->options().integrator.method);
    out += ",\"dt\":";
    appendJsonNumber(out, mb->options().dt);
    // (a sea, or a hull floating in the default one) => the still-water level, m: the replay's
    // water surface
    const auto& sea = mb->builtMechanics().environment;
    if (sea.hasWater || !sea.hulls.empty()) {
      out += ",\"water_level\":";
      appendJsonNumber(out, sea.water.level);
    }
    // (the system at its start) => its stiffest mode: what the stiffness guard judged
    try {
      const mechanics::StiffnessEstimate e = mechanics::estimateStiffness(mb->builtMechanics(), mb->system().servo());
      out += ",\"omega_max\":";
      appendJsonNumber(out, e.omegaMax);
      out += ",\"damping_ratio\":";
      appendJsonNumber(out, e.dampingRatio);
      out += ",\"stiffest_body\":";
      appendJsonString(out, e.body);
    } catch (const std::exception&) {  // accelerations not finite at the start: the run says so
    }
    // (marched providers: rankine_td's free surface) => their own step beside its stability limit:
    // what the stiffness guard judged beside omega_max
    std::string marching;
    for (const auto& h : sea.hydrodynamics) {
      if (!h.marchingStep) continue;
      try {
        const forces::hydro::MarchingStep step = h.marchingStep();
        marching += marching.empty() ? "{\"name\":" : ",{\"name\":";
        appendJsonString(marching, h.name);
        marching += ",\"scheme\":";
        appendJsonString(marching, step.scheme);
        marching += ",\"step\":";
        appendJsonNumber(marching, step.step);
        marching += ",\"limit\":";
        appendJsonNumber(marching, step.limit);
        marching += ",\"lambda_max\":";
        appendJsonNumber(marching, step.lambdaMax);
        marching += "}";
      } catch (const std::exception&) {  // the guard reported it before the run
      }
    }
    if (!marching.empty()) out += ",\"marching\":[" + marching + "]";
    out += "}";
  }
}

// (model tree, report's static levels) => per rope of every multibody model: its channel name,
// parts, peak tension of one part and when, the static tension (the report's static level of
// its tension channel, else its tension at the start), peak/static, MBL and peak/MBL
void ropes(const devs::Model& m, const Scene& scene, std::string& out) {
  if (!m.isAtomic()) {
    for (const auto& c : static_cast<const devs::Coupled&>(m).components()) ropes(*c, scene, out);
    return;
  }
  const auto* mb = dynamic_cast<const MultibodyModel*>(&m);
  if (mb == nullptr) return;
  const auto& x = mb->state().x;
  for (std::size_t r = 0; r < mb->system().ropes().size(); ++r) {
    const forces::Rope& rope = mb->rope(r);
    const std::string name = (mb->channelNamesArePaths() ? "" : mb->path() + ".") + rope.name();
    double statical = mb->initialTension()[r];
    for (const auto& [channel, level] : scene.report.staticLevels)
      if (channel == name + ".tension") statical = level;
    out += out.back() == '[' ? "{\"name\":" : ",{\"name\":";
    appendJsonString(out, name);
    auto number = [&](const char* k, double v) {
      out += std::string(",\"") + k + "\":";
      appendJsonNumber(out, v);
    };
    number("parts", rope.parts());
    number("peak", x.peakTension[r]);
    number("peak_time", x.peakTime[r]);
    number("static", statical);
    number("peak_over_static", statical > 0 ? x.peakTension[r] / statical : 0.0);
    const double mbl = rope.properties().breakingLoad.value_or(0.0);
    number("mbl", mbl);
    number("mbl_utilisation", mbl > 0 ? x.peakTension[r] / mbl : 0.0);
    out += "}";
  }
}

// (alarm, model tree, its channels) => the SI unit of its worst value: N for loads over a limit,
// m for distances and rope lengths, the watched channel's unit for a crossing ("" if unknown)
std::string alarmUnit(const Alarm& a, const devs::Model& root,
                      const std::vector<models::Channel>& channels) {
  if (a.kind == "over_mbl" || a.kind == "over_hook_load") return "N";
  if (a.kind == "clearance_below" || a.kind == "touched" || a.kind == "contact" ||
      a.kind == "release" || a.kind == "slack" || a.kind == "taut")
    return "m";
  if (a.kind != "crossed") return "";
  // (the watch of that name in its multibody model) => the channel of its element and quantity
  const devs::Model* m = &root;
  std::vector<const devs::Model*> todo{&root};
  const MultibodyModel* mb = nullptr;
  while (!todo.empty() && mb == nullptr) {
    m = todo.back();
    todo.pop_back();
    if (!m->isAtomic())
      for (const auto& c : static_cast<const devs::Coupled&>(*m).components())
        todo.push_back(c.get());
    else if (const auto* x = dynamic_cast<const MultibodyModel*>(m); x && x->path() == a.model)
      mb = x;
  }
  if (mb == nullptr) return "";
  for (const auto& w : mb->builtMechanics().watches) {
    if (w.name != a.element) continue;
    const std::string local = w.element + "." + w.quantity;
    for (const auto& c : channels)
      if (c.name == local || c.name == mb->path() + "." + local) return c.unit;
  }
  return "";
}

}  // namespace

std::string runSummaryJson(const Scene& scene, const devs::Model& root, const RunFacts& f) {
  std::string o = "{\"yardsim\":";
  appendJsonString(o, kVersion);
  auto key = [&](const char* k) { o += std::string(",\"") + k + "\":"; };
  auto text = [&](const char* k, const std::string& v) { key(k); appendJsonString(o, v); };
  auto number = [&](const char* k, double v) { key(k); appendJsonNumber(o, v); };
  text("scene", scene.name);
  text("file", scene.file.string());
  text("scene_sha256", scene.sha256);
  text("integrator", scene.integrator);
  number("step", scene.dt);
  number("until", f.until);
  number("t_end", f.tEnd);
  number("wall", f.wall);
  number("real_time_factor", f.wall > 0 ? f.tEnd / f.wall : 0.0);
  text("status", f.status);
  text("message", f.message);
  number("record_interval", scene.record.interval);
  number("replay_interval", f.replayInterval);
  key("systems");
  o += "[";
  systems(root, o);
  o += "]";
  key("ropes");
  o += "[";
  ropes(root, scene, o);
  o += "]";
  key("alarms");
  o += "[";
  const auto channels =
      f.alarms.empty() ? std::vector<models::Channel>{} : models::collectChannels(root);
  for (std::size_t i = 0; i < f.alarms.size(); ++i) {
    const Alarm& a = f.alarms[i];
    o += i ? ",{\"model\":" : "{\"model\":";
    appendJsonString(o, a.model);
    text("element", a.element);
    text("kind", a.kind);
    text("severity", a.severity);
    number("first", a.first);
    number("count", static_cast<double>(a.count));
    number("worst", a.worst);
    number("worst_at", a.worstAt);
    text("unit", alarmUnit(a, root, channels));
    text("message", a.message);
    o += "}";
  }
  o += "]";
  key("actors");
  o += "[";
  actors(scene.root, o);
  o += "]";
  key("report");
  o += "{\"plots\":[";
  for (std::size_t i = 0; i < scene.report.plots.size(); ++i)
    appendJsonString(o += i ? "," : "", scene.report.plots[i]);
  o += "],\"static\":{";
  for (std::size_t i = 0; i < scene.report.staticLevels.size(); ++i) {
    appendJsonString(o += i ? "," : "", scene.report.staticLevels[i].first);
    appendJsonNumber(o += ":", scene.report.staticLevels[i].second);
  }
  return o + "}}}\n";
}

void writeRunSummary(const std::filesystem::path& file, const Scene& scene,
                     const devs::Model& root, const RunFacts& facts) {
  std::ofstream out(file);
  out << runSummaryJson(scene, root, facts);
  if (!out) throw std::runtime_error("cannot write '" + file.string() + "'");
}

}  // namespace yardsim::run
