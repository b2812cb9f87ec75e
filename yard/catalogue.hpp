#pragma once
// The rope and sling catalogue and the facilities (cranes) in the database.
#include <optional>
#include <string>
#include <vector>

#include "yard/database.hpp"
#include "yard/records.hpp"

namespace yardsim::yard {

// (database for writing, CSV file) => the number of ropes added, all in one transaction. The
// CSV has the header `name,diameter,construction,EA,MBL,mass_per_metre` (m, -, N, N, kg/m; a
// header in another column order is fine) and one rope a line; DatabaseError naming file:line
// for a bad number, a value <= 0, a missing column or a name already in the catalogue.
int importRopeCatalogue(const Database& db, const std::string& csvPath);
// (database, name) => the rope, or DatabaseError naming the catalogue's ropes
Rope getRope(const Database& db, const std::string& name);
// (database) => the catalogue, sorted by name
std::vector<Rope> ropes(const Database& db);

// (database for writing, facility) => stored with its hook-load curve in one transaction;
// DatabaseError for a duplicate name, capacity <= 0, a curve not ascending in outreach
void insertFacility(const Database& db, const Facility& f);
// (database, name) => the facility with its curve, or nothing
std::optional<Facility> findFacility(const Database& db, const std::string& name);
// (database) => the facilities, sorted by name
std::vector<Facility> facilities(const Database& db);

}  // namespace yardsim::yard
