#include "devs/checkpoint_archive.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <tuple>
#include <vector>

using namespace yardsim;
using devs::CheckpointError;
using devs::CheckpointReader;
using devs::CheckpointWriter;

namespace {
struct Sample {
  enum class Mode { Off, On };
  double x = 0.0;
  int n = 0;
  bool flag = false;
  Mode mode = Mode::Off;
  std::string name;
  std::vector<double> history;
  std::set<std::string> seen;
  bool operator==(const Sample&) const = default;
};
}  // namespace

namespace yardsim::devs {
template <>
struct StateCodec<Sample> : FieldCodec<Sample> {
  static auto fields(auto& s) {
    return std::tie(s.x, s.n, s.flag, s.mode, s.name, s.history, s.seen);
  }
};
}  // namespace yardsim::devs

namespace {
Sample sample() {
  const double tiny = std::numeric_limits<double>::denorm_min();
  return {0.1 + 0.2,
          -7,
          true,
          Sample::Mode::On,
          "GOC201.hoist1",
          {1.0 / 3.0, -0.0, tiny, 1e308, std::numeric_limits<double>::infinity()},
          {"a", "b.c"}};
}
}  // namespace

TEST_CASE("a state archived and read back is the same value to the last bit") {
  CheckpointWriter w;
  w.section("sample");
  devs::save(w, sample());
  CheckpointReader r(w.bytes());
  r.section("sample");
  Sample back;
  devs::load(r, back);
  CHECK(back == sample());
  CHECK(std::signbit(back.history[1]));  // -0.0 keeps its sign
  CHECK(r.atEnd());
}

TEST_CASE("NaN survives an archive with its bits") {
  CheckpointWriter w;
  w.f64(std::numeric_limits<double>::quiet_NaN());
  CheckpointReader r(w.bytes());
  CHECK(std::isnan(r.f64()));
}

TEST_CASE("a truncated archive is refused at every length, never half-read") {
  CheckpointWriter w;
  w.section("sample");
  devs::save(w, sample());
  const std::string& bytes = w.bytes();
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    CheckpointReader r(std::string_view(bytes).substr(0, n));
    Sample back;
    CHECK_THROWS_AS((r.section("sample"), devs::load(r, back)), CheckpointError);
  }
}

TEST_CASE("another type or section than expected is refused with what was expected") {
  CheckpointWriter w;
  w.i64(3);
  w.section("multibody");
  CheckpointReader r(w.bytes());
  CHECK_THROWS_WITH(r.f64(), Catch::Contains("an integer where a number was expected"));
  CheckpointReader r2(w.bytes());
  r2.i64();
  CHECK_THROWS_WITH(r2.section("actor"), Catch::Contains("the section 'actor'"));
}

TEST_CASE("a list longer than the bytes left is refused before anything is allocated") {
  CheckpointWriter w;
  w.list(std::size_t{1} << 60);
  CheckpointReader r(w.bytes());
  CHECK_THROWS_WITH(r.list(), Catch::Contains("longer than the checkpoint"));
}
