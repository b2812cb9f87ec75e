// The log-log SVG plot: points land on the decades they belong to, and unusable points (zero,
// negative, infinite) are left out.
#include "models/svg_plot.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace yardsim;

namespace {
std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}
}  // namespace

TEST_CASE("log-log panels: decade ticks, one polyline per series, unusable points dropped") {
  models::PlotPanel p{"t", "x", "y", {{"a", {{1e-3, 1e-9}, {1e-1, 1e-7}, {0.0, 1.0}, {1.0, HUGE_VAL}}}}};
  const std::string svg = models::logLogSvg({p, p});
  CHECK(count(svg, "<polyline") == 2);
  CHECK(count(svg, "<circle") == 4);
  // x decades 1e-3..1e-1 and y decades 1e-9..1e-7 are labelled
  CHECK(count(svg, ">1e-3<") == 2);
  CHECK(count(svg, ">1e-1<") == 2);
  CHECK(count(svg, ">1e-9<") == 2);
  CHECK(count(svg, ">1e-7<") == 2);
  CHECK(count(svg, ">1e-6<") == 0);
  // the smallest point sits at the bottom-left corner of the first panel: (left, top + height)
  CHECK_THAT(svg, Catch::Contains("cx=\"70\" cy=\"290\""));
}
