#include "studies/sweep_spec.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numeric>
#include <optional>

#include "scene/yaml_source.hpp"

namespace yardsim::studies {

namespace fs = std::filesystem;
using scene::checkKeys;
using scene::joinKey;
using scene::markOf;
using scene::shown;

namespace {

const std::vector<std::string> kSweepKeys{"scene",       "vary",    "mode",   "samples",
                                          "seed",        "collect", "limits", "case_timeout",
                                          "operability", "series"};
const std::vector<std::string> kOps{"max", "min", "absmax", "mean", "final"};

// (scalar node) => its number, or nullopt
std::optional<double> number(const YAML::Node& n) {
  if (!n || !n.IsScalar()) return std::nullopt;
  const std::string& s = n.Scalar();
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// (scalar node) => whether it is written as a whole number ("3", "-2")
bool wholeText(const YAML::Node& n) {
  if (!n.IsScalar()) return false;
  const std::string& t = n.Scalar();
  const std::size_t first = !t.empty() && t[0] == '-' ? 1 : 0;
  return t.size() > first && std::all_of(t.begin() + static_cast<std::ptrdiff_t>(first), t.end(),
                                         [](char c) { return c >= '0' && c <= '9'; });
}

// (node under vary.NAME) => the parameter's values; mistakes in diags
SweepParam readParam(const std::string& name, const YAML::Node& v, const std::string& f,
                     Diagnostics& d) {
  SweepParam p;
  p.name = name;
  p.where = markOf(v, f);
  const std::string kp = joinKey("sweep.vary", name);
  if (v.IsSequence()) {
    p.integer = v.size() > 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const auto x = number(v[i]);
      if (!x) {
        d.error(markOf(v[i], f), kp + "[" + std::to_string(i) + "]",
                "expected a number, got " + shown(v[i]));
        continue;
      }
      p.values.push_back(*x);
      p.integer = p.integer && wholeText(v[i]);
    }
    if (v.size() == 0) d.error(p.where, kp, "expected at least one value");
  } else if (v.IsMap() && v["count"] && !v["from"]) {
    checkKeys(v, {"count"}, f, kp, d);
    const auto n = number(v["count"]);
    if (!n || *n < 1 || *n != std::floor(*n) || *n > 1e6)
      d.error(markOf(v["count"], f), kp + ".count",
              "expected a whole number of seeds >= 1, got " + shown(v["count"]));
    else
      for (int i = 1; i <= static_cast<int>(*n); ++i) p.values.push_back(i);
    p.integer = true;
  } else if (v.IsMap()) {
    checkKeys(v, {"from", "to", "step", "count"}, f, kp, d);
    const auto from = number(v["from"]), to = number(v["to"]);
    if (!from)
      d.error(v["from"] ? markOf(v["from"], f) : p.where, kp + ".from", "expected a number");
    if (!to) d.error(v["to"] ? markOf(v["to"], f) : p.where, kp + ".to", "expected a number");
    const auto step = number(v["step"]), count = number(v["count"]);
    if (from && to && step && !count) {
      if (*step <= 0.0 || *to < *from || (*to - *from) / *step > 1e6)
        d.error(markOf(v["step"], f), kp + ".step",
                "expected a step > 0 with to >= from and at most 1e6 values");
      else
        for (double k = 0; *from + k * *step <= *to + 1e-9 * *step; ++k)
          p.values.push_back(*from + k * *step);
    } else if (from && to && count && !step) {
      if (*count < 1 || *count != std::floor(*count) || *count > 1e6)
        d.error(markOf(v["count"], f), kp + ".count", "expected a whole number of values >= 1");
      else if (*count == 1)
        p.values.push_back(*from);
      else
        for (int k = 0; k < static_cast<int>(*count); ++k)
          p.values.push_back(*from + (*to - *from) * k / (*count - 1.0));
    } else if (from && to) {
      d.error(p.where, kp, "expected either `step` or `count` with from and to");
    }
  } else {
    d.error(p.where, kp,
            "expected a list of values, {from, to, step}, {from, to, count} or {count: n} (seeds)");
  }
  if (!p.values.empty()) {
    p.from = *std::min_element(p.values.begin(), p.values.end());
    p.to = *std::max_element(p.values.begin(), p.values.end());
  }
  return p;
}

// (text "op(glob)") => the collect spec, or nullopt
std::optional<CollectSpec> parseCollect(const std::string& text) {
  // (text) => blanks? op(lowercase letters) blanks? "(" blanks? glob(no blank, no paren)
  // blanks? ")" blanks?, read by hand (std::regex trips GCC 12's -Wmaybe-uninitialized)
  auto blank = [](char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
  };
  std::size_t i = 0;
  const std::size_t n = text.size();
  auto skip = [&] {
    while (i < n && blank(text[i])) ++i;
  };
  skip();
  const std::size_t opBegin = i;
  while (i < n && text[i] >= 'a' && text[i] <= 'z') ++i;
  const std::string op = text.substr(opBegin, i - opBegin);
  skip();
  if (op.empty() || i >= n || text[i] != '(') return std::nullopt;
  ++i;
  skip();
  const std::size_t globBegin = i;
  while (i < n && !blank(text[i]) && text[i] != '(' && text[i] != ')') ++i;
  const std::string glob = text.substr(globBegin, i - globBegin);
  skip();
  if (glob.empty() || i >= n || text[i] != ')') return std::nullopt;
  ++i;
  skip();
  if (i != n) return std::nullopt;
  if (std::find(kOps.begin(), kOps.end(), op) == kOps.end()) return std::nullopt;
  CollectSpec c;
  c.op = op;
  c.glob = glob;
  c.text = c.op + "(" + c.glob + ")";
  return c;
}

// (sweep node) => collect and limits into spec
void readCollect(SweepSpec& s, const YAML::Node& sw, const std::string& f, Diagnostics& d) {
  const YAML::Node col = sw["collect"];
  if (col && !col.IsSequence())
    d.error(markOf(col, f), "sweep.collect", "expected a list like [max(hoist.tension)]");
  if (col && col.IsSequence())
    for (std::size_t i = 0; i < col.size(); ++i) {
      auto c = col[i].IsScalar() ? parseCollect(col[i].Scalar()) : std::nullopt;
      if (!c) {
        d.error(
            markOf(col[i], f), "sweep.collect[" + std::to_string(i) + "]",
            "expected OP(GLOB) with OP one of max, min, absmax, mean, final, got " + shown(col[i]));
        continue;
      }
      c->where = markOf(col[i], f);
      s.collect.push_back(*c);
    }
  const YAML::Node lim = sw["limits"];
  if (lim && !lim.IsMap())
    d.error(markOf(lim, f), "sweep.limits", "expected a mapping like {max(hoist.tension): 4.0e6}");
  if (!lim || !lim.IsMap()) return;
  for (auto it = lim.begin(); it != lim.end(); ++it) {
    const std::string key = it->first.as<std::string>();
    const std::string kp = joinKey("sweep.limits", key);
    auto c = parseCollect(key);
    if (!c) {
      d.error(markOf(it->first, f), kp, "expected OP(GLOB) as the key, like max(hoist.tension)");
      continue;
    }
    LimitSpec l;
    l.collect = c->text;
    l.where = markOf(it->second, f);
    l.upper = c->op != "min";
    std::optional<double> b = number(it->second);
    if (it->second.IsMap()) {
      checkKeys(it->second, {"max", "min"}, f, kp, d);
      l.upper = static_cast<bool>(it->second["max"]);
      b = number(it->second[l.upper ? "max" : "min"]);
    }
    if (!b) {
      d.error(
          l.where, kp,
          "expected a number (an upper bound; a lower one for min(...)) or {max: x} / {min: x}");
      continue;
    }
    l.bound = *b;
    s.limits.push_back(l);
    const bool known = std::any_of(s.collect.begin(), s.collect.end(),
                                   [&](const auto& x) { return x.text == c->text; });
    if (!known) {  // a limit collects its own quantity
      c->where = markOf(it->first, f);
      s.collect.push_back(*c);
    }
  }
}

// (spec, sweep node) => mode, samples, seed, time-out, operability checked
void readSettings(SweepSpec& s, const YAML::Node& sw, const std::string& f, Diagnostics& d) {
  if (const YAML::Node m = sw["mode"]) {
    s.mode = m.IsScalar() ? m.Scalar() : "";
    if (s.mode != "grid" && s.mode != "latin_hypercube" && s.mode != "list")
      d.error(markOf(m, f), "sweep.mode", "expected grid, latin_hypercube or list, got " + shown(m),
              models::didYouMean(s.mode, {"grid", "latin_hypercube", "list"}));
  }
  if (const YAML::Node n = sw["samples"]) {
    const auto v = number(n);
    if (!v || *v < 1 || *v != std::floor(*v))
      d.error(markOf(n, f), "sweep.samples", "expected a whole number >= 1");
    else
      s.samples = static_cast<std::size_t>(*v);
  }
  if (s.mode == "latin_hypercube" && s.samples == 0)
    d.error(markOf(sw, f), "sweep.samples",
            "mode latin_hypercube needs `samples:` (the number of cases)");
  if (const YAML::Node n = sw["seed"]) {
    const auto v = number(n);
    if (!v || *v < 0 || *v != std::floor(*v))
      d.error(markOf(n, f), "sweep.seed", "expected a whole number >= 0");
    else
      s.seed = static_cast<std::uint64_t>(*v);
  }
  if (const YAML::Node n = sw["case_timeout"]) {
    const auto v = number(n);
    if (!v || *v <= 0)
      d.error(markOf(n, f), "sweep.case_timeout", "expected a wall time in s > 0");
    else
      s.caseTimeout = *v;
  }
  if (const YAML::Node n = sw["series"]) {
    if (!n.IsScalar() || (n.Scalar() != "true" && n.Scalar() != "false"))
      d.error(markOf(n, f), "sweep.series", "expected true or false");
    else
      s.series = n.Scalar() == "true";
  }
  if (s.mode == "list")
    for (const auto& p : s.params)
      if (p.values.size() != s.params.front().values.size())
        d.error(p.where, "sweep.vary." + p.name,
                "mode list pairs the i-th values: expected " +
                    std::to_string(s.params.front().values.size()) + " values like " +
                    s.params.front().name + ", got " + std::to_string(p.values.size()));
  std::vector<std::string> names;
  for (const auto& p : s.params) names.push_back(p.name);
  if (const YAML::Node o = sw["operability"]) {
    if (!o.IsSequence() || o.size() != 2)
      d.error(markOf(o, f), "sweep.operability", "expected two varied parameters");
    else
      for (std::size_t i = 0; i < 2; ++i) {
        const std::string n = o[i].IsScalar() ? o[i].Scalar() : "";
        if (std::find(names.begin(), names.end(), n) == names.end())
          d.error(markOf(o[i], f), "sweep.operability[" + std::to_string(i) + "]",
                  "not a varied parameter: " + shown(o[i]), models::didYouMean(n, names));
        s.operability.push_back(n);
      }
  } else {
    for (std::size_t i = 0; i < std::min<std::size_t>(2, names.size()); ++i)
      s.operability.push_back(names[i]);
  }
}

// (state) => the next of a splitmix64 sequence, the same on every platform
std::uint64_t splitmix(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// (spec with its scene) => every varied name a root param of the scene (or its seed)
void checkNames(SweepSpec& s, Diagnostics& d) {
  Diagnostics ignored;  // the scene's own mistakes are reported when a case loads it
  const auto doc = scene::readYamlFile(s.scene, {}, "", ignored);
  if (!doc) return;
  std::vector<std::string> declared;
  if (const YAML::Node ps = (*doc)["params"]; ps && ps.IsMap())
    for (auto it = ps.begin(); it != ps.end(); ++it)
      declared.push_back(it->first.as<std::string>());
  for (auto& p : s.params) {
    if (std::find(declared.begin(), declared.end(), p.name) != declared.end()) continue;
    if (p.name == "seed") {
      p.sceneSeed = true;
      continue;
    }
    std::string all;
    for (const auto& n : declared) all += (all.empty() ? "" : ", ") + n;
    d.error(p.where, "sweep.vary." + p.name,
            "no root parameter '" + p.name + "' in " + s.scene.string() +
                "; its `params:` declare: " + (all.empty() ? "(none)" : all),
            models::didYouMean(p.name, declared));
  }
}

}  // namespace

SweepSpec readSweepSpec(const fs::path& file, Diagnostics& d) {
  SweepSpec s;
  s.file = file;
  const std::string f = file.string();
  const auto doc = scene::readYamlFile(file, {}, "", d);
  if (!doc) return s;
  checkKeys(*doc, {"sweep"}, f, "", d);
  const YAML::Node sw = (*doc)["sweep"];
  if (!sw || !sw.IsMap()) {
    d.error(sw ? markOf(sw, f) : SourceMark{f, 1, 1}, "sweep",
            "expected a `sweep:` mapping (docs/sweeps.md)");
    return s;
  }
  checkKeys(sw, kSweepKeys, f, "sweep", d);
  const YAML::Node sc = sw["scene"];
  if (!sc || !sc.IsScalar()) {
    d.error(sc ? markOf(sc, f) : markOf(sw, f), "sweep.scene",
            "expected the scene file (relative to this file)");
  } else {
    s.scene = fs::path(sc.Scalar()).is_absolute() ? fs::path(sc.Scalar())
                                                  : file.parent_path() / sc.Scalar();
    std::error_code ec;
    if (!fs::is_regular_file(s.scene, ec))
      d.error(markOf(sc, f), "sweep.scene", "no scene file " + s.scene.string());
  }
  const YAML::Node vary = sw["vary"];
  if (!vary || !vary.IsMap() || vary.size() == 0)
    d.error(vary ? markOf(vary, f) : markOf(sw, f), "sweep.vary",
            "expected a mapping of root params to their values");
  else
    for (auto it = vary.begin(); it != vary.end(); ++it)
      s.params.push_back(readParam(it->first.as<std::string>(), it->second, f, d));
  if (!s.scene.empty() && fs::is_regular_file(s.scene)) checkNames(s, d);
  readCollect(s, sw, f, d);
  readSettings(s, sw, f, d);
  return s;
}

std::vector<SweepCase> expandCases(const SweepSpec& s) {
  std::vector<SweepCase> cases;
  if (s.params.empty()) return cases;
  if (s.mode == "list") {
    for (std::size_t i = 0; i < s.params.front().values.size(); ++i) {
      SweepCase c{i, {}};
      for (const auto& p : s.params) c.values.push_back(p.values.at(i));
      cases.push_back(c);
    }
  } else if (s.mode == "latin_hypercube") {
    // (seed) => per parameter a random permutation of the n strata and a point inside each
    std::uint64_t state = s.seed;
    const auto unit = [&] { return static_cast<double>(splitmix(state) >> 11) * 0x1.0p-53; };
    const std::size_t n = s.samples;
    cases.resize(n);
    for (std::size_t i = 0; i < n; ++i) cases[i].id = i;
    for (const auto& p : s.params) {
      std::vector<std::size_t> perm(n);
      std::iota(perm.begin(), perm.end(), 0);
      for (std::size_t i = n; i > 1; --i) std::swap(perm[i - 1], perm[splitmix(state) % i]);
      for (std::size_t i = 0; i < n; ++i) {
        const double u = (static_cast<double>(perm[i]) + unit()) / static_cast<double>(n);
        const double x = p.from + (p.to - p.from) * u;
        cases[i].values.push_back(p.integer ? std::round(x) : x);
      }
    }
  } else {
    std::size_t total = 1;
    for (const auto& p : s.params) total *= p.values.size();
    for (std::size_t i = 0; i < total; ++i) {
      SweepCase c{i, std::vector<double>(s.params.size())};
      std::size_t rest = i;
      for (std::size_t k = s.params.size(); k-- > 0;) {
        c.values[k] = s.params[k].values[rest % s.params[k].values.size()];
        rest /= s.params[k].values.size();
      }
      cases.push_back(c);
    }
  }
  return cases;
}

std::string formatValue(double value, bool integer) {
  if (integer) return std::to_string(static_cast<long long>(std::llround(value)));
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, r.ptr);
}

}  // namespace yardsim::studies
