#include "devstone_models.hpp"

#include <catch2/catch.hpp>

#include "devs/simulator.hpp"

using namespace yardsim::bench::devstone;

TEST_CASE("DEVStone transition counts equal the closed forms for every variant") {
  for (Variant v : {Variant::LI, Variant::HI, Variant::HO, Variant::HOmod}) {
    for (int d = 1; d <= 6; ++d) {
      for (int w = 1; w <= 6; ++w) {
        auto root = build(v, d, w);
        yardsim::devs::Simulator sim(*root);
        sim.run();
        const Counts got = count(*root);
        const Counts want = expected(v, d, w);
        INFO(variantName(v) << " d=" << d << " w=" << w);
        CHECK(got.atomics == want.atomics);
        CHECK(got.internal == want.internal);
        CHECK(got.external == want.external);
      }
    }
  }
  CHECK(expected(Variant::HI, 100, 100).internal == 490051);  // the figure
}

TEST_CASE("DEVStone variant names round-trip and bad ones are refused") {
  for (const char* n : {"LI", "HI", "HO", "HOmod"}) CHECK(variantName(parseVariant(n)) == n);
  CHECK_THROWS_WITH(parseVariant("HX"), Catch::Contains("LI, HI, HO or HOmod"));
}
