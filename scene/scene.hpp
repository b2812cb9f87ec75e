#pragma once
// A scene after loading and validation: the instance tree every component of every included
// file resolved (types found, `$name` references replaced, overrides applied), plus the
// run settings of the root file. Nothing is built yet: assemble() does that.
#include <array>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/integrators/factory.hpp"
#include "models/params.hpp"
#include "models/registry.hpp"

namespace yardsim::scene {

using models::Params;
using models::PortSpec;
using models::SourceMark;
using models::TypeInfo;

struct Placement {
  std::array<double, 3> xyz{0.0, 0.0, 0.0};     // m, in the parent's frame
  std::array<double, 3> rpyDeg{0.0, 0.0, 0.0};  // roll, pitch, yaw in degrees
};

struct CouplingSpec {
  std::string fromModel, fromPort;  // fromModel empty: this coupled model's own port
  std::string toModel, toPort;
  SourceMark where;
};

struct Instance {
  std::string name;
  std::string path;  // dot path from the scene root ("" for the root)
  SourceMark where;  // where the scene declares it
  std::string keyPath;
  Placement placement;  // relative to the parent
  // atomic
  const TypeInfo* type = nullptr;
  Params params;
  bool feedthrough = false;  // from the type, for these params
  std::string boundSystem;   // an actor acting on a scene mechanical system (set-points routed there)
  std::vector<std::string> listensTo;  // actors whose `finished` the assembler couples to `trigger`
  // both: ports (for an atomic, from its type)
  std::vector<PortSpec> ports;
  // coupled
  std::string source;  // file that defines it (include) or "" when inline or atomic
  std::vector<std::unique_ptr<Instance>> children;
  std::vector<CouplingSpec> couplings;
  // coupled: the fragment of mechanics this model contributes (`mechanics:`, `$name` resolved;
  // undefined when it has none), and where it was written
  YAML::Node mechanics{YAML::NodeType::Undefined};
  SourceMark mechanicsWhere;

  bool atomic() const { return type != nullptr; }
  const Instance* child(const std::string& n) const;
  const PortSpec* port(const std::string& n) const;
};

struct RecordSpec {
  double interval = 0.0;              // s; 0: nothing recorded
  std::vector<std::string> channels;  // globs over channel names
  SourceMark where;                   // record.interval
};

// Ceilings on one run's cost (scene/resource_limits.hpp); the root key `limits:` raises them.
inline constexpr double kDefaultMaxSteps = 1e8;  // steps of one fixed-step model
inline constexpr double kDefaultMaxRows = 1e6;   // rows of timeseries.csv
struct LimitsSpec {
  double steps = kDefaultMaxSteps;
  double rows = kDefaultMaxRows;
};

// What the HTML report shows (docs/report.md): the recorded channels it plots and the static
// levels drawn over them (and the peak of a tension channel is compared with).
struct ReportSpec {
  std::vector<std::string> plots;                             // globs; empty: every recorded channel
  std::vector<std::pair<std::string, double>> staticLevels;   // channel => value in its unit
  std::vector<SourceMark> staticWhere;                        // where each is written
};

struct MechanicalSystem;  // models/mechanical_systems.hpp

// A crane of the yard database whose hook-load curve the run checks (run/hook_load_monitor.hpp):
// the hook load is the sum of tension x parts over its hoist ropes (those hanging from one of its
// bodies and holding a body outside it), the outreach the largest horizontal distance from its
// root body (the one on world, e.g. the gantry) to a body a hoist rope hangs from.
struct HookLoadCheck {
  std::string crane;                               // the facility's instance path: GOC201
  std::string facility;                            // its name in the database
  std::vector<std::pair<double, double>> curve;    // (outreach m, capacity N), outreach ascending
  std::string system;                              // the multibody model that holds its ropes
  std::string root;                                // its root body: GOC201.gantry
  std::vector<std::pair<std::string, int>> ropes;  // hoist rope full names and their parts
  std::vector<std::string> hoists;                 // the bodies they hang from
};

// A value a scene took from the yard's database (scene/yard_reader.hpp), or a scene key that
// overrode one: for `validate --print-resolved`.
struct Provenance {
  std::string key;     // full path: GOC201.lower_fore.EA, block.mass
  std::string value;   // as used, with its unit
  std::string source;  // "blocks row 1 'GT-BLOCK-920'", or "the scene (the database has ...)"
};

struct Scene {
  std::filesystem::path file;
  std::string name;
  std::string sha256;  // of the root file's bytes
  double until = std::numeric_limits<double>::infinity();
  long long seed = 0;
  std::string integrator = "none";  // method named by the scene (= integratorSpec.method)
  double dt = 0.0;                   // its step, s (= integratorSpec.dt)
  dynamics::IntegratorSpec integratorSpec;  // every parameter of the `integrator:` block
  // integrator.stiffness_check: what to do when omega_max dt exceeds the method's stability
  // limit before the run (docs/numerics.md): warn, refuse (an error) or off
  std::string stiffnessCheck = "warn";
  SourceMark integratorWhere;  // the `integrator:` block, for diagnostics about the step
  RecordSpec record;
  LimitsSpec limits;
  ReportSpec report;
  std::vector<std::string> trace;  // sink names from the scene: jsonl, chrome, csv
  Instance root;
  // the mechanics of every coupled model, merged and split into mechanically connected
  // systems (each becomes one multibody model)
  std::vector<std::shared_ptr<const MechanicalSystem>> systems;
  // the yard database the scene names (`database:`): its file and schema ("" when none), and
  // every value taken from it
  std::string database;
  std::vector<Provenance> provenance;
  std::vector<HookLoadCheck> hookLoads;  // cranes of the database with a hook-load curve
};

}  // namespace yardsim::scene
