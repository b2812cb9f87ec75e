#pragma once
// The yard database's keys in scenes (docs/database.md, "In scenes"): `database:` at the scene
// root, a body's `from_db: BLOCK` (mass kg, centre of gravity m, inertia kg m^2 about it, mesh;
// all in the block's own frame, which becomes the body frame), a rope's or equalizer's
// `catalogue: NAME` (EA N, mbl N), a component's `facility: NAME` (its YAML model included, its
// particulars as parameters) and a rope point named by a lug of a block from the database. What
// the scene states itself overrides the database; every value taken from it is kept, with the
// table and row it came from, for `validate --print-resolved`. Errors at the door: file:line:col,
// the key path, what was expected.
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "forces/geometry/triangle_mesh.hpp"
#include "models/diagnostics.hpp"
#include "scene/scene.hpp"
#include "scene/scene_loader.hpp"
#include "yard/database.hpp"
#include "yard/records.hpp"

namespace yardsim::scene {

// A facility named by a component: the model file to include and the facility itself.
struct FacilityUse {
  std::filesystem::path modelFile;  // absolute or relative to the working directory
  yard::Facility facility;
  std::int64_t row = 0;  // its rowid in `facilities`
};

class SceneYard {
 public:
  // (the root's `database:` node: a path relative to the scene file, or {env: VAR, default:
  // path}; the root file) => the database opened read-only, or an error at the node
  void open(const YAML::Node& node, const std::filesystem::path& sceneFile, Diagnostics& d);
  bool isOpen() const { return db_ != nullptr; }

  // (`facility:` node, file, key path) => the facility and its model file, or an error
  std::optional<FacilityUse> facility(const YAML::Node& node, const std::string& file,
                                      const std::string& keyPath, Diagnostics& d);
  // (facility, the model file's `params:`, instance path, where named) => its particulars
  // (capacity N, hoist_speed m/s, hoist_acceleration m/s^2, max_outreach m) added to the
  // overrides for the parameters the model declares and the scene does not set itself
  void addParticulars(const FacilityUse& use, const YAML::Node& params, const std::string& instPath,
                      const SourceMark& where, const std::string& keyPath,
                      ParamOverrides& overrides);

  // (a fragment's mechanics, $references resolved; file; its key path; instance path) =>
  // bodies with from_db and ropes/equalizers with catalogue filled in, those keys removed
  void expandMechanics(YAML::Node& mechanics, const std::string& file, const std::string& keyPath,
                       const std::string& instPath, Diagnostics& d);
  // (scene root) => every rope or equalizer point written as a lug's name replaced by the lug's
  // position on its block (the body resolved as the mechanics resolves names)
  void resolveLugPoints(Instance& root, Diagnostics& d);

  // (scene) => its `database` line, provenance and the facilities' hook-load curves filled in
  void describe(Scene& scene) const;

 private:
  struct DbBody {
    yard::Block block;
    std::int64_t row = 0;
  };
  bool need(const YAML::Node& at, const std::string& file, const std::string& keyPath,
            const std::string& key, Diagnostics& d) const;
  void expandBody(YAML::Node body, const std::string& name, const std::string& file,
                  const std::string& keyPath, const std::string& instPath, Diagnostics& d);
  void expandRope(YAML::Node rope, const std::string& name, const std::string& file,
                  const std::string& keyPath, const std::string& instPath, Diagnostics& d);
  void lugPoint(YAML::Node point, const Instance& inst, const std::string& where, Diagnostics& d);
  std::int64_t rowOf(const std::string& table, const std::string& name) const;
  std::string source(const std::string& table, const std::string& name, std::int64_t row) const;

  std::shared_ptr<yard::Database> db_;
  bool named_ = false;                    // the scene has `database:` (opened or not)
  std::string label_;                     // the file as shown: path, schema version
  std::map<std::string, DbBody> bodies_;  // full body path => its block
  std::vector<Provenance> provenance_;
  std::vector<HookLoadCheck> hookLoads_;
};

// (scene with its mechanical systems) => each hook-load check given its system, root body and
// hoist ropes; a crane without hoist ropes is dropped with a warning at its component
void completeHookLoadChecks(Scene& scene, Diagnostics& d);

// (database file, block name) => the block's stored mesh (or its mesh file), in the block frame;
// forces::MeshError when it has none or it cannot be read
std::shared_ptr<const forces::TriangleMesh> databaseBlockMesh(const std::string& databaseFile,
                                                              const std::string& block);

}  // namespace yardsim::scene
