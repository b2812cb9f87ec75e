#pragma once
// What the provider readers of scene/providers/ share: a spring law (`k` or `table`), a body name,
// a non-negative number, and the problems a provider's constructor would throw turned into
// problems at the entry's YAML node before the run.
#include <optional>
#include <stdexcept>
#include <string>

#include "forces/spring_curve.hpp"
#include "scene/provider_readers.hpp"

namespace yardsim::scene::providers {

// (entry, key) => f(x) from `k` (>= 0, linear) or `table` ([[x, f], ...], x increasing); one of
// the two is required; nullopt after a reported problem
inline std::optional<forces::SpringCurve> readCurve(const spec::Reader& r, const YAML::Node& n,
                                                    const std::string& key, const char* unit) {
  if (n["k"] && n["table"]) {
    r.fail(n["table"], key + ".table", "give either k or table, not both");
    return std::nullopt;
  }
  if (const YAML::Node t = n["table"]) {
    std::vector<double> x, f;
    if (!t.IsSequence()) {
      r.fail(t, key + ".table", std::string("expected a list of [x, f] rows (f in ") + unit + ")");
      return std::nullopt;
    }
    for (std::size_t i = 0; i < t.size(); ++i) {
      const auto row = r.numbers(t[i], key + ".table[" + std::to_string(i) + "]", 2);
      x.push_back(row[0]);
      f.push_back(row[1]);
    }
    try {
      return forces::SpringCurve::table(x, f, key);
    } catch (const std::invalid_argument& e) {
      r.fail(t, key + ".table", e.what());
      return std::nullopt;
    }
  }
  if (!n["k"]) {
    r.fail(n, key,
           std::string("missing required key 'k' (stiffness, ") + unit +
               " per unit deflection) or 'table'");
    return std::nullopt;
  }
  const double k = r.number(n["k"], key + ".k", 0.0);
  if (k < 0) {
    r.fail(n["k"], key + ".k", "k must be >= 0");
    return std::nullopt;
  }
  return forces::SpringCurve::linear(k);
}

// (node, key, fallback, required) => a number >= 0 (a problem reported at the node otherwise)
inline double nonNegative(const spec::Reader& r, const YAML::Node& n, const std::string& key,
                          double fallback, bool required = false) {
  const double v = r.number(n, key, fallback, required);
  if (n && v < 0) r.fail(n, key, "must be >= 0, got " + std::to_string(v));
  return v;
}

// (entry, its field, key) => the body name in entry[field] (a problem at the entry when missing)
inline std::string bodyName(const spec::Reader& r, const YAML::Node& entry, const char* field,
                            const std::string& key) {
  const YAML::Node n = entry[field];
  if (!n) {
    r.fail(entry, key, std::string("missing required key '") + field + "' (a body name)");
    return "world";
  }
  if (!n.IsScalar()) {
    r.fail(n, key, "expected a body name");
    return "world";
  }
  return n.Scalar();
}

// (entry, its field, key) => entry[field] as a {body, point} attachment, or a world point given
// as [x, y, z] (a problem at the entry when missing)
inline mechanics::MechanicsSpec::Point readEnd(const spec::Reader& r, const YAML::Node& entry,
                                               const char* field, const std::string& key) {
  const YAML::Node n = entry[field];
  if (!n) {
    r.fail(entry, key,
           std::string("missing required key '") + field +
               "' ({body, point}, or [x, y, z] in the world)");
    return {"world", dynamics::Vector3::Zero()};
  }
  const std::string at = key + "." + field;
  if (n.IsSequence()) return {"world", r.vec3(n, at, dynamics::Vector3::Zero())};
  return readPoint(r, n, at);
}

}  // namespace yardsim::scene::providers
