#include "scene/yaml_source.hpp"

#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace yardsim::scene {

using models::Diagnostics;
using models::didYouMean;
using models::SourceMark;

namespace {
// Counts a stream's documents and stops at the start of the second (the exception ends the parse).
class SecondDocument final : public YAML::EventHandler {
 public:
  struct Found {
    YAML::Mark mark;
  };
  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ == 2) throw Found{mark};
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}

 private:
  int documents_ = 0;
};

// (YAML text) => where its second document starts, or nullopt when it has one (or none);
// throws YAML::ParserException on a syntax error before that
std::optional<YAML::Mark> secondDocument(const std::string& text) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  SecondDocument counter;
  try {
    while (parser.HandleNextDocument(counter)) {
    }
  } catch (const SecondDocument::Found& f) {
    return f.mark;
  }
  return std::nullopt;
}

// What one walk over a document found: the nodes left of the budget, the first mapping key that
// is not a plain scalar (`? [a, b]: 1`, `~: 1`), and whether it nests too deep.
struct Walk {
  std::size_t budget = kMaxSceneNodes;
  std::optional<YAML::Node> badKey;
  bool tooDeep = false;
};

// (node, its depth) => counted into the walk as aliases expand it; stops when the budget is
// spent (an alias bomb of a few lines expands to billions of nodes) or below kMaxSceneDepth (an
// alias inside its own anchor, `a: &a [*a]`, is a node that contains itself)
void walk(const YAML::Node& n, Walk& w, int depth) {
  if (w.budget == 0) return;
  if (depth > kMaxSceneDepth) {
    w.tooDeep = true;
    w.budget = 0;
    return;
  }
  --w.budget;
  if (n.IsSequence())
    for (const auto& e : n) walk(e, w, depth + 1);
  else if (n.IsMap())
    for (auto it = n.begin(); it != n.end() && w.budget > 0; ++it) {
      if (!it->first.IsScalar() && !w.badKey) w.badKey.emplace(it->first);
      walk(it->second, w, depth + 1);
    }
}
}  // namespace

std::optional<YAML::Node> readYamlFile(const std::filesystem::path& file, const SourceMark& from,
                                       const std::string& keyPath, Diagnostics& diags,
                                       std::string* text) {
  const SourceMark at = from.file.empty() ? SourceMark{file.string()} : from;
  // (path) => a regular file below the size limit (a device or a FIFO would never end)
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    diags.error(at, keyPath,
                std::filesystem::exists(file, ec)
                    ? "'" + file.string() + "' is not a regular file"
                    : "cannot read scene file '" + file.string() + "'");
    return std::nullopt;
  }
  if (const auto size = std::filesystem::file_size(file, ec); !ec && size > kMaxSceneFileBytes) {
    diags.error(at, keyPath,
                "'" + file.string() + "' has " + std::to_string(size) +
                    " bytes; a scene file has at most " + std::to_string(kMaxSceneFileBytes) +
                    " (meshes belong in mesh files)");
    return std::nullopt;
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    diags.error(at, keyPath, "cannot read scene file '" + file.string() + "'");
    return std::nullopt;
  }
  std::stringstream ss;
  ss << in.rdbuf();
  if (text) *text = ss.str();
  try {
    // (text) => the start of a second document, if any, found without reading further (a stray
    // ',' before the first node makes yaml-cpp's LoadAll produce empty documents without end)
    if (const auto second = secondDocument(ss.str())) {
      const std::string& t = ss.str();
      const std::size_t pos =
          std::min<std::size_t>(static_cast<std::size_t>(std::max(second->pos, 0)), t.size());
      diags.error({file.string(), second->line + 1, second->column + 1}, "",
                  t.compare(pos, 3, "---") == 0 ? "a scene file holds one YAML document; a second "
                                                  "one starts here (remove the '---' line, "
                                                  "or move it to its own file)"
                                                : "YAML syntax error: '" + t.substr(pos, 1) +
                                                      "' outside any mapping or list");
      return std::nullopt;
    }
    std::vector<YAML::Node> docs;
    if (const YAML::Node doc = YAML::Load(ss.str()); doc.IsDefined() && !doc.IsNull())
      docs.push_back(doc);
    Walk w;
    if (!docs.empty()) walk(docs[0], w, 0);
    if (w.tooDeep) {
      diags.error({file.string(), 1, 1}, "",
                  "the document nests deeper than " + std::to_string(kMaxSceneDepth) +
                      " levels (a YAML alias inside its own anchor, such as a: &a [*a]?); a scene "
                      "is far flatter");
      return std::nullopt;
    }
    if (w.budget == 0) {
      diags.error({file.string(), 1, 1}, "",
                  "the document expands to more than " + std::to_string(kMaxSceneNodes) +
                      " nodes (YAML aliases repeated into each other?); a scene is far smaller");
      return std::nullopt;
    }
    if (w.badKey) {
      diags.error(markOf(*w.badKey, file.string()), "",
                  "a key must be a plain name, got " + shown(*w.badKey) +
                      " (a list, mapping or empty key)");
      return std::nullopt;
    }
    if (docs.empty() || !docs[0].IsMap()) {
      diags.error({file.string(), 1, 1}, "", "a scene file must be a mapping of keys");
      return std::nullopt;
    }
    return docs[0];
  } catch (const YAML::ParserException& e) {
    diags.error({file.string(), e.mark.line + 1, e.mark.column + 1}, "",
                "YAML syntax error: " + e.msg);
    return std::nullopt;
  }
}

