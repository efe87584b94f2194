#pragma once
// An aggregation multigrid preconditioner for the symmetric positive definite systems of the
// implicit methods (M − h·D − h²·K), after the plain-aggregation algebraic multigrid of
// Vaněk, Mandel & Brezina 1996, which Tamstorf, Jones & McCormick 2015 use for cloth.
//
// Conjugate gradients preconditioned by the diagonal need O(n) iterations on an n × n cloth,
// because one iteration carries information one spring further; a V-cycle moves the smooth
// part of the error through coarse copies of the cloth in one go, so the count stays nearly
// flat as the cloth grows.
//
// Setup: nodes strongly coupled by the matrix are grouped into aggregates; each aggregate
// becomes one coarse node, and the coarse matrix is the Galerkin product Pᵀ·A·P of the
// piecewise-constant prolongation P. A node is a point's (x, y) pair when every DOF belongs
// to a point (the matrix is then kept in 2 × 2 blocks), otherwise a single DOF. The grouping
// and the coarse patterns are worked out when the fine pattern changes; other steps only
// re-sum the values into fixed slots, so a step allocates nothing. The coarsest level
// (a few hundred DOFs) is factorised.
//
// Apply: one symmetric V-cycle, a forward block Gauss–Seidel sweep before each coarse
// correction and a backward one after it, which makes the preconditioner symmetric positive
// definite, as conjugate gradients need.

#include "physics/core/Types.h"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include <vector>

namespace phasebox {

class AggregationMultigrid {
public:
    // Builds the hierarchy for the symmetric matrix a (its compressed columns are read as
    // rows; its values weigh the couplings). DOFs [0, pointDofs) are (x, y) pairs of points.
    void build(const SparseMatrix& a, int pointDofs);
    // The fine matrix's values, to be filled in place between build() and refresh(): entry
    // (row, col) lives at fineValues()[fineOffset(row, col)], and (row, col + 1) right after
    // it whenever both are in the pattern.
    double* fineValues() { return levels_[0].values.data(); }
    std::size_t fineValueCount() const { return levels_[0].values.size(); }
    int fineOffset(int row, int col) const;
    // After the fine values changed: the smoother's diagonal, and with coarse (the default)
    // the coarse levels' values and factorisation. Keeping an older coarse correction is
    // still a symmetric preconditioner, and a positive definite one while the coarse matrix
    // has not changed by a factor near 2 (the coarse correction then over-shoots by less
    // than the error it removes); the caller checks that conjugate gradients still converge.
    void refresh(bool coarse = true);
    // build + copying a's values + refresh, for callers that keep their own matrix.
    void setup(const SparseMatrix& a, int pointDofs, bool patternChanged);

    // y = A·x with the fine matrix in its blocked form.
    void multiply(const Vec& x, Vec& y) const;
    // z = B·r, one V-cycle.
    void apply(const Vec& r, Vec& z);

    int levels() const { return static_cast<int>(levels_.size()); }
    // The coarsest level's Galerkin matrix, and x = its inverse times b by the factorisation the
    // V-cycle uses (for tests; both allocate).
    SparseMatrix coarsestOperator() const;
    Vec solveCoarsest(const Vec& b);
    int coarsestSize() const { return levels_.empty() ? 0 : levels_.back().n; }

private:
    // A symmetric matrix in compressed sparse rows of block × block blocks.
    struct Level {
        int nodes = 0, n = 0;
        std::vector<int> outer, inner, diagonal;  // diagonal: index of each row's diagonal block
        std::vector<int> column;                  // inner × block: each block's first DOF
        std::vector<double> values;               // block² per block, row-major
        std::vector<double> diagonalInverse;      // block² per node
        std::vector<int> toCoarse;                // node → node of the next level
        std::vector<int> galerkinSlot;            // block → block of the next level
        Vec x, b;
    };

    bool coarsen(const Level& fine, Level& coarse, std::vector<int>& toCoarse,
                 std::vector<int>& slot) const;
    void prepare(Level& level) const;      // sizes the diagonal, values and work vectors
    void fillFine(const SparseMatrix& a);  // level 0's blocks from a
    void galerkin(std::size_t level);      // level + 1's values from level's
    void cycle(std::size_t level, const double* b, double* x);
    void coarsestSolve(const double* b, double* x);

    int block_ = 1;
    std::vector<Level> levels_;
    std::vector<int> fineSlot_;  // scalar entry of a → index in levels_[0].values
    // The coarsest level as a scalar matrix in fill-reducing order (upper triangle), to
    // factorise; coarsestSlot_ maps each of its block entries there (−1: below the diagonal).
    SparseMatrix coarsestMatrix_;
    std::vector<int> coarsestSlot_;
    Eigen::VectorXi coarsestOrder_;  // DOF → position in that order
    Vec coarsestB_, coarsestX_;
    // Eigen's factorize() builds an empty temporary matrix (one allocation a step) even when,
    // as here, it does not use it; this calls the factorisation proper.
    class OrderedLdlt
        : public Eigen::SimplicialLDLT<SparseMatrix, Eigen::Upper, Eigen::NaturalOrdering<int>> {
    public:
        void factorizeOrdered(const SparseMatrix& upper) { factorize_preordered<true>(upper); }
        const SparseMatrix& factor() const { return m_matrix; }  // L, strictly lower
        const Vec& diagonal() const { return m_diag; }           // D (vectorD() copies it)
    };
    OrderedLdlt coarsest_;
    bool coarsestOk_ = false;
    // With 2 × 2 blocks: the factor as a block-unit L̂ (its rows, and its transpose's rows)
    // and the inverses of the 2 × 2 blocks of D̂, so that A = L̂·D̂·L̂ᵀ.
    struct BlockFactor {
        std::vector<int> lowerOuter, lowerColumn, upperOuter, upperColumn;
        std::vector<double> lower, upper, diagonalInverse;
        std::vector<int> slot;    // entry of L → its place in lower (−1: in a diagonal block)
        std::vector<int> intra;   // node → entry of L inside its diagonal block (−1: none)
        std::vector<int> mirror;  // block of lower → the same block's place in upper
        bool ready = false;
    };
    void blockFactor();
    BlockFactor factor_;
};

}  // namespace phasebox
