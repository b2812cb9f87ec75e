#include "devs/model.hpp"

#include <catch2/catch.hpp>
#include <string>

using yardsim::devs::checkName;
using yardsim::devs::ModelError;

TEST_CASE("a name is refused for a forbidden byte at any position, accepted otherwise") {
  // (names of 1 to 24 bytes, a forbidden byte at each position in turn) => refused, naming it;
  // the same names with an allowed byte there => accepted (eight bytes at a time, then the rest)
  for (std::size_t n = 1; n <= 24; ++n) {
    for (std::size_t at = 0; at < n; ++at) {
      std::string name(n, 'a');
      for (std::size_t k = 0; k < n; ++k) name[k] = static_cast<char>('a' + (k * 7) % 26);
      CHECK_NOTHROW(checkName(name, "model"));
      for (const char bad : {'.', ' ', '\t', '\n', '"'}) {
        name[at] = bad;
        CHECK_THROWS_AS(checkName(name, "model"), ModelError);
      }
      // bytes next to the forbidden ones in value, and bytes past 0x7f, are allowed
      for (const char ok : {'-', '/', '!', '#', '\x0b', '\x80', '\xae', '\xff', '_'}) {
        name[at] = ok;
        CHECK_NOTHROW(checkName(name, "model"));
      }
    }
  }
  CHECK_THROWS_WITH(checkName("", "port"), Catch::Contains("must not be empty"));
  CHECK_THROWS_WITH(checkName("abcdefghij.k", "port"), Catch::Contains("contains '.'"));
}
