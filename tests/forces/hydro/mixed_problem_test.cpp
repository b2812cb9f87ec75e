// The mixed boundary-value problem against a harmonic function known in closed form: the
// potential of a point source above the free surface, phi = 1/|x - x0| (x0 = (0.3, 0.2, 2) m), is
// harmonic in the fluid; given its normal derivative on a floating hemisphere and its value on
// the free surface, the solver must return its value on the hull and its normal derivative on the
// free surface. The same with a sea-bed image (phi + its mirror in z = -h, so phi_z = 0 on the
// bed). And the adjoint maps give the same functionals as the direct solve.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/LU>

#include "forces/hydro/free_surface_mesh.hpp"
#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/mixed_problem.hpp"
#include "forces/hydro/rankine_integrals.hpp"
#include "forces/hydro/wetted_surface.hpp"

using namespace yardsim::forces::hydro;

namespace {

struct Case {
  std::vector<Panel> body, surface;
};

Case hemisphere(int n, double truncation) {
  const PanelMesh wet = wettedSurface(cubeSphere(1.0, n));
  FreeSurfaceSettings s;
  s.truncationRadius = truncation;
  s.firstSpacing = 0.15;
  s.maxSpacing = 1.0;
  s.growth = 1.15;
  return {buildPanels(wet), buildPanels(buildFreeSurface(wet, s).mesh)};
}

// (x, source points with their signs) => phi and grad phi of sum 1/|x - x0|
double phiAt(const Vector3& x, const std::vector<Vector3>& sources) {
  double v = 0.0;
  for (const Vector3& s : sources) v += 1.0 / (x - s).norm();
  return v;
}
Vector3 gradAt(const Vector3& x, const std::vector<Vector3>& sources) {
  Vector3 v = Vector3::Zero();
  for (const Vector3& s : sources) v -= (x - s) / std::pow((x - s).norm(), 3);
  return v;
}

// (case, depth, sources) => largest errors of phi on the hull and of phi_n on the free surface,
// relative to the largest value of each
std::pair<double, double> errors(const Case& c, double depth, const std::vector<Vector3>& sources) {
  const MixedProblem pb(c.body, c.surface, depth);
  Eigen::MatrixXd a(pb.bodyCount(), 1), p(pb.surfaceCount(), 1);
  for (int k = 0; k < pb.bodyCount(); ++k)
    a(k, 0) = c.body[static_cast<std::size_t>(k)].normal.dot(
        gradAt(c.body[static_cast<std::size_t>(k)].centroid, sources));
  for (int k = 0; k < pb.surfaceCount(); ++k)
    p(k, 0) = phiAt(c.surface[static_cast<std::size_t>(k)].centroid, sources);
  const Eigen::MatrixXd u = pb.solve(a, p);
  double eb = 0.0, mb = 0.0, ef = 0.0, mf = 0.0;
  for (int k = 0; k < pb.bodyCount(); ++k) {
    const double exact = phiAt(c.body[static_cast<std::size_t>(k)].centroid, sources);
    eb = std::max(eb, std::abs(u(k, 0) - exact));
    mb = std::max(mb, std::abs(exact));
  }
  for (int k = 0; k < pb.surfaceCount(); ++k) {
    const Panel& q = c.surface[static_cast<std::size_t>(k)];
    const double exact = q.normal.dot(gradAt(q.centroid, sources));
    ef = std::max(ef, std::abs(u(pb.bodyCount() + k, 0) - exact));
    mf = std::max(mf, std::abs(exact));
  }
  return {eb / mb, ef / mf};
}

}  // namespace

TEST_CASE("the mixed problem reproduces a point source above the free surface") {
  const std::vector<Vector3> source{{0.3, 0.2, 2.0}};
  const auto [coarseBody, coarseSurface] =
      errors(hemisphere(6, 40.0), std::numeric_limits<double>::infinity(), source);
  const auto [fineBody, fineSurface] =
      errors(hemisphere(10, 40.0), std::numeric_limits<double>::infinity(), source);
  INFO("hull phi error " << coarseBody << " -> " << fineBody << ", free-surface phi_n error "
                         << coarseSurface << " -> " << fineSurface);
  // (the hull error is held at about 0.4 % by the truncation at 40 m, where phi ~ 1/r is cut off;
  // the free-surface error, largest at the waterline, falls with the panel size)
  CHECK(fineBody < 0.01);
  CHECK(coarseBody < 0.01);
  CHECK(fineSurface < 0.07);
  CHECK(fineSurface < 0.6 * coarseSurface);
}

