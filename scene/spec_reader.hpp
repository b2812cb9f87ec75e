#pragma once
// Reading a mechanics mapping with errors at their YAML nodes: keys checked against a list (with
// "did you mean"), numbers, lists, vectors and poses, each problem reported once through the
// MechanicsReport with the key path below the parameter. Shared by mechanics_spec.cpp (bodies,
// joints, ropes) and floating_spec.cpp (water, wind, hydrostatics, flow loads, damping).
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "scene/mechanics_reader.hpp"
#include "dynamics/rotation.hpp"
#include "models/diagnostics.hpp"
#include "mechanics/description.hpp"

namespace yardsim::scene::spec {

using dynamics::Vector3;
using models::didYouMean;

constexpr double kDeg = M_PI / 180.0;
// The largest coordinate or size a scene accepts, m (docs/robustness.md)
constexpr double kMaxSceneLength = 1.0e6;

struct Reader {
  const MechanicsReport& report;
  std::string param;

  // (node, key path, message) => reported at the node; a node that is not there (a missing key
  // read from a mapping) is reported at the parameter's place
  void fail(const YAML::Node& at, const std::string& key, const std::string& msg) const {
    report(param, at.IsDefined() ? marked(at) : YAML::Node(), key, msg);
  }
  // (mapping, key, key path, what it holds) => whether the mapping has the key; if not, a
  // "missing required key" at the mapping
  bool required(const YAML::Node& map, const char* name, const std::string& key,
                const std::string& what) const {
    if (map.IsMap() && map[name]) return true;
    fail(map, key, std::string("missing required key '") + name + "' (" + what + ")");
    return false;
  }
  // (node, key path, fallback) => the text of a scalar (a name); a list or mapping is reported
  std::string text(const YAML::Node& n, const std::string& key, const std::string& fallback) const {
    if (!n) return fallback;
    if (!n.IsScalar()) {
      fail(n, key,
           "expected a name, got " + std::string(n.IsSequence() ? "a list"
                                                 : n.IsMap()    ? "a mapping"
                                                                : "nothing"));
      return fallback;
    }
    return n.Scalar();
  }
  // (node) => itself when it knows its place in the file, else its first element or key that
  // does (collections rebuilt while resolving $references lose their marks)
  static YAML::Node marked(const YAML::Node& n) {
    if (!n.IsDefined() || !n.Mark().is_null()) return n;
    if (n.IsSequence())
      for (std::size_t i = 0; i < n.size(); ++i)
        if (const YAML::Node m = marked(n[i]); !m.Mark().is_null()) return m;
    if (n.IsMap())
      for (auto it = n.begin(); it != n.end(); ++it)
        if (const YAML::Node m = marked(it->second); !m.Mark().is_null()) return m;
    return n;
  }
  bool keys(const YAML::Node& map, const std::vector<std::string>& allowed,
            const std::string& key) const {
    if (!map || !map.IsMap()) {
      fail(map, key, "expected a mapping");
      return false;
    }
    bool ok = true;
    for (auto it = map.begin(); it != map.end(); ++it) {
      const auto k = it->first.as<std::string>();
      if (std::find(allowed.begin(), allowed.end(), k) != allowed.end()) continue;
      const std::string hint = didYouMean(k, allowed);
      fail(it->first.Mark().is_null() ? it->second : it->first, key.empty() ? k : key + "." + k,
           "unknown key '" + k + "'" + (hint.empty() ? "" : " (" + hint + ")"));
      ok = false;
    }
    return ok;
  }
  double number(const YAML::Node& n, const std::string& key, double fallback,
                bool required = false) const {
    if (!n) {
      if (required) fail(n, key, "missing required key '" + key + "' (a number)");
      return fallback;
    }
    double v = 0;
    if (!n.IsScalar() || !YAML::convert<double>::decode(n, v) || !std::isfinite(v)) {
      fail(n, key, "expected a number, got " + (n.IsScalar() ? "'" + n.Scalar() + "'" : std::string("a collection")));
      return fallback;
    }
    return v;
  }
  std::vector<double> numbers(const YAML::Node& n, const std::string& key, std::size_t size) const {
    std::vector<double> out;
    if (!n || !n.IsSequence() || (size && n.size() != size)) {
      fail(n, key, "expected a list of " + (size ? std::to_string(size) + " " : std::string()) + "numbers");
      return std::vector<double>(size, 0.0);
    }
    for (std::size_t i = 0; i < n.size(); ++i) out.push_back(number(n[i], key, 0.0));
    return out;
  }
  Vector3 vec3(const YAML::Node& n, const std::string& key, const Vector3& fallback) const {
    if (!n) return fallback;
    const auto v = numbers(n, key, 3);
    return {v[0], v[1], v[2]};
  }
  // (node, key path, fallback) => a position or size in m, each component at most
  // kMaxSceneLength in magnitude (a coordinate of 1e300 m would reach the collision tree and
  // the guard as an overflow far from its key)
  Vector3 length3(const YAML::Node& n, const std::string& key, const Vector3& fallback) const {
    const Vector3 v = vec3(n, key, fallback);
    if (n && v.cwiseAbs().maxCoeff() > kMaxSceneLength) {
      std::ostringstream got;
      got << "[" << v.x() << ", " << v.y() << ", " << v.z() << "]";
      fail(n, key,
           "expected lengths in m within ±1e6 (a yard or an offshore site), got " + got.str());
    }
    return v;  // as read: one error, no follow-on errors from a fallback
  }
  // ({xyz, rpy_deg}) => transform
  dynamics::Transform pose(const YAML::Node& n, const std::string& key) const {
    if (!n) return dynamics::Transform::identity();
    if (!keys(n, {"xyz", "rpy_deg"}, key)) return dynamics::Transform::identity();
    const Vector3 rpy = vec3(n["rpy_deg"], key + ".rpy_deg", Vector3::Zero()) * kDeg;
    return {dynamics::eulerToMatrix(rpy), length3(n["xyz"], key + ".xyz", Vector3::Zero())};
  }
};

// (node, key, `name_deg` or `name`) => an angle in rad (0 when neither is there)
inline double angle(const Reader& r, const YAML::Node& n, const std::string& key, const std::string& name) {
  if (n[name + "_deg"]) return kDeg * r.number(n[name + "_deg"], key + "." + name + "_deg", 0.0);
  return r.number(n[name], key + "." + name, 0.0);
}

// (node, key) => a whole number in [lo, hi] (fallback when absent), reported otherwise
inline long wholeNumber(const Reader& r, const YAML::Node& n, const std::string& key, long fallback, long lo, long hi) {
  if (!n) return fallback;
  const double v = r.number(n, key, static_cast<double>(fallback));
  if (v != std::floor(v) || v < static_cast<double>(lo) || v > static_cast<double>(hi)) {
    r.fail(n, key, "expected a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return fallback;
  }
  return static_cast<long>(v);
}

}  // namespace yardsim::scene::spec
