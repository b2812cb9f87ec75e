#include "output/base64.hpp"

#include <catch2/catch.hpp>

using yardsim::output::appendBase64;

TEST_CASE("base64 matches the RFC 4648 test vectors") {
  const std::pair<std::string, std::string> vectors[] = {
      {"", ""}, {"f", "Zg=="}, {"fo", "Zm8="}, {"foo", "Zm9v"},
      {"foob", "Zm9vYg=="}, {"fooba", "Zm9vYmE="}, {"foobar", "Zm9vYmFy"}};
  for (const auto& [in, out] : vectors) {
    std::string s = "x";
    appendBase64(s, in.data(), in.size());
    CHECK(s == "x" + out);
  }
  const unsigned char high[] = {0xff, 0xfe, 0x00};
  std::string s;
  appendBase64(s, high, 3);
  CHECK(s == "//4A");
}
