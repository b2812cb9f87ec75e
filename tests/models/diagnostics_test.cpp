#include "models/diagnostics.hpp"

#include <catch2/catch.hpp>

using namespace yardsim::models;

TEST_CASE("did you mean picks the nearest name within a small distance") {
  CHECK(didYouMean("procesor", {"generator", "processor", "transducer"}) ==
        "did you mean 'processor'?");
  CHECK(didYouMean("SPEED", {"speed", "seed"}) == "did you mean 'speed'?");
  CHECK(didYouMean("xyzzy", {"generator", "processor"}).empty());
}

TEST_CASE("diagnostics format as file:line:column: severity: key: message (hint)") {
  Diagnostics d;
  d.error({"a.yaml", 3, 7}, "components.x.type", "unknown model type 'y'", "did you mean 'z'?");
  d.warning({"a.yaml", 9, 1}, "", "input port 'in' of 'p' is not connected");
  CHECK(d.hasErrors());
  CHECK(d.errorCount() == 1);
  CHECK(d.report() ==
        "a.yaml:3:7: error: components.x.type: unknown model type 'y' (did you mean 'z'?)\n"
        "a.yaml:9:1: warning: input port 'in' of 'p' is not connected\n");
}
