// OpenBLAS behind a module (forces/hydro/lapack_module.hpp): a process linked to yardsim::forces
// has neither OpenBLAS nor the module mapped until its first dense solve; the solve then loads
// them from beside libyardsim_forces.so and solves a system whose solution is known; a missing
// module, or a library without the entry, is refused naming the file and the fix.
#include <catch2/catch.hpp>

#include <filesystem>

#include "forces/hydro/dense_eigenvalues.hpp"
#include "forces/hydro/dense_solve.hpp"
#include "forces/hydro/lapack_module.hpp"
#include "support/loaded_objects.hpp"

using namespace yardsim::forces::hydro;
using Catch::Matchers::Contains;
using yardsim::testing::loaded;

TEST_CASE("OpenBLAS is mapped only once a dense solve needs it", "[lapack]") {
  // (each test case runs in its own process under ctest) => nothing of OpenBLAS at start-up
  CHECK_FALSE(loaded("libopenblas"));
  CHECK_FALSE(loaded("libyardsim_lapack"));
  // (a refused solve does not load it) => still nothing
  Eigen::MatrixXd notSquare(2, 3), rhs(2, 1);
  CHECK_THROWS_AS(solveInPlace(notSquare, rhs), std::invalid_argument);
  CHECK_FALSE(loaded("libopenblas"));
  // x + 2y = 5, 3x + 4y = 11 => x = 1, y = 2 (a row interchange on the way)
  Eigen::MatrixXd M(2, 2), B(2, 1);
  M << 1, 2, 3, 4;
  B << 5, 11;
  solveInPlace(M, B);
  CHECK(B(0) == Approx(1.0).epsilon(1e-14));
  CHECK(B(1) == Approx(2.0).epsilon(1e-14));
  CHECK(loaded("libyardsim_lapack"));
  CHECK(loaded("libopenblas"));
  // the eigenvalues of a rotation by 90 degrees, +-i, through the same module
  Eigen::MatrixXd R(2, 2);
  R << 0, -1, 1, 0;
  const Eigen::VectorXcd e = denseEigenvalues(R);
  CHECK(std::abs(e(0) - std::complex<double>(0, 1)) < 1e-14);
  CHECK(std::abs(e(1) - std::complex<double>(0, -1)) < 1e-14);
}

TEST_CASE("The LAPACK module sits beside libyardsim_forces and a missing one is named",
          "[lapack]") {
  const std::filesystem::path module = lapackModulePath();
  CHECK(module.filename() == "libyardsim_lapack.so");
  CHECK(std::filesystem::is_regular_file(module));
  CHECK(std::filesystem::is_regular_file(module.parent_path() / "libyardsim_forces.so"));
  CHECK_THROWS_WITH(loadLapackModule("/nonexistent/libyardsim_lapack.so"),
                    Contains("/nonexistent/libyardsim_lapack.so") && Contains("missing") &&
                        Contains("reinstall yardsim"));
  // a loadable library without the entry
  const std::string forces = (module.parent_path() / "libyardsim_forces.so").string();
  CHECK_THROWS_WITH(loadLapackModule(forces),
                    Contains(forces) && Contains("yardsim_lapack_routines"));
}
