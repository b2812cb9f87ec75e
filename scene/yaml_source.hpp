#pragma once
// Reading YAML with its positions: marks as file:line:column, key checks with "did you mean",
// duplicate keys, and `$name` parameter references resolved through nested scopes.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "models/diagnostics.hpp"

namespace yardsim::scene {

using models::Diagnostics;
using models::SourceMark;

// (node, file) => its 1-based position
SourceMark markOf(const YAML::Node& node, const std::string& file);

// (key path, key) => "a.b.key" (or "key" at the top)
std::string joinKey(const std::string& path, const std::string& key);

// (mapping, allowed keys) => an error for every unknown or repeated key; false if any
bool checkKeys(const YAML::Node& map, const std::vector<std::string>& allowed,
               const std::string& file, const std::string& keyPath, Diagnostics& diags);

// Named parameter values visible at one place of a scene, with the scope they are nested in.
struct Scope {
  std::map<std::string, YAML::Node> values;
  const Scope* parent = nullptr;
  const YAML::Node* find(const std::string& name) const;
  std::vector<std::string> names() const;
};

// (node, scope) => a copy where every scalar "$name" is replaced by that parameter's value;
// an unknown name is reported (with "did you mean") and becomes null
YAML::Node resolveRefs(const YAML::Node& node, const Scope& scope, const std::string& file,
                       const std::string& keyPath, Diagnostics& diags);

// (node) => short text of a scalar for messages ("'abc'"), or its kind ("a mapping")
std::string shown(const YAML::Node& node);

}  // namespace yardsim::scene
