// A run's time series in HDF5, read back by h5py: every column with its unit, the metadata.
#include <sys/wait.h>
#include <catch2/catch.hpp>
#include <cstdio>

#include "output/timeseries_hdf5.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

TEST_CASE("timeseries.h5 holds every column of timeseries.csv with its unit, read by h5py") {
  yardsim::testing::SceneDir dir;
  const auto csv =
      dir.write("timeseries.csv",
                "# yardsim 0.1.0\n# scene a.yaml\ntime[s],crane.hoist.tension[N],x[m]\n"
                "0,1.5e6,nan\n0.5,-2,0.1\n");
  yardsim::output::writeTimeseriesHdf5(csv, dir.path() / "timeseries.h5");
  const std::string cmd =
      "timeout -s KILL 60 " + std::string(YARDSIM_PYTHON3) + " -c 'import sys, h5py\n"
      "g = h5py.File(sys.argv[1], \"r\")[\"series\"]\n"
      "print(sorted(g.keys()), g.attrs[\"scene\"], g[\"crane.hoist.tension\"].attrs[\"unit\"])\n"
      "print([repr(float(v)) for v in g[\"x\"][:]], [float(v) for v in g[\"time\"][:]])' " +
      (dir.path() / "timeseries.h5").string() + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  std::string out;
  char buf[4096];
  while (std::size_t n = fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int raw = pclose(p);
  INFO(out);
  REQUIRE((WIFEXITED(raw) && WEXITSTATUS(raw) == 0));
  CHECK(out == "['crane.hoist.tension', 'time', 'x'] a.yaml N\n['nan', '0.1'] [0.0, 0.5]\n");
}
