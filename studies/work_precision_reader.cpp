#include "studies/work_precision_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "dynamics/integrators/factory.hpp"
#include "models/diagnostics.hpp"
#include "scene/yaml_source.hpp"

namespace yardsim::studies {

using models::Diagnostics;
using scene::Scene;
using scene::checkKeys;
using scene::markOf;
using scene::shown;

std::string WpRun::param() const {
  std::ostringstream s;
  s.precision(6);
  if (!(dt > 0) && !(rtol > 0)) return "";  // a published reference
  if (rtol > 0) s << "rtol=" << rtol;
  else s << "dt=" << dt;
  return s.str();
}

namespace {
constexpr int kMaxLevels = 20;     // halvings of dt0 in one sweep: 2^19 times the first run's steps
constexpr int kMaxRepeats = 1000;  // timed runs after the warm-up
constexpr double kMinRtol = 1e-15;  // below the double precision of the state

// (number) => "1.2e+07" style text for messages
std::string shortNumber(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}
}  // namespace

WpSpec parseWpSpec(const Scene& scene, Diagnostics& d) {
  WpSpec spec;
  const std::string f = scene.file.string();
  const YAML::Node doc = YAML::LoadFile(f);
  const YAML::Node wp = doc["wp"];
  if (!wp || !wp.IsMap()) {
    d.error(markOf(wp ? wp : doc, f), "wp",
            "the scene has no `wp:` block: give channels, methods and a reference (docs/numerics.md)");
    return spec;
  }
  checkKeys(wp, {"channels", "interval", "until", "methods", "reference", "check", "repeats"}, f, "wp", d);
  // (node, key) => a positive number, or an error there
  auto positive = [&](const YAML::Node& n, const std::string& key, double fallback) {
    double v = 0.0;
    if (!n) return fallback;
    if (!n.IsScalar() || !YAML::convert<double>::decode(n, v) || !(v > 0) || !std::isfinite(v)) {
      d.error(markOf(n, f), key, "expected a positive number, got " + shown(n));
      return fallback;
    }
    return v;
  };
  // (node, key) => its text when it is a scalar, or an error there (a list or a map where a
  // channel, label or file name belongs was an internal error: tests/fuzz/mutate.py)
  auto nameOf = [&](const YAML::Node& n, const std::string& key) {
    if (n.IsScalar()) return n.Scalar();
    d.error(markOf(n, f), key, "expected a name, got " + shown(n));
    return std::string();
  };
  const YAML::Node ch = wp["channels"];
  if (!ch || !ch.IsSequence() || ch.size() == 0)
    d.error(markOf(ch ? ch : wp, f), "wp.channels", "expected a list of channel names (see `yardsim list-channels`)");
  else
    for (std::size_t i = 0; i < ch.size(); ++i)
      spec.channels.push_back(nameOf(ch[i], "wp.channels[" + std::to_string(i) + "]"));
  spec.interval = positive(wp["interval"], "wp.interval", scene.record.interval);
  spec.until = positive(wp["until"], "wp.until", scene.until);
  if (!(spec.interval > 0)) d.error(markOf(wp, f), "wp.interval", "missing: the output grid step, s");
  if (!std::isfinite(spec.until)) d.error(markOf(wp, f), "wp.until", "missing: the scene runs without end; give wp.until");
  // (grid) => every run records until / interval rows: held to the scene's ceiling
  if (spec.interval > 0 && std::isfinite(spec.until) && spec.until / spec.interval > scene.limits.rows)
    d.error(markOf(wp["interval"] ? wp["interval"] : wp, f), "wp.interval",
            "an interval of " + shortNumber(spec.interval) + " s over wp.until = " + shortNumber(spec.until) +
                " s is " + shortNumber(spec.until / spec.interval) + " rows per run, above the ceiling of " +
                shortNumber(scene.limits.rows) + "; raise it with the root key `limits: {rows: " +
                shortNumber(spec.until / spec.interval) + "}`");
  // (node, key, range) => a whole number in [1, most], or an error there with the range
  auto count = [&](const YAML::Node& n, const std::string& key, int most, int fallback) {
    const double v = positive(n, key, fallback);
    if (v == std::floor(v) && v <= most) return static_cast<int>(v);
    d.error(markOf(n, f), key, "expected a whole number from 1 to " + std::to_string(most) + ", got " + shown(n));
    return fallback;
  };
  spec.repeats = count(wp["repeats"], "wp.repeats", kMaxRepeats, 3);
  // (method node, key) => its name, or an error naming the methods there are
  auto method = [&](const YAML::Node& n, const std::string& key) {
    const std::string name = n.IsScalar() ? n.Scalar() : "";
    const auto known = dynamics::integratorMethodNames();
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      d.error(markOf(n, f), key, "unknown integrator method " + shown(n) + " (expected one of " + list + ")",
              models::didYouMean(name, known));
    }
    return name;
  };
  // (one run: method and dt or rtol) => the run
  auto single = [&](const YAML::Node& n, const std::string& key) {
    WpRun r;
    if (!n || !n.IsMap() || !n["method"]) {
      d.error(markOf(n ? n : wp, f), key, "expected {method: name, dt: s} or {method: name, rtol: x}");
      return r;
    }
    r.method = r.label = method(n["method"], key + ".method");
    if (n["label"]) r.label = nameOf(n["label"], key + ".label");
    r.dt = positive(n["dt"], key + ".dt", 0.0);
    r.rtol = positive(n["rtol"], key + ".rtol", 0.0);
    if (!(r.dt > 0) && !(r.rtol > 0)) d.error(markOf(n, f), key, "give dt (fixed step) or rtol (adaptive)");
    if (r.dt > 0 && std::isfinite(spec.until) && spec.until / r.dt > scene.limits.steps)
      d.error(markOf(n["dt"], f), key + ".dt",
              "a step of " + shortNumber(r.dt) + " s over wp.until = " + shortNumber(spec.until) + " s is " +
                  shortNumber(spec.until / r.dt) + " steps, above the ceiling of " + shortNumber(scene.limits.steps) +
                  "; raise it with the root key `limits: {steps: " + shortNumber(spec.until / r.dt) + "}`");
    if (r.rtol > 0 && !(r.rtol <= 1.0 && r.rtol >= kMinRtol))
      d.error(markOf(n["rtol"], f), key + ".rtol",
              "expected a tolerance from " + shortNumber(kMinRtol) + " to 1, got " + shown(n["rtol"]));
    r.extra = YAML::Clone(n);
    for (const char* k : {"method", "label", "dt", "rtol", "dt0", "levels"}) r.extra.remove(k);
    return r;
  };
  const YAML::Node ref = wp["reference"];
  if (ref && ref.IsMap() && ref["file"]) {
    // (reference: {file}) => a published solution, relative to the scene file
    checkKeys(ref, {"file"}, f, "wp.reference", d);
    const std::string file = nameOf(ref["file"], "wp.reference.file");
    const std::filesystem::path path = scene.file.parent_path() / file;
    if (!std::filesystem::is_regular_file(path))
      d.error(markOf(ref["file"], f), "wp.reference.file", "no such file: " + path.string());
    spec.referenceFile = path.string();
    spec.reference.label = spec.reference.method = "file " + file;
  } else {
    spec.reference = single(ref, "wp.reference");
  }
  if (wp["check"] || spec.referenceFile.empty()) spec.check = single(wp["check"], "wp.check");
  if (!spec.check.method.empty() && spec.check.method == spec.reference.method)
    d.error(markOf(wp["check"], f), "wp.check",
            "the check must use a different method than the reference (" + spec.reference.method +
                "), so that it is an independent confirmation");
  const YAML::Node ms = wp["methods"];
  if (!ms || !ms.IsSequence() || ms.size() == 0) {
    d.error(markOf(ms ? ms : wp, f), "wp.methods", "expected a list of {method, dt0, levels} or {method, rtol: [hi, lo]}");
    return spec;
  }
  for (std::size_t i = 0; i < ms.size(); ++i) {
    const YAML::Node m = ms[i];
    const std::string key = "wp.methods[" + std::to_string(i) + "]";
    if (!m.IsMap() || !m["method"]) {
      d.error(markOf(m, f), key, "expected {method: name, dt0: s, levels: n} or {method: name, rtol: [hi, lo]}");
      continue;
    }
    WpRun base;
    base.method = base.label = method(m["method"], key + ".method");
    if (m["label"]) base.label = nameOf(m["label"], key + ".label");
    base.extra = YAML::Clone(m);
    for (const char* k : {"method", "label", "dt", "rtol", "dt0", "levels"}) base.extra.remove(k);
    if (const YAML::Node rt = m["rtol"]) {
      // (rtol: [hi, lo]) => one run per decade from hi down to lo
      if (!rt.IsSequence() || rt.size() != 2) {
        d.error(markOf(rt, f), key + ".rtol", "expected [highest, lowest], e.g. [1.0e-3, 1.0e-10]");
        continue;
      }
      const double hi = positive(rt[0], key + ".rtol[0]", 1e-3), lo = positive(rt[1], key + ".rtol[1]", 1e-10);
      if (!(hi <= 1.0 && lo >= kMinRtol && lo <= hi)) {
        d.error(markOf(rt, f), key + ".rtol",
                "expected [highest, lowest] with 1 >= highest >= lowest >= " + shortNumber(kMinRtol) + ", got " +
                    shown(rt));
        continue;
      }
      for (double r = hi; r >= lo * (1 - 1e-9); r /= 10.0) {
        WpRun run = base;
        run.rtol = r;
        spec.runs.push_back(run);
      }
    } else {
      const double dt0 = positive(m["dt0"], key + ".dt0", 0.0);
      const int levels = count(m["levels"], key + ".levels", kMaxLevels, 4);
      if (!(dt0 > 0)) {
        d.error(markOf(m, f), key, "missing dt0 (the longest step of the sweep, s) or rtol");
        continue;
      }
      // (dt0, levels) => the shortest step's count over wp.until, held to the scene's ceiling
      const double steps = spec.until / (dt0 / std::pow(2.0, levels - 1));
      if (std::isfinite(spec.until) && steps > scene.limits.steps) {
        d.error(markOf(m["levels"] ? m["levels"] : m["dt0"], f), key + (m["levels"] ? ".levels" : ".dt0"),
                "the shortest step dt0 / 2^" + std::to_string(levels - 1) + " over wp.until = " +
                    shortNumber(spec.until) + " s is " + shortNumber(steps) + " steps, above the ceiling of " +
                    shortNumber(scene.limits.steps) +
                    "; fewer levels, a longer dt0 or wp.until, or raise the ceiling with the root key "
                    "`limits: {steps: " + shortNumber(steps) + "}`");
        continue;
      }
      for (int k = 0; k < levels; ++k) {
        WpRun run = base;
        run.dt = dt0 / std::pow(2.0, k);
        spec.runs.push_back(run);
      }
    }
  }
  // (fixed steps) => each divides the grid interval, so that samples fall on step times
  std::vector<const WpRun*> all{&spec.reference, &spec.check};
  for (const auto& r : spec.runs) all.push_back(&r);
  for (const WpRun* r : all) {
    if (!(r->dt > 0) || !(spec.interval > 0)) continue;
    const double ratio = spec.interval / r->dt;
    if (std::abs(ratio - std::round(ratio)) > 1e-6 * ratio || std::round(ratio) < 1)
      d.error(markOf(wp, f), "wp.interval",
              "the grid interval " + std::to_string(spec.interval) + " s is not a multiple of the step " +
                  std::to_string(r->dt) + " s of " + r->label + ": samples must fall on step times");
  }
  return spec;
}

}  // namespace yardsim::studies