TEST_CASE("the sea-bed image makes the bed a wall") {
  // the source and its mirror in z = -h: phi_z = 0 on the bed; a solver without the image fails
  const double h = 3.0;
  const std::vector<Vector3> sources{{0.3, 0.2, 2.0}, {0.3, 0.2, -2.0 * h - 2.0}};
  const Case c = hemisphere(8, 40.0);
  const auto [withBody, withSurface] = errors(c, h, sources);
  const auto [withoutBody, withoutSurface] =
      errors(c, std::numeric_limits<double>::infinity(), sources);
  INFO("with image " << withBody << ", " << withSurface << "; without " << withoutBody << ", "
                     << withoutSurface);
  CHECK(withBody < 0.01);
  CHECK(withSurface < 0.1);
  CHECK(withoutBody > 10.0 * withBody);
  CHECK(withoutSurface > 3.0 * withSurface);
}

TEST_CASE("the adjoint maps give the direct solve's functionals") {
  const Case c = hemisphere(4, 8.0);
  const MixedProblem pb(c.body, c.surface);
  const Eigen::MatrixXd w = Eigen::MatrixXd::Random(pb.size(), 3);
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(pb.bodyCount(), 2),
                        p = Eigen::MatrixXd::Random(pb.surfaceCount(), 2);
  const auto [qb, qf] = pb.adjointMaps(w);
  const Eigen::MatrixXd direct = w.transpose() * pb.solve(a, p);
  const Eigen::MatrixXd viaMaps = qb * a + qf * p;
  CHECK((direct - viaMaps).norm() < 1e-10 * direct.norm());
}

TEST_CASE("the solution map solves the assembled system, with and without the sea-bed image") {
  // (A = M^-1 [R_b R_f]) => M A = R, with M and R assembled here from the panel integrals on
  // their own; and A's last Nf rows and columns are the direct solve's phi_n,f for a = 0
  const Case c = hemisphere(4, 8.0);
  for (const double depth : {std::numeric_limits<double>::infinity(), 3.0}) {
    const MixedProblem pb(c.body, c.surface, depth);
    const int nb = pb.bodyCount(), nf = pb.surfaceCount(), n = pb.size();
    Eigen::MatrixXd M(n, n), R(n, n);
    for (int j = 0; j < n; ++j) {
      const Panel& pj = j < nb ? c.body[static_cast<std::size_t>(j)]
                               : c.surface[static_cast<std::size_t>(j - nb)];
      for (int i = 0; i < n; ++i) {
        const Vector3 x = i < nb ? c.body[static_cast<std::size_t>(i)].centroid
                                 : c.surface[static_cast<std::size_t>(i - nb)].centroid;
        PanelIntegrals v = panelIntegrals(pj, x);
        if (std::isfinite(depth)) {
          const PanelIntegrals w = panelIntegrals(pj, Vector3(x.x(), x.y(), -2.0 * depth - x.z()));
          v.source += w.source;
          v.dipole += w.dipole;
        }
        const double self = i == j ? 2.0 * std::numbers::pi : 0.0;
        M(i, j) = j < nb ? self - v.dipole : v.source;
        R(i, j) = j < nb ? -v.source : v.dipole - self;
      }
    }
    const Eigen::MatrixXd& A = pb.solutionMap();
    REQUIRE(A.rows() == n);
    REQUIRE(A.cols() == n);
    CHECK((M * A - R).norm() < 1e-12 * M.norm() * A.norm());
    // (any a, p) => solve is A [a; p]
    const Eigen::VectorXd a = Eigen::VectorXd::Random(nb), p = Eigen::VectorXd::Random(nf);
    Eigen::VectorXd ap(n);
    ap << a, p;
    const Eigen::VectorXd reference = M.partialPivLu().solve(R * ap);
    CHECK((pb.solve(a, p) - reference).norm() < 1e-11 * reference.norm());
    CHECK((A.bottomRightCorner(nf, nf) * p - pb.solve(Eigen::VectorXd::Zero(nb), p).bottomRows(nf))
              .norm() < 1e-12 * p.norm() * A.norm());
  }
}

TEST_CASE("a hull reaching the sea bed is refused") {
  const Case c = hemisphere(4, 8.0);
  CHECK_THROWS_WITH(MixedProblem(c.body, c.surface, 0.9), Catch::Contains("reaches the sea bed"));
}

TEST_CASE("a panel with non-finite geometry is refused, naming it") {
  // (a free-surface panel's centroid at NaN, as a degenerate panel would give) => PanelError
  // naming that panel, before any factorisation
  Case c = hemisphere(4, 8.0);
  c.surface[3].centroid.x() = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(MixedProblem(c.body, c.surface),
                    Catch::Contains("free-surface panel 3") && Catch::Contains("not finite"));
}
