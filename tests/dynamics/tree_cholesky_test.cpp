// The tree-sparse Cholesky factorisation M = L^T L: against Eigen's dense LLT on random trees
// (chains, branched trees, floating bases, every joint type, added mass), the residual of
// M x = b, and the sparsity: L is zero off each dof's ancestor set, which is derived here from
// the bodies' parents, independently of model.dofParent.
#include <catch2/catch.hpp>

#include <Eigen/Cholesky>
#include <limits>
#include <vector>

#include "dynamics/configuration.hpp"
#include "dynamics/crba.hpp"
#include "dynamics/tree_cholesky.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

namespace {

// (model) => A(i, j) = 1 when dof j is dof i or one of its ancestors (from the body tree)
Eigen::MatrixXi ancestorPattern(const Model& m) {
  Eigen::MatrixXi A = Eigen::MatrixXi::Zero(m.nv, m.nv);
  for (int i = 0; i < m.nv; ++i) {
    for (int j = 0; j <= i; ++j) {
      const int bi = m.dofBody[i], bj = m.dofBody[j];
      bool anc = bi == bj;
      for (int b = m.parent[bi]; b > 0 && !anc; b = m.parent[b]) anc = b == bj;
      A(i, j) = anc ? 1 : 0;
    }
  }
  return A;
}

// (N) => a free-floating 1000 kg block with four branches of revolute and prismatic joints
// alternating, axes cycling x, y, z (the shape of bench/peers' tree)
Model floatingTree(int perBranch) {
  ModelBuilder b;
  b.addBody("block", "world", Joint::free(), {},
            makeInertia(1000.0, Vector3::Zero(), Vector3(1e3, 2e3, 2.5e3).asDiagonal()));
  const double corner[4][2] = {{5, 3}, {-5, 3}, {-5, -3}, {5, -3}};
  for (int br = 0; br < 4; ++br) {
    for (int j = 0; j < perBranch; ++j) {
      const std::string name = indexed("b", br * 100 + j),
                        parent = j == 0 ? "block" : indexed("b", br * 100 + j - 1);
      const Vector3 axis = Vector3::Unit(j % 3);
      const Vector3 off =
          j == 0 ? Vector3(corner[br][0], corner[br][1], 1.0) : Vector3(0.1, 0.2, 2.0);
      b.addBody(
          name, parent, j % 2 == 0 ? Joint::revolute(axis) : Joint::prismatic(axis),
          Transform::translation(off),
          makeInertia(50.0, Vector3(0.05, -0.02, 1.0), Vector3(20.0, 21.0, 2.0).asDiagonal()));
    }
  }
  return b.build();
}

// (model, seed) => checks of the factorisation at a random configuration
void checkFactorisation(const Model& m, std::mt19937& rng) {
  Data d(m);
  const Eigen::VectorXd q = randomConfiguration(m, rng);
  const Eigen::MatrixXd M = crba(m, d, q);
  REQUIRE(choleskyFactor(m, d));
  const Eigen::MatrixXd& L = d.L;
  // (L) => L^T L reproduces M
  const Eigen::MatrixXd Lt = L.triangularView<Eigen::Lower>();
  CHECK(relativeError(Lt.transpose() * Lt, M) < 1e-13);
  // (pattern) => L and M are zero off the ancestor set; L's diagonal is positive
  const Eigen::MatrixXi P = ancestorPattern(m);
  for (int i = 0; i < m.nv; ++i) {
    CHECK(L(i, i) > 0.0);
    for (int j = 0; j < m.nv; ++j) {
      const bool related = j <= i ? P(i, j) != 0 : P(j, i) != 0;
      if (j > i || !related) CHECK(L(i, j) == 0.0);
      if (!related) CHECK(M(i, j) == 0.0);
    }
  }
  // (b) => x = M^-1 b: residual and Eigen's dense LLT
  const Eigen::VectorXd b = randomVectorX(rng, m.nv);
  Eigen::VectorXd x = b;
  choleskySolveInPlace(m, d, x);
  const Eigen::LLT<Eigen::MatrixXd> llt(M);
  REQUIRE(llt.info() == Eigen::Success);
  const Eigen::VectorXd xd = llt.solve(b);
  CHECK((M * x - b).norm() <= 1e-13 * M.norm() * x.norm());
  CHECK((x - xd).norm() <= 1e-9 * xd.norm());
  // (B) => M^-1 B column by column, as the vector solve
  Eigen::MatrixXd B = Eigen::MatrixXd::Random(m.nv, 3);
  const Eigen::MatrixXd B0 = B;
  choleskySolveInPlace(m, d, B);
  CHECK((M * B - B0).norm() <= 1e-13 * M.norm() * B.norm());
  Eigen::VectorXd col = B0.col(1);
  choleskySolveInPlace(m, d, col);
  CHECK(col == B.col(1));
}

}  // namespace

