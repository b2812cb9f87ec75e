#pragma once
// `yardsim db ...`: the yard's database from the command line (docs/database.md).
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace yardsim::cli {

struct DbArgs {
  std::string db;                              // -d/--db or $YARDSIM_DB
  std::string file, name, what, outdir = ".";  // positionals of the subcommands
  std::string step, obj, stl;                  // import-block geometry (one of them)
  double density = 0, mass = 0;                // kg/m^3 | kg
  std::vector<double> cog, inertia;            // m | kg m^2 (3 or 6 values)
  std::vector<std::string> lugs;               // NAME:x,y,z:dx,dy,dz:swl
  std::string project, weightStatus = "";      // import-block
  double chord = 1e-3, angleDeg = 20;          // STEP tessellation
  std::string kind = "goliath", model, curve;  // add-facility
  double capacity = 0, hoistSpeed = 0, hoistAcceleration = 0, maxOutreach = 0;
};

// (app, arguments) => the `db` subcommand and its own subcommands added to app
CLI::App* addDbCommand(CLI::App& app, DbArgs& a);
// (parsed db subcommand, arguments) => exit status: 0, or 1 with a message for a user error
int dbCommand(const CLI::App& db, const DbArgs& a);

}  // namespace yardsim::cli
