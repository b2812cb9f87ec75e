// The HDF5 writer, read back by h5py (an independent reader): every dataset type, nested
// groups, attributes, and a file that cannot be created.
#include <sys/wait.h>
#include <catch2/catch.hpp>
#include <cstdio>

#include "output/hdf5_file.hpp"
#include "output/hdf5_module.hpp"
#include "support/loaded_objects.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using yardsim::output::Hdf5File;

namespace {
// (python program) => its output, killed after 60 s
std::string python(const std::string& program, const std::string& file) {
  const std::string cmd = "timeout -s KILL 60 " + std::string(YARDSIM_PYTHON3) + " -c '" + program + "' " + file + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  std::string out;
  char buf[4096];
  while (std::size_t n = fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int raw = pclose(p);
  INFO(out);
  REQUIRE((WIFEXITED(raw) && WEXITSTATUS(raw) == 0));
  return out;
}
}  // namespace

TEST_CASE("Datasets and attributes written by Hdf5File read back with h5py") {
  yardsim::testing::SceneDir dir;
  const std::string file = dir.file("t.h5");
  {
    Hdf5File h(file);
    h.doubles("/a/b/x", {0.1, -2.5e300, 1.0 / 3.0});
    h.integers("/a/n", {1, -7, 1LL << 40});
    h.strings("/a/s", {"ok", "", "failed: NaN in 'hook' at t = 1.5 s"});
    h.doubles("/empty", {});
    h.attribute("/a/b/x", "unit", "m");
    h.attribute("/", "sweep", "sweep.yaml");
  }
  const std::string out = python(
      "import sys, h5py\n"
      "f = h5py.File(sys.argv[1], \"r\")\n"
      "print([repr(float(v)) for v in f[\"a/b/x\"][:]])\n"
      "print([int(v) for v in f[\"a/n\"][:]])\n"
      "print(list(f[\"a/s\"].asstr()[:]))\n"
      "print(f[\"empty\"].shape, f[\"a/b/x\"].attrs[\"unit\"], f.attrs[\"sweep\"])\n",
      file);
  CHECK(out ==
        "['0.1', '-2.5e+300', '0.3333333333333333']\n"
        "[1, -7, 1099511627776]\n"
        "['ok', '', \"failed: NaN in 'hook' at t = 1.5 s\"]\n"
        "(0,) m sweep.yaml\n");
}

TEST_CASE("An HDF5 file that cannot be created throws naming it") {
  CHECK_THROWS_WITH(Hdf5File("/nonexistent-folder/x.h5"),
                    Catch::Contains("/nonexistent-folder/x.h5"));
}

TEST_CASE("libhdf5 is loaded with the first HDF5 file, not before") {
  using yardsim::testing::loaded;
  // (each test case runs in its own process under ctest) => nothing of HDF5 at start-up: the
  // writer's module and libhdf5 come with the first file
  CHECK_FALSE(loaded("libhdf5"));
  CHECK_FALSE(loaded("libyardsim_hdf5"));
  yardsim::testing::SceneDir dir;
  { Hdf5File h(dir.file("first.h5")); }
  CHECK(loaded("libhdf5"));
  CHECK(loaded("libyardsim_hdf5"));
}

TEST_CASE("A missing HDF5 module is an error naming it and the fix") {
  CHECK_THROWS_WITH(yardsim::output::loadHdf5Module("/nonexistent-folder/libyardsim_hdf5.so"),
                    Catch::Contains("/nonexistent-folder/libyardsim_hdf5.so") &&
                        Catch::Contains("reinstall yardsim"));
}