TEST_CASE("tree Cholesky: random trees with every joint type and added mass match dense LLT") {
  std::mt19937 rng(2105);
  for (int n : {1, 2, 5, 12, 30}) {
    for (bool added : {false, true}) {
      INFO("bodies " << n << " added mass " << added);
      checkFactorisation(randomTree(rng, n, {0.0, 0.0, -9.81}, added), rng);
    }
  }
}

TEST_CASE("tree Cholesky: planar chains and the floating-base tree with prismatic branches") {
  std::mt19937 rng(2106);
  for (int n : {1, 8, 33, 64, 97})
    checkFactorisation(planarChain(n), rng);  // 64 on: the dense path
  for (int k : {1, 2, 8}) checkFactorisation(floatingTree(k), rng);
}

TEST_CASE("tree Cholesky: the dof tree of the model follows its bodies") {
  std::mt19937 rng(2107);
  const Model m = randomTree(rng, 25);
  const Eigen::MatrixXi P = ancestorPattern(m);
  for (int i = 0; i < m.nv; ++i) {
    // (dofParent walk) => the same ancestor set as the body tree
    Eigen::VectorXi walk = Eigen::VectorXi::Zero(m.nv);
    walk[i] = 1;
    for (int j = m.dofParent[i]; j >= 0; j = m.dofParent[j]) {
      CHECK(j < i);
      walk[j] = 1;
    }
    CHECK(walk.head(i + 1) == P.row(i).head(i + 1).transpose());
    // (subtree) => the dofs with i among their ancestors: i .. i + dofSubtree[i] - 1
    int count = 0;
    for (int k = i; k < m.nv; ++k) count += P(k, i);
    CHECK(count == m.dofSubtree[i]);
    for (int k = i; k < i + m.dofSubtree[i]; ++k) CHECK(P(k, i) == 1);
  }
}

TEST_CASE("tree Cholesky: a matrix that is not positive definite is reported") {
  std::mt19937 rng(2108);
  const Model m = randomTree(rng, 6);
  Data d(m);
  crba(m, d, randomConfiguration(m, rng));
  d.M(0, 0) = -1.0;
  CHECK_FALSE(choleskyFactor(m, d));
  d.M = -d.M;
  CHECK_FALSE(choleskyFactor(m, d));
}

TEST_CASE("tree Cholesky: the generic kernel on a dense chain pattern equals the dense LLT solve") {
  std::mt19937 rng(2109);
  const int n = 20;
  const Eigen::MatrixXd G = Eigen::MatrixXd::Random(n, n);
  const Eigen::MatrixXd A = G * G.transpose() + n * Eigen::MatrixXd::Identity(n, n);
  std::vector<int> parent(n), subtree(n);
  for (int i = 0; i < n; ++i) {
    parent[static_cast<std::size_t>(i)] = i - 1;
    subtree[static_cast<std::size_t>(i)] = n - i;
  }
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd work(n);
  REQUIRE(treeCholeskyFactor(A, parent, subtree, L, work));
  const Eigen::VectorXd b = randomVectorX(rng, n);
  Eigen::VectorXd x = b;
  treeCholeskySolveInPlace(L, subtree, x);
  CHECK((x - A.llt().solve(b)).norm() < 1e-12 * x.norm());
}

