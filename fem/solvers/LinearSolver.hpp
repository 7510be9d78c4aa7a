// The sparse direct solver for one matrix, chosen from the matrix itself: CHOLMOD's simplicial
// LDL' when it is symmetric (beams, springs, masses: every static and most dynamic systems),
// UMFPACK's LU otherwise (cross-coupled bearings, gyroscopic terms). On the benchmark models
// LDL' stores half the factor of LU and factorises 2-3x faster (see the closing notes of the
// performance issue); both report the same kind of reciprocal condition estimate.
#pragma once

#include <Eigen/CholmodSupport>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "fem/assembly/Assembly.hpp"
#include "fem/solvers/SparseLU.hpp"
#include "fem/solvers/SupernodalCholesky.hpp"

namespace beamrotor {

/// CHOLMOD's simplicial LDL' plus what Eigen's wrapper keeps to itself.
class SparseLDLT : public Eigen::CholmodSimplicialLDLT<SparseMatrix, Eigen::Upper> {
 public:
  /// Quiet: a zero pivot is reported through info() and rcond(), never printed.
  SparseLDLT() { cholmod().print = 0; }
  SparseLDLT(const SparseLDLT&) = delete;
  SparseLDLT& operator=(const SparseLDLT&) = delete;
  /// x = A^-1 b for the last factorisation, with no workspace beyond x (and, under a
  /// fill-reducing ordering, one vector for the permutation): repeated solves (Lanczos) into
  /// the same x allocate nothing.
  void solveInto(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  /// CHOLMOD's cheap reciprocal condition estimate, min |D_ii| / max |D_ii| (0 when singular).
  /// It depends on the units of the dofs; see scaledRcond().
  double rcond() const;
  /// Numeric factorisation; keeps A's diagonal for scaledRcond().
  void factorize(const SparseMatrix& A);
  /// The same estimate for the symmetrically scaled matrix D^-1/2 A D^-1/2, D = diag(A),
  /// from this factor: with P A P' = L D L', the scaled matrix factors as (S L S^-1) (S D S)
  /// (S L S^-1)' with S = D^-1/2 permuted, whose pivots are D_jj / A_pp. Independent of the
  /// units (and of any diagonal scaling) of the dofs; 0 when singular or when a diagonal
  /// entry of A is not positive (a dof nothing holds).
  double scaledRcond() const;
  /// The smallest and largest |pivot| of that scaled matrix ({0, 0} when scaledRcond() is 0):
  /// the range of a factor made of several, whose estimate is the least over the most.
  std::pair<double, double> scaledPivotRange() const;
  /// Entries in the factor L (including its unit diagonal, which holds D).
  double factorEntries() const;
  /// The same, as the symbolic analysis predicts it (before factorize()).
  double predictedFactorEntries() const;
  /// Negative entries of D. By Sylvester's law of inertia, for A = K - sigma M this is the
  /// number of eigenvalues of K x = lambda M x below sigma (M positive definite).
  int negativePivots() const;
  /// Symbolic analysis. When the matrix as numbered already has (almost) no room for fill,
  /// or creates none, as a line of beams numbered node by node does, its own order is kept
  /// and the fill-reducing ordering, which would cost more than the factorisation, is
  /// skipped. Otherwise the order is AMD's: on the graph of nodes when `nodeOfRow` names each
  /// row's node (fem/solvers/NodeOrdering), else on the graph of equations.
  void analyzePattern(const SparseMatrix& A, std::span<const int> nodeOfRow = {});
  /// The fill-reducing ordering the analysis chose: "natural", "AMD", "AMD by node", "METIS",
  /// "NESDIS".
  const char* orderingName() const;
  /// That ordering as a permutation (row k of P A P' is row order()[k] of A), after the
  /// analysis.
  std::vector<int> order() const;

  /// The last factorisation as CHOLMOD holds it, P A P' = L D L': L unit lower, each column
  /// starting at its diagonal entry, which holds D (a simplicial factor may leave room after a
  /// column, so its length is its inner count, not the next start); `perm` lists P (row k of
  /// P A P' is row perm[k] of A), null in A's own order.
  struct FactorView {
    Eigen::Map<const SparseMatrix> L;
    const int* perm;
    double pivot(Eigen::Index j) const { return L.valuePtr()[L.outerIndexPtr()[j]]; }
  };
  FactorView factorView() const;

 private:
  /// CHOLMOD's analysis in `order` (row k of P A P' is row order[k] of A), then postordered.
  void analyseInOrder(const SparseMatrix& A, std::vector<int> order);

  Eigen::VectorXd diagonal_;  ///< of the matrix last factorised
  bool byNode_ = false;       ///< the analysis ordered the graph of nodes
};

/// Entries in the lower envelope of a structurally symmetric A: for each row, from its first
/// entry to the diagonal. Cholesky in A's own order fills at most this (George and Liu 1981).
long long lowerEnvelope(const SparseMatrix& A);

/// True when A (structurally symmetric, as every assembled pattern is) equals its transpose to
/// within `relTol` of the largest entry in absolute value.
bool isNumericallySymmetric(const SparseMatrix& A, double relTol = 1e-13);

/// What the caller knows about a matrix's symmetry before its values are read.
enum class MatrixSymmetry {
  unknown,         ///< find out from the values (a scan of every entry)
  byConstruction,  ///< assembled from symmetric parts only (SparseAssembler::stiffnessSymmetric)
};

/// What the caller expects of a symmetric matrix: nothing, or positive definiteness (a
/// supported structure's stiffness), which lets a large factor be a supernodal Cholesky.
enum class Definiteness { unknown, positiveExpected };

/// Factors the LDL' analysis predicts this many entries or more are made by the supernodal
/// Cholesky when positive definiteness is expected: below it the simplicial LDL' takes well
/// under a second, above it the supernodal factor's dense blocks win by 5-20x.
inline constexpr double kSupernodalFrom = 2e6;

class LinearSolver {
 public:
  /// Chooses the method (from A's values unless `symmetry` says it is symmetric by
  /// construction) and computes the symbolic factorisation; later factorize() calls must pass
  /// matrices with the same pattern (and the same symmetry).
  /// `nodeOfRow` (optional) names each row's node, rows of a node consecutive: a sparse
  /// factor's fill-reducing order is then found on the graph of nodes (SparseLDLT).
  /// With Definiteness::positiveExpected a symmetric matrix whose factor is large
  /// (kSupernodalFrom) is also analysed for CHOLMOD's supernodal Cholesky, in the same order;
  /// factorize() tries it first and falls back to the LDL' when the matrix is not positive
  /// definite (a mechanism, negative springs).
  void analyzePattern(const SparseMatrix& A, MatrixSymmetry symmetry = MatrixSymmetry::unknown,
                      std::span<const int> nodeOfRow = {},
                      Definiteness definiteness = Definiteness::unknown);
  /// Numeric factorisation. Check healthy() before solving. A non-symmetric matrix is
  /// factorised symmetrically scaled, S A S with S = |diag(A)|^-1/2, and solved as
  /// x = S (S A S)^-1 S b.
  void factorize(const SparseMatrix& A);
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  bool symmetric() const { return symmetric_; }
  /// "CHOLMOD LDL'", "CHOLMOD supernodal LL'" (of the last factorisation) or "UMFPACK LU".
  std::string methodName() const;
  /// The fill-reducing ordering of the symbolic analysis (SparseLDLT, SparseLU).
  std::string orderingName() const;
  /// Reciprocal condition estimate of the symmetrically scaled matrix D^-1/2 A D^-1/2: the
  /// system's conditioning, whatever the units of its dofs.
  double rcond() const;
  /// True when the factorisation succeeded and rcond is above tol.
  bool healthy(double tol) const;
  /// Fill-in: entries of the factor(s).
  double factorEntries() const;

