#include "yard/catalogue.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "yard/block_store.hpp"

namespace yardsim::yard {

namespace {

// (CSV line) => its comma-separated fields, blanks around each trimmed
std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string f;
  while (std::getline(in, f, ',')) {
    const auto a = f.find_first_not_of(" \t\r"), b = f.find_last_not_of(" \t\r");
    out.push_back(a == std::string::npos ? "" : f.substr(a, b - a + 1));
  }
  return out;
}

// (text, where) => a finite number > 0, or DatabaseError at `where`
double positive(const std::string& text, const std::string& where) {
  double v = 0.0;
  std::size_t used = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v))
    throw DatabaseError(where + ": expected a number, got '" + text + "'");
  if (!(v > 0)) throw DatabaseError(where + ": must be > 0, got " + text);
  return v;
}

Rope ropeFrom(const Row& r) {
  return {asText(r[0]),   asNumber(r[1]), asText(r[2]),
          asNumber(r[3]), asNumber(r[4]), asNumber(r[5])};
}

const char* kRopeColumns =
    "SELECT name, diameter, construction, ea, mbl, mass_per_metre FROM ropes";

}  // namespace

int importRopeCatalogue(const Database& db, const std::string& csvPath) {
  std::ifstream in(csvPath);
  if (!in) throw DatabaseError(csvPath + ": cannot open the rope catalogue");
  std::string line;
  if (!std::getline(in, line))
    throw DatabaseError(csvPath + ":1: empty; expected the header " +
                        "name,diameter,construction,EA,MBL,mass_per_metre");
  const std::vector<std::string> header = fields(line);
  std::map<std::string, std::size_t> column;
  for (std::size_t i = 0; i < header.size(); ++i) column[header[i]] = i;
  for (const char* c : {"name", "diameter", "construction", "EA", "MBL", "mass_per_metre"})
    if (!column.count(c))
      throw DatabaseError(
          csvPath + ":1: the header has no column '" + c +
          "' (expected name,diameter,construction,EA,MBL,mass_per_metre in m, N, kg/m)");
  int added = 0;
  db.transaction([&] {
    for (std::size_t n = 2; std::getline(in, line); ++n) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      const std::string at = csvPath + ":" + std::to_string(n);
      const std::vector<std::string> f = fields(line);
      if (f.size() != header.size())
        throw DatabaseError(at + ": " + std::to_string(f.size()) + " fields, the header has " +
                            std::to_string(header.size()));
      Rope r{f[column["name"]],
             positive(f[column["diameter"]], at + ": diameter"),
             f[column["construction"]],
             positive(f[column["EA"]], at + ": EA"),
             positive(f[column["MBL"]], at + ": MBL"),
             positive(f[column["mass_per_metre"]], at + ": mass_per_metre")};
      if (r.name.empty()) throw DatabaseError(at + ": a rope needs a name");
      if (!db.query("SELECT 1 FROM ropes WHERE name = ?", {r.name}).empty())
        throw DatabaseError(at + ": rope '" + r.name + "' is already in the catalogue of " +
                            db.path());
      db.execute("INSERT INTO ropes VALUES (?, ?, ?, ?, ?, ?)",
                 {r.name, r.diameter, r.construction, r.ea, r.mbl, r.massPerMetre});
      ++added;
    }
  });
  return added;
}

Rope getRope(const Database& db, const std::string& name) {
  const auto rows = db.query(std::string(kRopeColumns) + " WHERE name = ?", {name});
  if (!rows.empty()) return ropeFrom(rows[0]);
  std::vector<std::string> names;
  for (const Rope& r : ropes(db)) names.push_back(r.name);
  throw DatabaseError(db.path() + ": " + unknownName(names, "rope", name));
}

std::vector<Rope> ropes(const Database& db) {
  std::vector<Rope> out;
  for (const Row& r : db.query(std::string(kRopeColumns) + " ORDER BY name"))
    out.push_back(ropeFrom(r));
  return out;
}

void insertFacility(const Database& db, const Facility& f) {
  const std::string what = db.path() + ": facility '" + f.name + "'";
  if (!(f.capacity > 0)) throw DatabaseError(what + ": the capacity must be > 0 N");
  for (std::size_t i = 0; i < f.hookLoadCurve.size(); ++i) {
    const CurvePoint& p = f.hookLoadCurve[i];
    if (!(p.capacity > 0) || p.outreach < 0 ||
        (i > 0 && !(p.outreach > f.hookLoadCurve[i - 1].outreach)))
      throw DatabaseError(
          what + ": the hook-load curve needs outreach >= 0 m ascending and capacity > 0 N");
  }
  db.transaction([&] {
    if (!db.query("SELECT 1 FROM facilities WHERE name = ?", {f.name}).empty())
      throw DatabaseError(what + " already exists");
    auto optional = [](double v) { return v > 0 ? Value(v) : Value(); };
    db.execute("INSERT INTO facilities VALUES (?, ?, ?, ?, ?, ?, ?)",
               {f.name, f.kind, f.modelFile, f.capacity, optional(f.hoistSpeed),
                optional(f.hoistAcceleration), optional(f.maxOutreach)});
    for (const CurvePoint& p : f.hookLoadCurve)
      db.execute("INSERT INTO hook_load_curves VALUES (?, ?, ?)", {f.name, p.outreach, p.capacity});
  });
}

std::optional<Facility> findFacility(const Database& db, const std::string& name) {
  const auto rows = db.query(
      "SELECT name, kind, model_file, capacity, hoist_speed, hoist_acceleration, max_outreach "
      "FROM facilities WHERE name = ?",
      {name});
  if (rows.empty()) return std::nullopt;
  const Row& r = rows[0];
  auto optional = [](const Value& v) { return isNull(v) ? 0.0 : asNumber(v); };
  Facility f{asText(r[0]),   asText(r[1]),   asText(r[2]),   asNumber(r[3]),
             optional(r[4]), optional(r[5]), optional(r[6]), {}};
  for (const Row& p : db.query(
           "SELECT outreach, capacity FROM hook_load_curves WHERE facility = ? ORDER BY outreach",
           {name}))
    f.hookLoadCurve.push_back({asNumber(p[0]), asNumber(p[1])});
  return f;
}

std::vector<Facility> facilities(const Database& db) {
  std::vector<Facility> out;
  for (const Row& r : db.query("SELECT name FROM facilities ORDER BY name"))
    out.push_back(*findFacility(db, asText(r[0])));
  return out;
}

}  // namespace yardsim::yard