namespace {

// (n, rng, top) => a random dof tree in depth-first order: parent[i] on the path from the root to
// i - 1 (or -1: a forest); top: dofs 0 .. 5 a chain at the single root (a floating base)
std::vector<int> randomDofTree(int n, std::mt19937& rng, bool top) {
  std::vector<int> parent(static_cast<std::size_t>(n), -1);
  for (int i = 1; i < n; ++i) {
    if (top && i < 6) {
      parent[static_cast<std::size_t>(i)] = i - 1;
      continue;
    }
    std::vector<int> path;  // i - 1 and its ancestors
    for (int j = i - 1; j >= 0; j = parent[static_cast<std::size_t>(j)]) path.push_back(j);
    if (top) path.resize(path.size() - 5);  // below dof 5
    std::uniform_int_distribution<int> pick(top ? 0 : -1, static_cast<int>(path.size()) - 1);
    const int k = pick(rng);
    parent[static_cast<std::size_t>(i)] = k < 0 ? -1 : path[static_cast<std::size_t>(k)];
  }
  return parent;
}

// (parent) => subtree sizes and the ancestor pattern P(i, j) = 1 for j = i or an ancestor of i
std::vector<int> subtreeSizes(const std::vector<int>& parent, Eigen::MatrixXi& P) {
  const int n = static_cast<int>(parent.size());
  std::vector<int> subtree(parent.size(), 1);
  P = Eigen::MatrixXi::Zero(n, n);
  for (int i = n - 1; i >= 0; --i) {
    for (int j = i; j >= 0; j = parent[static_cast<std::size_t>(j)]) P(i, j) = 1;
    if (parent[static_cast<std::size_t>(i)] >= 0)
      subtree[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])] +=
          subtree[static_cast<std::size_t>(i)];
  }
  return subtree;
}

}  // namespace

TEST_CASE("tree Cholesky: the factor of L0^T L0 is L0 on random tree-sparse matrices") {
  // A = L0^T L0 for a random L0 on the ancestor pattern with a positive diagonal: the factor with
  // a positive diagonal is unique, so treeCholeskyFactor must return L0 itself; A's entries off the
  // pattern are NaN (never read) and L's are a sentinel (never written); the solve against
  // Eigen's LDLT of the dense A
  std::mt19937 rng(2110);
  std::uniform_real_distribution<double> u(-1.0, 1.0), diag(0.5, 2.0);
  int tops = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const bool top = trial % 3 == 0;
    const int n = top ? 7 + trial % 17 : 1 + trial % 23;
    const std::vector<int> parent = randomDofTree(n, rng, top);
    Eigen::MatrixXi P;
    const std::vector<int> subtree = subtreeSizes(parent, P);
    if (top && n > 7 && subtree[6] < n - 6) ++tops;  // a branched floating base: the 6x6 path
    Eigen::MatrixXd L0 = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < i; ++j) L0(i, j) = P(i, j) != 0 ? u(rng) : 0.0;
      L0(i, i) = diag(rng);
    }
    Eigen::MatrixXd A = L0.transpose() * L0;
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        if (P(i, j) == 0 && P(j, i) == 0) A(i, j) = std::numeric_limits<double>::quiet_NaN();
      }
    }
    Eigen::MatrixXd L = Eigen::MatrixXd::Constant(n, n, 7.0);
    Eigen::VectorXd work(n);
    INFO("trial " << trial << " n " << n);
    REQUIRE(treeCholeskyFactor(A, parent, subtree, L, work));
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        if (j <= i && P(i, j) != 0) {
          CHECK(std::abs(L(i, j) - L0(i, j)) <= 1e-12 * L0.norm());
        } else {
          CHECK(L(i, j) == 7.0);
        }
      }
    }
    const Eigen::MatrixXd Ad = L0.transpose() * L0;
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    Eigen::VectorXd x = b;
    treeCholeskySolveInPlace(L, subtree, x);
    const Eigen::VectorXd xd = Ad.ldlt().solve(b);
    CHECK((x - xd).norm() <= 1e-10 * xd.norm());
  }
  CHECK(tops >= 10);
}
