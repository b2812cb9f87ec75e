// The database file: created with the current schema and our application_id, opened read-only
// by runs (writes refused), writes in transactions (rolled back on error), and foreign, damaged,
// empty, newer and older files told apart with clear messages.
#include <sqlite3.h>
#include <catch2/catch.hpp>

#include <fstream>

#include "support/scene_files.hpp"
#include "yard/database.hpp"
#include "yard/schema.hpp"

using namespace yardsim::yard;
using Catch::Matchers::Contains;
using yardsim::testing::SceneDir;

namespace {
// (path, SQL) => the SQL run by plain SQLite, as another program would
void raw(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open(path.c_str(), &db) == SQLITE_OK);
  REQUIRE(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr) == SQLITE_OK);
  sqlite3_close(db);
}
}  // namespace

TEST_CASE("a new database has the current schema, our application_id and its tables") {
  SceneDir dir;
  const std::string path = dir.file("yard.sqlite");
  { Database::create(path); }
  const Database db = Database::openReadOnly(path);
  CHECK(db.schemaVersion() == kSchemaVersion);
  CHECK(kSchemaVersion == static_cast<int>(migrations().size()));
  CHECK(asNumber(db.query("PRAGMA application_id")[0][0]) == kApplicationId);
  std::vector<std::string> tables;
  for (const Row& r : db.query("SELECT name FROM sqlite_schema WHERE type = 'table' ORDER BY name"))
    tables.push_back(asText(r[0]));
  CHECK(tables == std::vector<std::string>{"blocks", "facilities", "friction_pairs",
                                           "hook_load_curves", "lugs", "materials", "ropes"});
  CHECK_THROWS_WITH(Database::create(path), Contains("already exists"));
}

TEST_CASE("a read-only database refuses writes, and a failed transaction leaves nothing behind") {
  SceneDir dir;
  const std::string path = dir.file("yard.sqlite");
  { Database::create(path); }
  const Database ro = Database::openReadOnly(path);
  CHECK_THROWS_WITH(ro.execute("INSERT INTO materials VALUES ('steel', 7850)"),
                    Contains("readonly"));
  const Database rw = Database::openForWriting(path);
  CHECK_THROWS_AS(rw.transaction([&] {
    rw.execute("INSERT INTO materials VALUES ('steel', 7850)");
    rw.execute("INSERT INTO materials VALUES ('steel', 7850)");  // duplicate: the whole unit goes
  }),
                  DatabaseError);
  CHECK(rw.query("SELECT * FROM materials").empty());
  rw.transaction([&] {
    rw.execute("INSERT INTO materials VALUES (?, ?)", {std::string("steel"), 7850.0});
  });
  CHECK(asNumber(ro.query("SELECT density FROM materials")[0][0]) ==
        7850.0);  // a second reader sees it
  // the schema's own checks hold too: a density <= 0 is refused by SQLite
  CHECK_THROWS_WITH(rw.execute("INSERT INTO materials VALUES ('air', -1)"), Contains("CHECK"));
}

TEST_CASE("files that are not our database are refused with what they are") {
  SceneDir dir;
  CHECK_THROWS_WITH(Database::openReadOnly(dir.file("none.sqlite")), Contains("no such database"));
  dir.write("text.sqlite", std::string(4096, 'x'));
  CHECK_THROWS_WITH(Database::openReadOnly(dir.file("text.sqlite")),
                    Contains("not a readable yardsim database"));
  raw(dir.file("other.sqlite"), "CREATE TABLE t(x); PRAGMA application_id = 1234;");
  CHECK_THROWS_WITH(Database::openReadOnly(dir.file("other.sqlite")),
                    Contains("another program's") && Contains("1234"));
  CHECK_THROWS_WITH(Database::openForWriting(dir.file("other.sqlite")),
                    Contains("another program's"));
  raw(dir.file("empty.sqlite"), "PRAGMA user_version = 0;");
  CHECK_THROWS_WITH(Database::openReadOnly(dir.file("empty.sqlite")),
                    Contains("empty SQLite file"));
  // a database of ours whose first page was overwritten after its header
  const std::string damaged = dir.file("damaged.sqlite");
  { Database::create(damaged); }
  {
    std::fstream f(damaged, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(100);  // page 1 past the file header: the schema table's b-tree
    const std::string junk(2000, '\x5a');
    f.write(junk.data(), static_cast<std::streamsize>(junk.size()));
  }
  CHECK_THROWS_WITH(Database::openReadOnly(damaged), Contains("damaged"));
}

TEST_CASE("a newer schema is refused, an older one is migrated by a writer only") {
  SceneDir dir;
  const std::string newer = dir.file("newer.sqlite"), older = dir.file("older.sqlite");
  { Database::create(newer); }
  raw(newer, "PRAGMA user_version = " + std::to_string(kSchemaVersion + 1));
  CHECK_THROWS_WITH(Database::openReadOnly(newer), Contains("newer yardsim"));
  // version 0 with our id: what `create` starts from before the first migration
  raw(older, "PRAGMA application_id = " + std::to_string(kApplicationId));
  CHECK_THROWS_WITH(Database::openReadOnly(older), Contains("older") && Contains("db init"));
  CHECK(Database::openForWriting(older).schemaVersion() == kSchemaVersion);
  CHECK(Database::openReadOnly(older).query("SELECT * FROM ropes").empty());
}
