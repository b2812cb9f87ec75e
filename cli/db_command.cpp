#include "cli/db_command.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/exit_codes.hpp"
#include "yard/block_export.hpp"
#include "yard/block_import.hpp"
#include "yard/block_store.hpp"
#include "yard/catalogue.hpp"

namespace yardsim::cli {

using dynamics::Vector3;
using namespace yardsim::yard;

namespace {

// (text "a,b,c", count, what) => the numbers; DatabaseError for another count or a bad number
std::vector<double> numbers(const std::string& text, std::size_t count, const std::string& what) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string f;
  while (std::getline(in, f, ',')) {
    try {
      std::size_t used = 0;
      out.push_back(std::stod(f, &used));
      if (used != f.size()) throw std::invalid_argument(f);
    } catch (const std::exception&) {
      throw DatabaseError(what + ": expected numbers separated by commas, got '" + text + "'");
    }
  }
  if (out.size() != count)
    throw DatabaseError(what + ": expected " + std::to_string(count) + " numbers, got '" + text +
                        "'");
  return out;
}

// (NAME:x,y,z:dx,dy,dz:swl) => a lug
Lug lug(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string p;
  while (std::getline(in, p, ':')) parts.push_back(p);
  if (parts.size() != 4)
    throw DatabaseError("--lug: expected NAME:x,y,z:dx,dy,dz:swl (m, unit, N), got '" + text + "'");
  const auto x = numbers(parts[1], 3, "--lug " + parts[0]),
             d = numbers(parts[2], 3, "--lug " + parts[0]);
  return {parts[0], Vector3(x[0], x[1], x[2]), Vector3(d[0], d[1], d[2]),
          numbers(parts[3], 1, "--lug swl")[0]};
}

// (a) => the block the import-block options describe
Block importedBlock(const CLI::App& c, const DbArgs& a) {
  BlockSource s;
  const int given = !a.step.empty() + !a.obj.empty() + !a.stl.empty();
  if (given > 1) throw DatabaseError("import-block: give one of --step, --obj, --stl");
  s.geometry = !a.step.empty() ? a.step : !a.obj.empty() ? a.obj : a.stl;
  if (c.count("--density")) s.density = a.density;
  if (c.count("--mass")) s.mass = a.mass;
  if (!a.cog.empty()) s.cog = Vector3(a.cog[0], a.cog[1], a.cog[2]);
  if (!a.inertia.empty()) {
    dynamics::Matrix3 I = dynamics::Matrix3::Zero();
    I.diagonal() << a.inertia[0], a.inertia[1], a.inertia[2];
    if (a.inertia.size() == 6) {
      I(0, 1) = I(1, 0) = a.inertia[3];
      I(0, 2) = I(2, 0) = a.inertia[4];
      I(1, 2) = I(2, 1) = a.inertia[5];
    } else if (a.inertia.size() != 3) {
      throw DatabaseError("--inertia: expected Ixx,Iyy,Izz or Ixx,Iyy,Izz,Ixy,Ixz,Iyz (kg m^2)");
    }
    s.inertia = I;
  }
  s.tolerance = {a.chord, a.angleDeg * M_PI / 180.0};
  Block b = blockFromSource(a.name, s);
  b.project = a.project;
  if (!a.weightStatus.empty()) b.weightStatus = a.weightStatus;
  for (const auto& l : a.lugs) b.lugs.push_back(lug(l));
  return b;
}

// (csv of outreach,capacity with a header) => the curve
std::vector<CurvePoint> curve(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw DatabaseError(path + ": cannot open the hook-load curve");
  std::vector<CurvePoint> out;
  std::string line;
  std::getline(in, line);  // header: outreach,capacity (m, N)
  for (int n = 2; std::getline(in, line); ++n) {
    if (line.find_first_not_of(" \r") == std::string::npos) continue;
    const auto v = numbers(line, 2, path + ":" + std::to_string(n));
    out.push_back({v[0], v[1]});
  }
  return out;
}

// (block) => what `db show` prints
void printBlock(const Block& b) {
  const auto& I = b.inertia;
  std::printf(
      "block %s\n  project        %s\n  weight status  %s\n  source         %s\n  mass           "
      "%.6g kg\n"
      "  cog            %.6g %.6g %.6g m\n  inertia        Ixx %.6g Iyy %.6g Izz %.6g Ixy %.6g Ixz "
      "%.6g Iyz %.6g kg m^2\n",
      b.name.c_str(), b.project.c_str(), b.weightStatus.c_str(), b.source.c_str(), b.mass,
      b.cog.x(), b.cog.y(), b.cog.z(), I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2));
  if (b.mesh)
    std::printf("  mesh           %zu triangles, %zu vertices\n", b.mesh->triangles.size(),
                b.mesh->vertices.size());
  for (const Lug& l : b.lugs)
    std::printf("  lug %-10s at %.6g %.6g %.6g m, pull %.3g %.3g %.3g, SWL %.6g N\n",
                l.name.c_str(), l.position.x(), l.position.y(), l.position.z(), l.direction.x(),
                l.direction.y(), l.direction.z(), l.swl);
}

