#include "dynamics/tree_cholesky.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <utility>

namespace yardsim::dynamics {

namespace {
// From this many dofs a single chain (a dense matrix) is factorised by Eigen's cache-blocked LLT.
constexpr int kDenseChain = 64;

// (A, the dof tree a single chain: A dense) => L by Eigen's blocked LLT of the reversed matrix:
// with P the reversal, P A P = G G^T gives A = L^T L with L = P G^T P, L(i, j) = G(n-1-j, n-1-i).
// Row by row products stream all of L through the cache once per row, the blocked algorithm does
// not: on the 256-link chain the row by row form took 0.70 of RBDL's time under load, where the
// dense LLT had 0.55.
bool denseChainFactor(const Eigen::Ref<const Eigen::MatrixXd>& A, Eigen::Ref<Eigen::MatrixXd> L) {
  const int n = static_cast<int>(A.rows());
  for (int c = 0; c < n; ++c) {
    for (int r = c; r < n; ++r) L(r, c) = A(n - 1 - r, n - 1 - c);
  }
  const Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>, Eigen::Lower> llt(L);
  // (G in L's lower triangle) => L(i, j) = G(n-1-j, n-1-i): swap each pair of the involution once,
  // in 8 x 8 tiles (the partner of a tile is a tile: both stay in the cache)
  constexpr int kTile = 8;
  for (int J = 0; J < n; J += kTile) {
    for (int I = J; I < n; I += kTile) {
      for (int j = J; j < std::min(J + kTile, n); ++j) {
        for (int i = std::max(I, j); i < std::min(I + kTile, n - 1 - j); ++i)
          std::swap(L(i, j), L(n - 1 - j, n - 1 - i));
      }
    }
  }
  return llt.info() == Eigen::Success;
}

// (pivot D_i, its row's numerators t_j = D_i U(i, j) for ancestors j) => L_ii = sqrt(D_i) at
// *diag; returns 1 / D_i (the next row's fresh term) and sets *scale = 1 / L_ii = sqrt(D_i) / D_i:
// the root and the division side by side, and only the division on the rows' chain
inline double pivotInverse(double d, double* diag, double* scale) {
  const double lii = std::sqrt(d);
  const double dinv = 1.0 / d;
  *diag = lii;
  *scale = lii * dinv;
  return dinv;
}

// The rows' chain of dependences. Row i's terms L(k, i) L(k, j) over its subtree rows k come from
// L, except the freshest, k = i + 1 (the row just before, i's first child when i has a subtree):
// it is t'_i t'_j / D_{i+1} from that row's numerators t' (work, by column) and 1 / D_{i+1}
// (dinvPrev), which are ready before that row's square root and scaling. So from one row's
// division to the next row's the chain is a product, a product and a subtraction (the pivot), and
// the square roots and L's entries run beside it. L is the same L^T L factor as before; only the
// freshest term's rounding differs (t'_i t'_j / D instead of L(i+1, i) L(i+1, j)).

// (NS subtree rows below row i, L(sub i, i) = li, A(., i) = ai, row i+1's numerators in work and
// its 1 / D in dinvPrev) => L_ii = out[i ld] and L(i, j) = out[j ld] for every ancestor j of i,
// found by walking the parents: D_i = A_ii - sum_k L(k, i)^2, t_j = A_ji - sum_k L(k, i) L(k, j),
// L_ii = sqrt(D_i), L(i, j) = t_j / L_ii; the terms of k = i + 2 .. from the last subtree row to
// the first, then k = i + 1's from the numerators; NS fixed at compile time (the loops unrolled);
// work[j] = t_j; returns 1 / D_i, and whether the pivot is positive in *positive.
template <int NS>
double rowFixed(std::span<const int> parent, int i, const double* li, const double* ai, double* out,
                Eigen::Index ld, double* work, double dinvPrev, bool* positive) {
  double x[NS > 0 ? NS : 1];
  for (int k = 1; k < NS; ++k) x[k] = li[k];
  double pivot = ai[i];
  for (int k = NS - 1; k >= 1; --k) pivot -= x[k] * x[k];
  double c = 0.0;  // t'_i / D_{i+1}
  if constexpr (NS > 0) {
    c = work[i] * dinvPrev;
    pivot -= c * work[i];
  }
  double scale = 0.0;
  const double dinv = pivotInverse(pivot, out + i * ld, &scale);
  for (int j = parent[static_cast<std::size_t>(i)]; j >= 0;
       j = parent[static_cast<std::size_t>(j)]) {
    const double* lj = out + j * ld + 1;  // L(sub i, j)
    double s = ai[j];
    for (int k = NS - 1; k >= 1; --k) s -= x[k] * lj[k];
    if constexpr (NS > 0) s -= c * work[j];
    work[j] = s;
    out[j * ld] = s * scale;
  }
  *positive = pivot > 0.0;
  return dinv;
}

// Eigen's vector register of at most 4 doubles (2 lanes with SSE2, 4 with AVX and AVX-512: its
// 8-lane predux trips GCC 12's -Wuninitialized in the intrinsics' header) for the long dot products
using Packet = Eigen::internal::find_best_packet<double, 4>::type;
constexpr int kLanes = Eigen::internal::unpacket_traits<Packet>::size;
// From this many subtree rows a row's dot products run in vector registers (rowLong);
// below it, one unrolled scalar loop per count of rows (rowFixed), summed term by term
constexpr int kLongRow = 8;
// rowLong takes up to this many consecutive ancestor columns per pass over L(sub i, i)
// (two: four spilled registers in GCC 12's code and cost more instructions)
constexpr int kMaxRun = 2;

// (x of length n, C columns y_c = y0 - c ld) => s_c = x . y_c, C dot products sharing each load
// of x, summed lane by lane in vector registers (Eigen's packets), then the lanes and the tail.
template <int C>
void dotColumns(const double* x, const double* y0, Eigen::Index ld, int n, double* s) {
  namespace ei = Eigen::internal;
  const double* y[C];
  Packet acc[C];
  for (int c = 0; c < C; ++c) {
    y[c] = y0 - c * ld;
    acc[c] = ei::pset1<Packet>(0.0);
  }
  int k = 0;
  for (; k + kLanes <= n; k += kLanes) {
    const Packet xk = ei::ploadu<Packet>(x + k);
    for (int c = 0; c < C; ++c) acc[c] = ei::pmadd(xk, ei::ploadu<Packet>(y[c] + k), acc[c]);
  }
  for (int c = 0; c < C; ++c) {
    double t = ei::predux(acc[c]);
    for (int r = k; r < n; ++r) t += x[r] * y[c][r];
    s[c] = t;
  }
}

// (as rowFixed, any ns >= 1) => row i of L, the dot products over k = i + 2 .. in vector
// registers (dotColumns), k = i + 1's term from row i+1's numerators last; where ancestors run
// (each the parent of the next: columns ld apart) two ancestor columns share each load of
// L(sub i, i)
double rowLong(int ns, std::span<const int> parent, int i, const double* li, const double* ai,
               double* out, Eigen::Index ld, double* work, double dinvPrev, bool* positive) {
  double sq = 0.0;
  dotColumns<1>(li + 1, li + 1, 0, ns - 1, &sq);
  const double c = work[i] * dinvPrev;  // t'_i / D_{i+1}
  const double pivot = (ai[i] - sq) - c * work[i];
  double scale = 0.0;
  const double dinv = pivotInverse(pivot, out + i * ld, &scale);
  for (int j = parent[static_cast<std::size_t>(i)]; j >= 0;) {
    // (j) => the run j, j - 1, ..., j - len + 1 (len <= kMaxRun) and the ancestor after it
    int len = 1, next = parent[static_cast<std::size_t>(j)];
    while (len < kMaxRun && next >= 0 && next == j - len) {
      ++len;
      next = parent[static_cast<std::size_t>(next)];
    }
    const double* y0 = out + j * ld + 2;  // L(sub i, j) from k = i + 2
    double s[kMaxRun];
    if (len == 2) {
      dotColumns<2>(li + 1, y0, ld, ns - 1, s);
    } else {
      dotColumns<1>(li + 1, y0, ld, ns - 1, s);
    }
    for (int r = 0; r < len; ++r) {
      const double t = (ai[j - r] - s[r]) - c * work[j - r];
      work[j - r] = t;
      out[(j - r) * ld] = t * scale;
    }
    j = next;
  }
  *positive = pivot > 0.0;
  return dinv;
}

// (ns subtree rows, as rowFixed) => row i of L: rowFixed<ns> for ns in NS... (one comparison
// each, inlined), rowLong from kLongRow rows; returns 1 / D_i, whether the pivot is positive in
// *positive
template <int... NS>
double row(std::integer_sequence<int, NS...>, int ns, std::span<const int> parent, int i,
           const double* li, const double* ai, double* out, Eigen::Index ld, double* work,
           double dinvPrev, bool* positive) {
  double dinv = 0.0;
  const bool fixed =
      ((ns == NS &&
        (dinv = rowFixed<NS>(parent, i, li, ai, out, ld, work, dinvPrev, positive), true)) ||
       ...);
  return fixed ? dinv : rowLong(ns, parent, i, li, ai, out, ld, work, dinvPrev, positive);
}

// Dofs 0 .. 5 form a chain at the root that every other dof descends from, and branch below it (a
// floating base with two or more limbs, or six single-dof joints in a row): their rows of L are a
// dense 6 x 6 block, done apart from the generic rows. (Below a single chain the generic rows are
// as fast: the top block would cost chain 8 a third more time.)
constexpr int kTop = 6;

// (parent, subtree) => whether dofs 0 .. kTop - 1 are such a chain with branches below
bool denseTop(std::span<const int> parent, std::span<const int> subtree, int n) {
  if (n <= kTop + 1 || parent[0] != -1 || subtree[kTop - 1] != n - (kTop - 1) ||
      subtree[kTop] == n - kTop)
    return false;
  for (int k = 1; k < kTop; ++k) {
    if (parent[static_cast<std::size_t>(k)] != k - 1) return false;
  }
  return true;
}

// (f, I...) => f<I>() for each I in order; forEachDown: f<N - 1 - I>() (I = 0 .. N - 1)
template <typename F, int... I>
void forEach(std::integer_sequence<int, I...>, const F& f) {
  (f.template operator()<I>(), ...);
}
template <typename F, int... I>
void forEachDown(std::integer_sequence<int, I...>, const F& f) {
  (f.template operator()<static_cast<int>(sizeof...(I)) - 1 - I>(), ...);
}

// (A, rows kTop .. n - 1 of L) => rows kTop - 1 .. 0 of L: the block's Schur complement S =
// A(0..5, 0..5) - B^T B first, B = L(6 .., 0 .. 5) (21 dot products of columns of length n - 6,
// none waiting for a pivot), then S = L_top^T L_top densely, from row 5 to row 0, unrolled: D_k =
// S_kk, L_kk = sqrt(D_k), L_kj = S_kj / L_kk, S_ij -= S_ki S_kj / D_k (i, j < k; the division
// alone on the pivots' chain); whether every pivot is positive
bool topBlock(const double* a, Eigen::Index lda, double* l, Eigen::Index ld, int n) {
  double S[kTop][kTop];  // S[i][j], j <= i
  const int nb = n - kTop;
  // (I) => S[I][j] for j = I, I - 1, ..., 0, the products sharing each load of L(6 .., I)
  const auto lower = [&]<int I>() {
    const double* x = l + I * ld + kTop;
    double s[I + 1];
    for (int c = 0; c <= I; ++c) s[c] = a[I * lda + (I - c)];
    for (int k = 0; k < nb; ++k) {
      for (int c = 0; c <= I; ++c) s[c] -= x[k] * x[k - c * ld];
    }
    for (int c = 0; c <= I; ++c) S[I][I - c] = s[c];
  };
  forEach(std::make_integer_sequence<int, kTop>{}, lower);
  bool ok = true;
  // (K) => pivot K of S: row K of L and the update of S above it (every loop of fixed length)
  const auto pivot = [&]<int K>() {
    const double d = S[K][K];
    const double dinv = 1.0 / d;
    const double root = std::sqrt(d);
    const double scale = root * dinv;
    ok = ok && d > 0.0;
    l[K * ld + K] = root;
    double c[K > 0 ? K : 1];
    for (int j = 0; j < K; ++j) {
      l[j * ld + K] = S[K][j] * scale;
      c[j] = S[K][j] * dinv;
    }
    for (int i = K - 1; i >= 0; --i) {
      for (int j = 0; j <= i; ++j) S[i][j] -= S[K][i] * c[j];
    }
  };
  forEachDown(std::make_integer_sequence<int, kTop>{}, pivot);
  return ok;
}

// (parent) => whether dof i's parent is i - 1 for every i (one chain: every entry non-zero)
bool singleChain(std::span<const int> parent) {
  for (std::size_t i = 0; i < parent.size(); ++i) {
    if (parent[i] != static_cast<int>(i) - 1) return false;
  }
  return true;
}
}  // namespace

bool treeCholeskyFactor(const Eigen::Ref<const Eigen::MatrixXd>& A, std::span<const int> parent,
                        std::span<const int> subtree, Eigen::Ref<Eigen::MatrixXd> L,
                        Eigen::VectorXd& work) {
  const int n = static_cast<int>(A.rows());
  if (n >= kDenseChain && singleChain(parent.first(static_cast<std::size_t>(n))))
    return denseChainFactor(A, L);
  if (work.size() < n) work.resize(n);
  const double* a = A.data();
  const Eigen::Index lda = A.outerStride();
  double* l = L.data();
  const Eigen::Index ld = L.outerStride();
  double* t = work.data();
  bool ok = true;
  double dinv = 0.0;  // 1 / D of the row just done
  // (A, rows of L below i) => row i of L, from the leaves (i = n - 1) to the root:
  //   L_ii = sqrt(A_ii - |L(sub i, i)|^2),  L_ij = (A_ji - L(sub i, i) . L(sub i, j)) / L_ii
  // for every ancestor j of i (A_ji from A's upper triangle, a column: contiguous).
  const bool top = denseTop(parent, subtree, n);
  for (int i = n - 1; i >= (top ? kTop : 0); --i) {
    const int ns = subtree[static_cast<std::size_t>(i)] - 1;
    const double* li = l + i * ld + i + 1;  // L(sub i, i)
    const double* ai = a + i * lda;         // A(., i)
    bool positive = false;
    dinv = row(std::make_integer_sequence<int, kLongRow>{}, ns, parent, i, li, ai, l + i, ld, t,
               dinv, &positive);
    if (!positive) ok = false;
  }
  if (top && !topBlock(a, lda, l, ld, n)) ok = false;
  return ok;
}

void treeCholeskySolveInPlace(const Eigen::Ref<const Eigen::MatrixXd>& L,
                              std::span<const int> subtree, Eigen::Ref<Eigen::VectorXd> x) {
  const int n = static_cast<int>(L.rows());
  const double* l = L.data();
  const Eigen::Index ld = L.outerStride();
  double* xp = x.data();
  // (b) => y = L^-T b, from the leaves: y_i = (b_i - L(sub i, i) . y(sub i)) / L_ii
  for (int i = n - 1; i >= 0; --i) {
    const int ns = subtree[static_cast<std::size_t>(i)] - 1;
    const double* li = l + i * ld + i + 1;
    double s = xp[i];
    for (int k = 0; k < ns; ++k) s -= li[k] * xp[i + 1 + k];
    xp[i] = s / l[i * ld + i];
  }
  // (y) => x = L^-1 y, from the root: x_i = y_i / L_ii, then y(sub i) -= L(sub i, i) x_i
  for (int i = 0; i < n; ++i) {
    const int ns = subtree[static_cast<std::size_t>(i)] - 1;
    const double* li = l + i * ld + i + 1;
    const double xi = xp[i] / l[i * ld + i];
    xp[i] = xi;
    for (int k = 0; k < ns; ++k) xp[i + 1 + k] -= li[k] * xi;
  }
}

bool choleskyFactor(const Model& m, Data& d) {
  return treeCholeskyFactor(d.M, m.dofParent, m.dofSubtree, d.L, d.cholWork);
}

void choleskySolveInPlace(const Model& m, const Data& d, Eigen::VectorXd& b) {
  treeCholeskySolveInPlace(d.L, m.dofSubtree, b);
}

void choleskySolveInPlace(const Model& m, const Data& d, Eigen::MatrixXd& B) {
  for (Eigen::Index c = 0; c < B.cols(); ++c) treeCholeskySolveInPlace(d.L, m.dofSubtree, B.col(c));
}

}  // namespace yardsim::dynamics
