#pragma once
// The Cholesky factorisation of a symmetric positive definite matrix with the sparsity of a
// kinematic tree, such as the joint-space mass matrix (Featherstone, "Efficient factorization of
// the joint-space inertia matrix for branched kinematic trees", IJRR 24(6), 2005, the LTL form):
// A = L^T L, L lower triangular with L(i, j) != 0 only for j = i or j an ancestor of i in the dof
// tree. Eliminating from the leaves to the root creates no fill-in, so the work is the sum over
// dofs of (ancestors x subtree) instead of n^3 / 6.
//
// The dof tree is given by parent[i] (lambda(i) < i, -1 at a root) and subtree[i] (the number of
// dofs in the subtree of i, itself included; depth-first order makes it i .. i + subtree[i] - 1).
// Unitless: A, L and the right-hand sides carry whatever units the caller's system has (kg,
// kg m, kg m^2 for a mass matrix in the velocity coordinates of model.hpp).

#include <Eigen/Core>
#include <span>

#include "dynamics/data.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

/// (A: its upper triangle and diagonal are read, tree sparsity) => L (lower triangle and diagonal;
/// entries off the ancestor pattern are neither read nor written); work: scratch of at least
/// A.rows() entries (each row's numerators D_i U(i, j) of the square-root-free form, which carry
/// the rows' chain of dependences; resized if shorter).
/// Returns false when A is not positive definite (L then holds a NaN or a non-positive pivot).
bool treeCholeskyFactor(const Eigen::Ref<const Eigen::MatrixXd>& A, std::span<const int> parent,
                        std::span<const int> subtree, Eigen::Ref<Eigen::MatrixXd> L,
                        Eigen::VectorXd& work);

/// (L of treeCholeskyFactor, subtree, b) => x = A^-1 b in place (x = L^-1 L^-T b).
void treeCholeskySolveInPlace(const Eigen::Ref<const Eigen::MatrixXd>& L,
                              std::span<const int> subtree, Eigen::Ref<Eigen::VectorXd> x);

/// (data.M of crba) => data.L, M = L^T L along the model's dof tree; false if M is not positive
/// definite.
bool choleskyFactor(const Model& model, Data& data);

/// (data.L of choleskyFactor, b) => M^-1 b in place.
void choleskySolveInPlace(const Model& model, const Data& data, Eigen::VectorXd& b);
/// (data.L of choleskyFactor, B) => M^-1 B in place, column by column.
void choleskySolveInPlace(const Model& model, const Data& data, Eigen::MatrixXd& B);

}  // namespace yardsim::dynamics
