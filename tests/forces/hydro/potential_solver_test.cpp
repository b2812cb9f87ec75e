// The potential solver: the surface potential of a translating sphere against the closed form
// phi = -a^3 U x / (2 r^3); GMRES against the dense LU (with and without the free-surface image),
// its iteration count nearly independent of the panel count, and its failure report.
#include <catch2/catch.hpp>

#include "forces/hydro/added_mass.hpp"
#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/wetted_surface.hpp"

using namespace yardsim::forces::hydro;
using Catch::Matchers::Contains;

TEST_CASE("a translating sphere's surface potential is -a^3 x / (2 r^3)") {
  const double a = 1.5;
  const PotentialSolver solver(buildPanels(cubeSphere(a, 12)), SolverOptions{});
  const Eigen::MatrixXd N = modeNormals(solver.panels(), Vector3::Zero());
  const Eigen::MatrixXd phi = solver.solve(N.leftCols(3));
  double worst = 0.0;
  for (std::size_t k = 0; k < solver.panels().size(); ++k) {
    const Vector3& c = solver.panels()[k].centroid;
    for (int j = 0; j < 3; ++j) {
      const double exact = -a * a * a * c[j] / (2.0 * c.norm() * c.norm() * c.norm());
      worst = std::max(worst, std::abs(phi(static_cast<Eigen::Index>(k), j) - exact));
    }
  }
  CHECK(worst < 0.01 * a / 2.0);
}

TEST_CASE("GMRES gives the LU's potentials in a number of iterations that hardly grows with N") {
  for (const FreeSurface fs : {FreeSurface::None, FreeSurface::NegativeImage}) {
    int iterations[2] = {0, 0};
    for (int level = 0; level < 2; ++level) {
      PanelMesh mesh = cubeSphere(2.0, level == 0 ? 6 : 12);
      if (fs == FreeSurface::NegativeImage) mesh = wettedSurface(mesh);
      const std::vector<Panel> panels = buildPanels(mesh);
      SolverOptions lu, gm;
      lu.freeSurface = gm.freeSurface = fs;
      gm.linearSolver = LinearSolver::Gmres;
      const PotentialSolver direct(panels, lu), iterative(panels, gm);
      const Eigen::MatrixXd N = modeNormals(panels, Vector3(0.2, -0.1, -0.3));
      const Eigen::MatrixXd a = direct.solve(N), b = iterative.solve(N);
      CHECK((a - b).norm() < 1e-8 * a.norm());
      CHECK(direct.lastIterations() == 0);
      iterations[level] = iterative.lastIterations();
      CHECK(iterations[level] > 0);
    }
    CHECK(iterations[1] <= iterations[0] + 10);
    CHECK(iterations[1] < 60);
  }
}

TEST_CASE("GMRES that cannot converge says so") {
  SolverOptions gm;
  gm.linearSolver = LinearSolver::Gmres;
  gm.gmresMaxIterations = 2;
  gm.gmresTolerance = 1e-15;
  const PotentialSolver solver(buildPanels(cubeSphere(1.0, 6)), gm);
  CHECK_THROWS_AS(solver.solve(modeNormals(solver.panels(), Vector3::Zero())), SolverError);
  CHECK_THROWS_WITH(solver.solve(modeNormals(solver.panels(), Vector3::Zero())), Contains("GMRES did not converge on 216 panels"));
}
