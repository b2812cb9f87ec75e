#include "scene/run_settings_reader.hpp"

#include <algorithm>

#include "scene/integrator_reader.hpp"
#include "scene/yaml_source.hpp"

namespace yardsim::scene {

using models::Diagnostics;
using models::didYouMean;
using models::hasKind;
using models::ParamKind;

namespace {

const std::vector<std::string> kTraceSinks{"jsonl", "events", "chrome", "csv"};

// ({plots: [globs], static: {channel: value}}) => what the report shows
void reportSettings(Scene& s, const YAML::Node& r, const std::string& f, Diagnostics& diags) {
  if (!r.IsMap()) {
    diags.error(markOf(r, f), "report",
                "expected {plots: [channel globs], static: {channel: value}}");
    return;
  }
  checkKeys(r, {"plots", "static"}, f, "report", diags);
  if (const YAML::Node p = r["plots"]) {
    if (hasKind(p, ParamKind::StringList))
      s.report.plots = p.as<std::vector<std::string>>();
    else
      diags.error(markOf(p, f), "report.plots", "expected a list of channel globs");
  }
  if (const YAML::Node st = r["static"]) {
    if (!st.IsMap()) {
      diags.error(markOf(st, f), "report.static",
                  "expected a mapping {channel: value}, e.g. {crane.hoist.tension: 4.5e6}");
      return;
    }
    for (auto it = st.begin(); it != st.end(); ++it) {
      const std::string name = it->first.Scalar();
      if (!hasKind(it->second, ParamKind::Number))
        diags.error(
            markOf(it->second, f), "report.static." + name,
            "expected a number (the static value in the channel's unit), got " + shown(it->second));
      else {
        s.report.staticLevels.emplace_back(name, it->second.as<double>());
        s.report.staticWhere.push_back(markOf(it->first, f));
      }
    }
  }
}

}  // namespace

void readRunSettings(Scene& s, const YAML::Node& doc, const std::string& f, Diagnostics& diags) {
  auto number = [&](const YAML::Node& n, const std::string& kp, double& out, bool positive) {
    if (!hasKind(n, ParamKind::Number) || (positive ? !(n.as<double>() > 0) : n.as<double>() < 0)) {
      diags.error(markOf(n, f), kp,
                  std::string("expected a ") + (positive ? "positive" : "non-negative") +
                      " number of seconds, got " + shown(n));
      return;
    }
    out = n.as<double>();
  };
  if (const YAML::Node n = doc["name"]) s.name = n.IsScalar() ? n.Scalar() : "";
  if (s.name.empty()) s.name = s.file.stem().string();
  if (const YAML::Node n = doc["until"]) number(n, "until", s.until, false);
  if (const YAML::Node n = doc["seed"]) {
    if (hasKind(n, ParamKind::Integer))
      s.seed = n.as<long long>();
    else
      diags.error(markOf(n, f), "seed", "expected an integer, got " + shown(n));
  }
  if (const YAML::Node n = doc["integrator"]) {
    s.integratorSpec = parseIntegratorSpec(n, f, diags);
    s.integrator = s.integratorSpec.method;
    if (n.IsMap())
      if (const YAML::Node dt = n["dt"]) number(dt, "integrator.dt", s.dt, true);
    s.integratorSpec.dt = s.dt;
    s.integratorWhere = markOf(n, f);
    if (const YAML::Node c = n.IsMap() ? n["stiffness_check"] : YAML::Node()) {
      static const std::vector<std::string> kChecks{"warn", "refuse", "off"};
      const std::string v = c.IsScalar() ? c.Scalar() : "";
      if (std::find(kChecks.begin(), kChecks.end(), v) == kChecks.end())
        diags.error(markOf(c, f), "integrator.stiffness_check",
                    "expected warn, refuse or off, got " + shown(c), didYouMean(v, kChecks));
      else
        s.stiffnessCheck = v;
    }
  }
  if (const YAML::Node r = doc["record"]) {
    if (!r.IsMap()) {
      diags.error(markOf(r, f), "record", "expected {interval: seconds, channels: [globs]}");
    } else {
      checkKeys(r, {"interval", "channels"}, f, "record", diags);
      if (const YAML::Node i = r["interval"]) {
        number(i, "record.interval", s.record.interval, true);
        s.record.where = markOf(i, f);
      } else
        diags.error(markOf(r, f), "record", "missing required key 'interval' (seconds)");
      const YAML::Node ch = r["channels"];
      if (ch && hasKind(ch, ParamKind::StringList))
        s.record.channels = ch.as<std::vector<std::string>>();
      else if (ch)
        diags.error(markOf(ch, f), "record.channels", "expected a list of channel globs");
      else
        s.record.channels = {"*"};
    }
  }
  if (const YAML::Node r = doc["report"]) reportSettings(s, r, f, diags);
  // (limits: {steps, rows}) => the ceilings raised (or lowered) by the scene
  if (const YAML::Node l = doc["limits"]) {
    if (!l.IsMap()) {
      diags.error(markOf(l, f), "limits", "expected {steps: N, rows: N} (the ceilings of one run)");
    } else {
      checkKeys(l, {"steps", "rows"}, f, "limits", diags);
      for (auto [key, out] :
           {std::pair{"steps", &s.limits.steps}, std::pair{"rows", &s.limits.rows}})
        if (const YAML::Node n = l[key]) {
          if (!hasKind(n, ParamKind::Number) || !(n.as<double>() >= 1) || !(n.as<double>() <= 1e15))
            diags.error(markOf(n, f), std::string("limits.") + key,
                        "expected a number from 1 to 1e15, got " + shown(n));
          else
            *out = n.as<double>();
        }
    }
  }
  if (const YAML::Node t = doc["trace"]) {
    if (!hasKind(t, ParamKind::StringList)) {
      diags.error(markOf(t, f), "trace", "expected a list of trace sinks: jsonl, chrome, csv");
    } else {
      for (const auto& e : t) {
        const std::string sink = e.Scalar();
        if (std::find(kTraceSinks.begin(), kTraceSinks.end(), sink) == kTraceSinks.end())
          diags.error(markOf(e, f), "trace",
                      "unknown trace sink '" + sink + "'; expected jsonl, events, chrome or csv",
                      didYouMean(sink, kTraceSinks));
        else
          s.trace.push_back(sink);
      }
    }
  }
}

}  // namespace yardsim::scene
