#pragma once
// Reading YAML with its positions: marks as file:line:column, key checks with "did you mean",
// duplicate keys, and `$name` parameter references resolved through nested scopes.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "models/diagnostics.hpp"

namespace yardsim::scene {

using models::Diagnostics;
using models::SourceMark;

// Scene files are regular files of at most this many bytes (a larger one is refused, not read).
inline constexpr std::uintmax_t kMaxSceneFileBytes = 16u << 20;
// ... and expand, with their YAML aliases, to at most this many nodes.
inline constexpr std::size_t kMaxSceneNodes = 1000000;
// ... nested at most this deep (a YAML alias inside its own anchor would nest without end)
inline constexpr int kMaxSceneDepth = 64;

// (file, where it was named from (empty for the root), the key that named it) => its one YAML
// document, a mapping; or nullopt with the reason (unreadable, not a regular file, too large,
// a syntax error at its place, a second document, not a mapping); its bytes in *text if asked
std::optional<YAML::Node> readYamlFile(const std::filesystem::path& file, const SourceMark& from,
                                       const std::string& keyPath, Diagnostics& diags,
                                       std::string* text = nullptr);

// (node, file) => its 1-based position
SourceMark markOf(const YAML::Node& node, const std::string& file);

// (mapping, key) => the key's own node (its mark is where the key is written), or an undefined
// node when the mapping does not have it or the key has no position
YAML::Node mapKey(const YAML::Node& map, const std::string& key);

// (mapping, key) => mapKey, or for a mapping rebuilt by resolveRefs (whose keys have no
// position) the first positioned node of the key's value, or an undefined node
YAML::Node placedEntry(const YAML::Node& map, const std::string& key);

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
