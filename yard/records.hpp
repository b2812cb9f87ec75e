#pragma once
// What the yard's database holds, as plain values. Units SI; a block's cog, inertia, mesh and
// lugs are in the block's own (CAD) frame, the inertia about the cog.
#include <memory>
#include <string>
#include <vector>

#include "dynamics/spatial.hpp"
#include "forces/geometry/triangle_mesh.hpp"

namespace yardsim::yard {

// A lifting lug: where a rope or shackle attaches and how much it may carry.
struct Lug {
  std::string name;
  dynamics::Vector3 position = dynamics::Vector3::Zero();    // m, block frame
  dynamics::Vector3 direction = dynamics::Vector3::UnitZ();  // unit, the pull it is rated for
  double swl = 0.0;                                          // safe working load, N
};

// A hull block (or any lifted body) with its weight-control figures.
struct Block {
  std::string name, project;
  double mass = 0.0;                                      // kg
  dynamics::Vector3 cog = dynamics::Vector3::Zero();      // m, block frame
  dynamics::Matrix3 inertia = dynamics::Matrix3::Zero();  // kg m^2 about the cog
  std::shared_ptr<const forces::TriangleMesh> mesh;       // block frame; null: none
  std::string meshPath;                                   // a file instead (relative to the db)
  std::vector<Lug> lugs;
  std::string weightStatus = "estimated";  // estimated | calculated | weighed
  std::string source;                      // where the figures came from
};

// A point of a crane's hook-load curve: the capacity at an outreach.
struct CurvePoint {
  double outreach = 0.0;  // m
  double capacity = 0.0;  // N
};

// A crane (goliath, floating, overhead): its YAML model and its particulars.
struct Facility {
  std::string name, kind = "goliath";     // goliath | floating | overhead | other
  std::string modelFile;                  // YAML model, relative to the database file
  double capacity = 0.0;                  // N at the hook
  double hoistSpeed = 0.0;                // m/s; 0: not stated
  double hoistAcceleration = 0.0;         // m/s^2; 0: not stated
  double maxOutreach = 0.0;               // m; 0: not stated
  std::vector<CurvePoint> hookLoadCurve;  // outreach ascending
};

// A wire rope or sling from a catalogue.
struct Rope {
  std::string name;           // e.g. "6x36 IWRC 64 mm"
  double diameter = 0.0;      // m
  std::string construction;   // e.g. "6x36 IWRC"
  double ea = 0.0;            // axial stiffness, N
  double mbl = 0.0;           // minimum breaking load, N
  double massPerMetre = 0.0;  // kg/m
};

}  // namespace yardsim::yard
