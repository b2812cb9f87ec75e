// The rope catalogue from CSV files (real files, columns in any order) and facilities with their
// hook-load curves; errors name file:line.
#include <catch2/catch.hpp>

#include "support/scene_files.hpp"
#include "yard/catalogue.hpp"

using namespace yardsim::yard;
using Catch::Matchers::Contains;
using yardsim::testing::SceneDir;

TEST_CASE("a rope catalogue imports, lists sorted and finds ropes by name") {
  SceneDir dir;
  const Database db = Database::create(dir.file("yard.sqlite"));
  dir.write("ropes.csv",
            "name,construction,diameter,EA,MBL,mass_per_metre\n"
            "6x36 IWRC 64 mm, 6x36 IWRC, 0.064, 2.1e8, 3.2e6, 17.6\n\n"
            "6x36 IWRC 52 mm,6x36 IWRC,0.052,1.4e8,2.1e6,11.6\r\n");
  CHECK(importRopeCatalogue(db, dir.file("ropes.csv")) == 2);
  const auto all = ropes(db);
  REQUIRE(all.size() == 2);
  CHECK(all[0].name == "6x36 IWRC 52 mm");
  const Rope r = getRope(db, "6x36 IWRC 64 mm");
  CHECK(r.diameter == 0.064);
  CHECK(r.ea == 2.1e8);
  CHECK(r.mbl == 3.2e6);
  CHECK(r.massPerMetre == 17.6);
  CHECK(r.construction == "6x36 IWRC");
  CHECK_THROWS_WITH(getRope(db, "6x36 64"),
                    Contains("unknown rope") && Contains("6x36 IWRC 52 mm"));
}

TEST_CASE("a bad catalogue is refused at its line and adds nothing") {
  SceneDir dir;
  const Database db = Database::create(dir.file("yard.sqlite"));
  dir.write("bad.csv",
            "name,diameter,construction,EA,MBL,mass_per_metre\na,0.05,x,1e8,2e6,10\nb,0.05,x,-1e8,"
            "2e6,10\n");
  CHECK_THROWS_WITH(importRopeCatalogue(db, dir.file("bad.csv")),
                    Contains("bad.csv:3: EA") && Contains("> 0"));
  CHECK(ropes(db).empty());  // the good first line rolled back with the bad one
  dir.write("word.csv", "name,diameter,construction,EA,MBL,mass_per_metre\na,thick,x,1e8,2e6,10\n");
  CHECK_THROWS_WITH(importRopeCatalogue(db, dir.file("word.csv")),
                    Contains("word.csv:2: diameter"));
  dir.write("cols.csv", "name,diameter,EA\n");
  CHECK_THROWS_WITH(importRopeCatalogue(db, dir.file("cols.csv")),
                    Contains("no column 'construction'"));
  CHECK_THROWS_WITH(importRopeCatalogue(db, dir.file("none.csv")), Contains("cannot open"));
  dir.write("dup.csv",
            "name,diameter,construction,EA,MBL,mass_per_metre\na,0.05,x,1e8,2e6,10\na,0.05,x,1e8,"
            "2e6,10\n");
  CHECK_THROWS_WITH(importRopeCatalogue(db, dir.file("dup.csv")),
                    Contains("dup.csv:3") && Contains("already"));
}

TEST_CASE("facilities keep their particulars and hook-load curve") {
  SceneDir dir;
  const Database db = Database::create(dir.file("yard.sqlite"));
  Facility f{"GOC201",
             "goliath",
             "cranes/goliath.yaml",
             4.5e6,
             0.083,
             0.05,
             0,
             {{0, 4.5e6}, {10, 4.0e6}, {20, 3e6}}};
  insertFacility(db, f);
  const auto back = findFacility(db, "GOC201");
  REQUIRE(back);
  CHECK(back->modelFile == "cranes/goliath.yaml");
  CHECK(back->hoistSpeed == 0.083);
  CHECK(back->maxOutreach == 0);
  REQUIRE(back->hookLoadCurve.size() == 3);
  CHECK(back->hookLoadCurve[2].capacity == 3e6);
  CHECK(facilities(db).size() == 1);
  CHECK_THROWS_WITH(insertFacility(db, f), Contains("already exists"));
  f.name = "X";
  f.hookLoadCurve = {{10, 1e6}, {5, 1e6}};
  CHECK_THROWS_WITH(insertFacility(db, f), Contains("ascending"));
  f.hookLoadCurve.clear();
  f.capacity = 0;
  CHECK_THROWS_WITH(insertFacility(db, f), Contains("capacity must be > 0"));
}