void printFacility(const Facility& f) {
  std::printf("facility %s (%s)\n  model file     %s\n  capacity       %.6g N\n", f.name.c_str(),
              f.kind.c_str(), f.modelFile.c_str(), f.capacity);
  if (f.hoistSpeed > 0) std::printf("  hoist speed    %.6g m/s\n", f.hoistSpeed);
  if (f.hoistAcceleration > 0) std::printf("  hoist accel.   %.6g m/s^2\n", f.hoistAcceleration);
  if (f.maxOutreach > 0) std::printf("  max outreach   %.6g m\n", f.maxOutreach);
  for (const CurvePoint& p : f.hookLoadCurve)
    std::printf("  curve          %.6g m: %.6g N\n", p.outreach, p.capacity);
}

void printRope(const Rope& r) {
  std::printf(
      "rope %s\n  construction   %s\n  diameter       %.6g m\n  EA             %.6g N\n  MBL       "
      "     %.6g N\n"
      "  mass           %.6g kg/m\n",
      r.name.c_str(), r.construction.c_str(), r.diameter, r.ea, r.mbl, r.massPerMetre);
}

// (db subcommand, arguments) => the chosen subcommand done
int run(const CLI::App& db, const DbArgs& a) {
  auto chosen = [&](const char* n) { return db.get_subcommand(n)->parsed(); };
  if (chosen("init")) {
    if (std::filesystem::exists(a.file)) {
      Database d = Database::openForWriting(a.file);  // migrates an older schema
      std::printf("%s: a yardsim database, schema version %d\n", a.file.c_str(), d.schemaVersion());
    } else {
      Database::create(a.file);
      std::printf("%s: created, schema version %d\n", a.file.c_str(), kSchemaVersion);
    }
    return kOk;
  }
  if (a.db.empty()) throw DatabaseError("no database: give --db FILE or set YARDSIM_DB");
  if (chosen("import-block")) {
    const Block b = importedBlock(*db.get_subcommand("import-block"), a);
    insertBlock(Database::openForWriting(a.db), b);
    std::printf(
        "%s: block %s added: %.6g kg%s\n", a.db.c_str(), b.name.c_str(), b.mass,
        b.mesh ? (", " + std::to_string(b.mesh->triangles.size()) + " triangles").c_str() : "");
    return kOk;
  }
  if (chosen("import-rope-catalogue")) {
    const int n = importRopeCatalogue(Database::openForWriting(a.db), a.file);
    std::printf("%s: %d rope(s) added from %s\n", a.db.c_str(), n, a.file.c_str());
    return kOk;
  }
  if (chosen("add-facility")) {
    Facility f{a.name,        a.kind, a.model, a.capacity, a.hoistSpeed, a.hoistAcceleration,
               a.maxOutreach, {}};
    if (!a.curve.empty()) f.hookLoadCurve = curve(a.curve);
    insertFacility(Database::openForWriting(a.db), f);
    std::printf("%s: facility %s added\n", a.db.c_str(), f.name.c_str());
    return kOk;
  }
  const Database d = Database::openReadOnly(a.db);
  if (chosen("list")) {
    if (a.what == "blocks")
      for (const auto& n : blockNames(d)) {
        const Block b = getBlock(d, n);
        std::printf("%-20s %-12s %14.6g kg  %s\n", n.c_str(), b.project.c_str(), b.mass,
                    b.weightStatus.c_str());
      }
    else if (a.what == "facilities")
      for (const auto& f : facilities(d))
        std::printf("%-20s %-10s %14.6g N  %s\n", f.name.c_str(), f.kind.c_str(), f.capacity,
                    f.modelFile.c_str());
    else
      for (const auto& r : ropes(d))
        std::printf("%-28s %8.4g m  EA %12.6g N  MBL %12.6g N\n", r.name.c_str(), r.diameter, r.ea,
                    r.mbl);
    return kOk;
  }
  if (chosen("show")) {
    if (auto b = findBlock(d, a.name))
      printBlock(*b);
    else if (auto f = findFacility(d, a.name))
      printFacility(*f);
    else
      printRope(getRope(d, a.name));  // names the ropes when nothing matches
    return kOk;
  }
  const std::string yaml = exportBlock(getBlock(d, a.name), a.outdir);
  std::printf("%s written\n", yaml.c_str());
  return kOk;
}

}  // namespace