 private:
  /// A symmetric matrix whose pattern falls into two large blocks that no entry couples (a
  /// flat grillage: in-plane and out-of-plane; fem/solvers/DecoupledBlocks) is factorised as
  /// two systems, on two cores at once: each block's factor is the one the whole matrix would
  /// have in an order that keeps the blocks apart, so the answers are those of one factor.
  struct Block {
    std::vector<int> rows;  ///< ascending
    SparseMatrix A;         ///< the matrix's block
    std::unique_ptr<SparseLDLT> ldlt = std::make_unique<SparseLDLT>();
  };
  bool splitIfDecoupled(const SparseMatrix& A, std::span<const int> nodeOfRow);

  bool symmetric_ = false;
  std::vector<Block> blocks_;  ///< two when split, else empty (ldlt_ holds the factor)
  SparseLDLT ldlt_;
  /// Analysed when a large positive definite matrix is expected; holds the last factor when
  /// it succeeded (usingCholesky_), else ldlt_ does.
  std::unique_ptr<SupernodalCholesky> cholesky_;
  bool usingCholesky_ = false;
  SparseLU lu_;
  Eigen::VectorXd luScale_;  ///< S of the scaled non-symmetric matrix
  SparseMatrix luMatrix_;    ///< S A S, referenced by lu_
};

}  // namespace beamrotor
