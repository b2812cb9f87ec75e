#include "yard/schema.hpp"

namespace yardsim::yard {

// () => the migrations. Units: SI (kg, m, kg m^2, N, N/m-free EA in N, kg/m, m/s, m/s^2). Frames:
// a block's cog, inertia, mesh and lugs are in the block's own (CAD) frame; the inertia is about
// the cog.
const std::vector<std::string>& migrations() {
  static const std::vector<std::string> all{
      // 1: materials, blocks and their lugs, facilities and their hook-load curves, rope catalogue
      R"sql(
CREATE TABLE materials (
  name TEXT PRIMARY KEY,
  density REAL NOT NULL CHECK (density > 0)                     -- kg/m^3
);
CREATE TABLE friction_pairs (
  material_a TEXT NOT NULL REFERENCES materials(name) ON DELETE CASCADE,
  material_b TEXT NOT NULL REFERENCES materials(name) ON DELETE CASCADE,
  mu REAL NOT NULL CHECK (mu >= 0),                             -- Coulomb coefficient
  PRIMARY KEY (material_a, material_b)
);
CREATE TABLE blocks (
  name TEXT PRIMARY KEY,
  project TEXT NOT NULL DEFAULT '',
  mass REAL NOT NULL CHECK (mass > 0),                          -- kg
  cog_x REAL NOT NULL, cog_y REAL NOT NULL, cog_z REAL NOT NULL,  -- m, block frame
  ixx REAL NOT NULL, iyy REAL NOT NULL, izz REAL NOT NULL,      -- kg m^2 about the cog
  ixy REAL NOT NULL DEFAULT 0, ixz REAL NOT NULL DEFAULT 0, iyz REAL NOT NULL DEFAULT 0,
  mesh BLOB,                                                    -- yard/mesh_blob.hpp, block frame
  mesh_path TEXT,                                               -- or a file, relative to the database
  weight_status TEXT NOT NULL DEFAULT 'estimated'
    CHECK (weight_status IN ('estimated', 'calculated', 'weighed')),
  source TEXT NOT NULL DEFAULT ''                               -- where the numbers came from
);
CREATE TABLE lugs (
  block TEXT NOT NULL REFERENCES blocks(name) ON DELETE CASCADE,
  name TEXT NOT NULL,
  x REAL NOT NULL, y REAL NOT NULL, z REAL NOT NULL,             -- m, block frame
  dx REAL NOT NULL, dy REAL NOT NULL, dz REAL NOT NULL,         -- unit pull direction
  swl REAL NOT NULL CHECK (swl > 0),                            -- safe working load, N
  PRIMARY KEY (block, name)
);
CREATE TABLE facilities (
  name TEXT PRIMARY KEY,
  kind TEXT NOT NULL CHECK (kind IN ('goliath', 'floating', 'overhead', 'other')),
  model_file TEXT NOT NULL,                                     -- YAML, relative to the database
  capacity REAL NOT NULL CHECK (capacity > 0),                  -- N, at the hook
  hoist_speed REAL CHECK (hoist_speed > 0),                     -- m/s
  hoist_acceleration REAL CHECK (hoist_acceleration > 0),       -- m/s^2
  max_outreach REAL CHECK (max_outreach > 0)                    -- m
);
CREATE TABLE hook_load_curves (
  facility TEXT NOT NULL REFERENCES facilities(name) ON DELETE CASCADE,
  outreach REAL NOT NULL CHECK (outreach >= 0),                 -- m
  capacity REAL NOT NULL CHECK (capacity > 0),                  -- N
  PRIMARY KEY (facility, outreach)
);
CREATE TABLE ropes (
  name TEXT PRIMARY KEY,                                        -- e.g. '6x36 IWRC 64 mm'
  diameter REAL NOT NULL CHECK (diameter > 0),                  -- m
  construction TEXT NOT NULL,
  ea REAL NOT NULL CHECK (ea > 0),                              -- N
  mbl REAL NOT NULL CHECK (mbl > 0),                            -- N
  mass_per_metre REAL NOT NULL CHECK (mass_per_metre > 0)       -- kg/m
);
)sql",
  };
  return all;
}

}  // namespace yardsim::yard