CLI::App* addDbCommand(CLI::App& app, DbArgs& a) {
  auto* db =
      app.add_subcommand("db", "the yard's database of blocks, facilities and ropes (SQLite)");
  db->require_subcommand(1);
  db->add_option("-d,--db", a.db, "database file (default: $YARDSIM_DB)")->envname("YARDSIM_DB");
  db->add_subcommand("init", "create a database (or migrate an older one)")
      ->add_option("file", a.file, "database file")
      ->required();
  auto* ib = db->add_subcommand("import-block",
                                "add a block from STEP/OBJ/STL geometry or stated figures");
  ib->add_option("name", a.name, "block name")->required();
  ib->add_option("--step", a.step, "STEP file (B-rep mass properties, tessellated mesh)");
  ib->add_option("--obj", a.obj, "closed OBJ mesh");
  ib->add_option("--stl", a.stl, "closed STL mesh");
  ib->add_option("--density", a.density, "kg/m^3: mass, cog and inertia of the homogeneous solid");
  ib->add_option("--mass", a.mass, "kg (with --cog)");
  ib->add_option("--cog", a.cog, "x,y,z m, block frame")->delimiter(',')->expected(3);
  ib->add_option("--inertia", a.inertia, "Ixx,Iyy,Izz[,Ixy,Ixz,Iyz] kg m^2 about the cog")
      ->delimiter(',');
  ib->add_option("--lug", a.lugs,
                 "NAME:x,y,z:dx,dy,dz:swl (m, unit pull direction, N); repeatable");
  ib->add_option("--project", a.project, "project (hull number)");
  ib->add_option("--weight-status", a.weightStatus, "estimated|calculated|weighed")
      ->check(CLI::IsMember({"estimated", "calculated", "weighed"}));
  ib->add_option("--chord", a.chord, "STEP tessellation chord tolerance, m")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  ib->add_option("--angle-deg", a.angleDeg, "STEP tessellation angle tolerance, deg")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  db->add_subcommand("import-rope-catalogue",
                     "add ropes from a CSV: name,diameter,construction,EA,MBL,mass_per_metre")
      ->add_option("csv", a.file, "CSV file (m, N, kg/m)")
      ->required();
  auto* af = db->add_subcommand("add-facility", "add a crane: its YAML model and particulars");
  af->add_option("name", a.name, "facility name")->required();
  af->add_option("--kind", a.kind, "goliath|floating|overhead|other")
      ->capture_default_str()
      ->check(CLI::IsMember({"goliath", "floating", "overhead", "other"}));
  af->add_option("--model", a.model, "YAML model file, relative to the database")->required();
  af->add_option("--capacity", a.capacity, "N at the hook")->required();
  af->add_option("--hoist-speed", a.hoistSpeed, "m/s");
  af->add_option("--hoist-acceleration", a.hoistAcceleration, "m/s^2");
  af->add_option("--max-outreach", a.maxOutreach, "m");
  af->add_option("--curve", a.curve, "hook-load curve CSV: outreach,capacity (m, N) with a header");
  db->add_subcommand("list", "list blocks, facilities or ropes")
      ->add_option("what", a.what, "blocks|facilities|ropes")
      ->required()
      ->check(CLI::IsMember({"blocks", "facilities", "ropes"}));
  db->add_subcommand("show", "show a block, facility or rope")
      ->add_option("name", a.name)
      ->required();
  auto* ex = db->add_subcommand("export", "write a block as NAME.yaml and NAME.obj");
  ex->add_option("name", a.name)->required();
  ex->add_option("-o,--outdir", a.outdir, "folder")->capture_default_str();
  return db;
}

int dbCommand(const CLI::App& db, const DbArgs& a) {
  try {
    return run(db, a);
  } catch (const DatabaseError& e) {
    std::fprintf(stderr, "yardsim db: %s\n", e.what());
    return kInvalidInput;
  }
}

}  // namespace yardsim::cli