SourceMark markOf(const YAML::Node& node, const std::string& file) {
  const YAML::Mark m = node.Mark();
  if (m.is_null()) return {file, 0, 0};
  return {file, m.line + 1, m.column + 1};
}

namespace {
// (node) => it or its first descendant that carries a position (resolveRefs rebuilds maps and
// sequences without one; the scalars keep theirs), or an undefined node
YAML::Node firstPlaced(const YAML::Node& node) {
  if (!node.Mark().is_null()) return node;
  if (node.IsMap() || node.IsSequence())
    for (auto it = node.begin(); it != node.end(); ++it) {
      const YAML::Node child = node.IsMap() ? it->second : *it;
      if (YAML::Node placed = firstPlaced(child); placed.IsDefined()) return placed;
    }
  return YAML::Node(YAML::NodeType::Undefined);
}
}  // namespace

YAML::Node mapKey(const YAML::Node& map, const std::string& key) {
  if (map.IsMap())
    for (auto it = map.begin(); it != map.end(); ++it)
      if (it->first.IsScalar() && it->first.Scalar() == key && !it->first.Mark().is_null())
        return it->first;
  return YAML::Node(YAML::NodeType::Undefined);
}

YAML::Node placedEntry(const YAML::Node& map, const std::string& key) {
  if (YAML::Node k = mapKey(map, key); k.IsDefined()) return k;
  return map.IsMap() && map[key].IsDefined() ? firstPlaced(map[key])
                                             : YAML::Node(YAML::NodeType::Undefined);
}

std::string joinKey(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

bool checkKeys(const YAML::Node& map, const std::vector<std::string>& allowed,
               const std::string& file, const std::string& keyPath, Diagnostics& diags) {
  bool ok = true;
  std::set<std::string> seen;
  for (auto it = map.begin(); it != map.end(); ++it) {
    const auto key = it->first.as<std::string>();
    if (!seen.insert(key).second) {
      diags.error(markOf(it->first, file), joinKey(keyPath, key),
                  "duplicate key '" + key + "'; each key may appear once");
      ok = false;
    } else if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::string expected;
      for (const auto& a : allowed) expected += (expected.empty() ? "" : ", ") + a;
      diags.error(markOf(it->first, file), joinKey(keyPath, key),
                  "unknown key '" + key + "'; expected one of: " + expected,
                  didYouMean(key, allowed));
      ok = false;
    }
  }
  return ok;
}

const YAML::Node* Scope::find(const std::string& name) const {
  for (const Scope* s = this; s; s = s->parent) {
    auto it = s->values.find(name);
    if (it != s->values.end()) return &it->second;
  }
  return nullptr;
}

std::vector<std::string> Scope::names() const {
  std::vector<std::string> out;
  for (const Scope* s = this; s; s = s->parent)
    for (const auto& [k, _] : s->values) out.push_back(k);
  return out;
}

namespace {
// The rebuilt maps and sequences of one resolveRefs call, made as entries of one throwaway map so
// that they share its node memory: yaml-cpp copies the whole set of a document's nodes into a
// node's memory the first time a node of that document is assigned into it, once per memory, so
// fresh maps (each with a memory of its own) copied the document once each
struct Rebuilt {
  YAML::Node arena{YAML::NodeType::Sequence};
  // () => a null node in the arena's memory, which becomes a map or a sequence when filled
  YAML::Node make() {
    YAML::Node n;
    arena.push_back(n);
    return n;
  }
};

YAML::Node resolveIn(const YAML::Node& node, const Scope& scope, const std::string& file,
                     const std::string& keyPath, Diagnostics& diags, Rebuilt& rebuilt) {
  if (node.IsScalar()) {
    const std::string& text = node.Scalar();
    if (text.size() < 2 || text[0] != '$' || node.Tag() == "!") return node;
    const std::string name = text.substr(1);
    if (const YAML::Node* value = scope.find(name)) return YAML::Clone(*value);
    diags.error(markOf(node, file), keyPath,
                "unknown parameter '" + name + "'; a '$name' refers to a key of a params block",
                didYouMean(name, scope.names()));
    return YAML::Node(YAML::NodeType::Null);
  }
  if (node.IsSequence()) {
    if (node.size() == 0) return YAML::Node(YAML::NodeType::Sequence);
    YAML::Node out = rebuilt.make();
    std::size_t i = 0;
    for (const auto& e : node)
      out.push_back(
          resolveIn(e, scope, file, keyPath + "[" + std::to_string(i++) + "]", diags, rebuilt));
    return out;
  }
  if (node.IsMap()) {
    if (node.size() == 0) return YAML::Node(YAML::NodeType::Map);
    YAML::Node out = rebuilt.make();
    for (auto it = node.begin(); it != node.end(); ++it) {
      const auto key = it->first.as<std::string>();
      out[key] = resolveIn(it->second, scope, file, joinKey(keyPath, key), diags, rebuilt);
    }
    return out;
  }
  return node;
}
}  // namespace

YAML::Node resolveRefs(const YAML::Node& node, const Scope& scope, const std::string& file,
                       const std::string& keyPath, Diagnostics& diags) {
  // (node) => the rebuilt copy, its maps and sequences in one memory (Rebuilt)
  Rebuilt rebuilt;
  return resolveIn(node, scope, file, keyPath, diags, rebuilt);
}

std::string shown(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

}  // namespace yardsim::scene
