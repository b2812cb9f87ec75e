// The disk cache of impulse responses: a write and read give back every value to the last bit
// (random bit patterns, -0, subnormals, the key); a flipped byte, a truncated file, another file
// type, another version and another key are refused with the file named and what is wrong; the
// folder follows YARDSIM_CACHE_DIR and XDG_CACHE_HOME; keys that are paths are refused.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <vector>

#include "forces/hydro/impulse_response_cache.hpp"
#include "support/scene_files.hpp"

using namespace yardsim::forces::hydro;

namespace {
// (seed) => a response whose numbers are random bit patterns of finite doubles, and a few special
// ones
ImpulseResponse randomResponse(unsigned seed) {
  std::mt19937_64 rng(seed);
  auto number = [&] {
    double x;
    do {
      const std::uint64_t bits = rng();
      std::memcpy(&x, &bits, 8);
    } while (!std::isfinite(x));
    return x;
  };
  ImpulseResponse ir;
  ir.key = "hull-3f9a_7.rtd";
  ir.dt = 0.05;
  for (int i = 0; i < 36; ++i) ir.aInf(i / 6, i % 6) = number();
  ir.aInf(0, 1) = -0.0;
  ir.aInf(0, 2) = 4.9e-324;
  ir.radiation.resize(37);
  for (auto& K : ir.radiation)
    for (int i = 0; i < 36; ++i) K(i / 6, i % 6) = number();
  ir.headings = {0.0, 1.5707963267948966, number()};
  ir.excitationStart = -3.25;
  ir.froudeKrylov = seed % 2 == 0;  // (seed 3: false, not the default) => the flag is stored
  ir.excitation.resize(3);
  for (std::size_t b = 0; b < 3; ++b) {
    ir.excitation[b].resize(10 + b);
    for (auto& x : ir.excitation[b])
      for (int i = 0; i < 6; ++i) x[i] = number();
  }
  return ir;
}

template <class M>
bool sameBits(const M& a, const M& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

std::vector<char> bytesOf(const std::filesystem::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
void writeBytes(const std::filesystem::path& f, const std::vector<char>& b) {
  std::ofstream(f, std::ios::binary).write(b.data(), static_cast<std::streamsize>(b.size()));
}
}  // namespace

TEST_CASE("a cached response reads back to the last bit") {
  yardsim::testing::SceneDir dir;
  const ImpulseResponse ir = randomResponse(3);
  const auto file = cacheFile(dir.path() / "cache", ir.key);
  writeImpulseResponse(ir, file);
  const auto back = loadCachedResponse(dir.path() / "cache", ir.key);
  REQUIRE(back);
  CHECK(back->key == ir.key);
  CHECK(std::memcmp(&back->dt, &ir.dt, 8) == 0);
  CHECK(std::memcmp(&back->excitationStart, &ir.excitationStart, 8) == 0);
  CHECK(sameBits(back->aInf, ir.aInf));
  CHECK_FALSE(back->froudeKrylov);
  ImpulseResponse withFk = ir;
  withFk.froudeKrylov = true;
  writeImpulseResponse(withFk, dir.path() / "fk.ysir");
  CHECK(readImpulseResponse(dir.path() / "fk.ysir").froudeKrylov);
  CHECK(std::signbit(back->aInf(0, 1)));
  REQUIRE(back->radiation.size() == ir.radiation.size());
  bool same = true;
  for (std::size_t k = 0; k < ir.radiation.size(); ++k)
    same = same && sameBits(back->radiation[k], ir.radiation[k]);
  REQUIRE(back->headings.size() == 3);
  for (std::size_t b = 0; b < 3; ++b) {
    same = same && std::memcmp(&back->headings[b], &ir.headings[b], 8) == 0;
    REQUIRE(back->excitation[b].size() == ir.excitation[b].size());
    for (std::size_t k = 0; k < ir.excitation[b].size(); ++k)
      same = same && sameBits(back->excitation[b][k], ir.excitation[b][k]);
  }
  CHECK(same);
  CHECK_FALSE(loadCachedResponse(dir.path() / "cache", "another-key"));  // (no file) => nothing
  CHECK_FALSE(std::filesystem::exists(file.string() + ".tmp"));
}

TEST_CASE("a damaged cache file is refused with what is wrong") {
  yardsim::testing::SceneDir dir;
  const ImpulseResponse ir = randomResponse(5);
  const auto file = cacheFile(dir.path(), ir.key);
  writeImpulseResponse(ir, file);
  const std::vector<char> good = bytesOf(file);
  SECTION("one byte flipped in the middle") {
    auto b = good;
    b[b.size() / 2] ^= 0x10;
    writeBytes(file, b);
    CHECK_THROWS_WITH(readImpulseResponse(file),
                      Catch::Contains(file.string()) && Catch::Contains("checksum"));
  }
  SECTION("cut short") {
    writeBytes(file,
               std::vector<char>(good.begin(), good.begin() + static_cast<long>(good.size()) / 3));
    CHECK_THROWS_AS(readImpulseResponse(file), CacheError);
  }
  SECTION("another file") {
    writeBytes(file,
               std::vector<char>{'s', 'o', 'l', 'i', 'd', ' ', 'x', '\n', 'e', 'n', 'd', 's',
                                 'o', 'l', 'i', 'd', 'x', 'x', 'x', 'x',  'x', 'x', 'x', 'x'});
    CHECK_THROWS_WITH(readImpulseResponse(file), Catch::Contains("not an impulse-response file"));
  }
  SECTION("another version, checksum right") {
    auto b = good;
    b[8] = 9;
    const std::uint64_t sum = fnv1a(b.data(), b.size() - 8);
    std::memcpy(b.data() + b.size() - 8, &sum, 8);
    writeBytes(file, b);
    CHECK_THROWS_WITH(readImpulseResponse(file), Catch::Contains("format version 9"));
  }
  SECTION("a Froude-Krylov flag neither 0 nor 1, checksum right") {
    // (magic, version, key, dt, aInf, K, headings, t0, w_c) => the flag's offset
    const std::size_t at = 8 + 4 + 4 + ir.key.size() + 8 + 36 * 8 + 8 +
                           ir.radiation.size() * 36 * 8 + 8 + ir.headings.size() * 8 + 8 + 8;
    auto b = good;
    std::uint32_t flag;
    std::memcpy(&flag, b.data() + at, 4);
    REQUIRE(flag == 0);
    flag = 7;
    std::memcpy(b.data() + at, &flag, 4);
    const std::uint64_t sum = fnv1a(b.data(), b.size() - 8);
    std::memcpy(b.data() + b.size() - 8, &sum, 8);
    writeBytes(file, b);
    CHECK_THROWS_WITH(readImpulseResponse(file), Catch::Contains("Froude-Krylov flag 7"));
  }
  SECTION("another key under this key's name") {
    std::filesystem::copy_file(file, cacheFile(dir.path(), "other"));
    CHECK_THROWS_WITH(loadCachedResponse(dir.path(), "other"), Catch::Contains("not 'other'"));
  }
}

TEST_CASE("the cache folder and the keys") {
  ::setenv("YARDSIM_CACHE_DIR", "/tmp/ys-cache", 1);
  CHECK(impulseResponseCacheDir() == std::filesystem::path("/tmp/ys-cache"));
  ::unsetenv("YARDSIM_CACHE_DIR");
  ::setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
  CHECK(impulseResponseCacheDir() == std::filesystem::path("/tmp/xdg/yardsim/impulse_responses"));
  CHECK(cacheFile("/c", "abc-1_2.x") == std::filesystem::path("/c/abc-1_2.x.ysir"));
  CHECK_THROWS_WITH(cacheFile("/c", "../etc/passwd"), Catch::Contains("expected letters"));
  CHECK_THROWS(cacheFile("/c", ""));
  // (FNV-1a 64 of "a", the published test vector) => af63dc4c8601ec8c
  CHECK(fnv1a("a", 1) == 0xaf63dc4c8601ec8cull);
}
