// General6Memo (devs/general_text_memo.hpp): every text it gives is appendGeneral6's fresh text.
#include "devs/general_text_memo.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "devs/general_text.hpp"

using namespace yardsim::devs;

namespace {
// (value) => appendGeneral6's text of it, formatted afresh
std::string fresh(double v) {
  std::string s;
  appendGeneral6(s, v);
  return s;
}
}  // namespace

TEST_CASE("a memo's text is a fresh format's for changed and unchanged values, slot by slot") {
  // (slots written in turn with values that repeat, change in their last bit, sign only, or
  // jump) => each append adds exactly the fresh text, after whatever out already held
  General6Memo memo;
  std::uint64_t s = 0x243f6a8885a308d3ULL;
  auto next = [&s] {  // splitmix64
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  std::vector<double> last(7, 0.25);
  std::size_t bad = 0, kept = 0;
  for (int round = 0; round < 20000; ++round)
    for (std::size_t slot = 0; slot < last.size(); ++slot) {
      double& v = last[slot];
      switch (next() % 6) {
        case 0:
        case 1: break;  // unchanged: the kept text
        case 2: v = std::nextafter(v, INFINITY); break;
        case 3: v = -v; break;
        case 4: v = (static_cast<double>(next() >> 11) * 0x1p-53 - 0.5) * std::pow(10.0, static_cast<double>(next() % 40) - 20.0); break;
        default: v = static_cast<double>(next() % 5) - 2.0; break;  // small integers and zeros
      }
      std::string out = "x,";
      memo.append(out, slot, v);
      bad += out != "x," + fresh(v);
      kept += out.size();
    }
  CHECK(bad == 0);
  CHECK(kept > 0);
}

TEST_CASE("a memo tells values apart by every bit: sign, last bit, neighbouring slots") {
  // values whose texts differ though their bits differ in one place only: the key must see it
  General6Memo memo;
  auto text = [&memo](std::size_t slot, double v) {
    std::string out;
    memo.append(out, slot, v);
    return out;
  };
  CHECK(text(0, 0.0) == "0");
  CHECK(text(0, -0.0) == "-0");  // equal as doubles, not in their bits
  CHECK(text(0, 0.0) == "0");
  // 1.234565 is near a tie of the sixth digit: its neighbours print differently
  const double tie = 1.234565;
  const double below = std::nextafter(tie, 0.0), above = std::nextafter(tie, 2.0);
  for (double v : {tie, below, above, below, tie, above, above}) CHECK(text(1, v) == fresh(v));
  CHECK(fresh(below) != fresh(above));  // the case is a real one: the texts differ
  // a slot keeps its own last value: the same values through other slots give their texts
  CHECK(text(2, 1.5) == "1.5");
  CHECK(text(3, 2.5) == "2.5");
  CHECK(text(2, 2.5) == "2.5");
  CHECK(text(3, 1.5) == "1.5");
  CHECK(text(40, std::nan("")) == fresh(std::nan("")));  // a far slot, first use
  CHECK(text(40, INFINITY) == "inf");
  CHECK(text(40, -1.7976931348623157e308) == "-1.79769e+308");
}
