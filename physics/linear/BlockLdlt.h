#pragma once
// A sparse block LDLᵀ factorization of a symmetric positive definite matrix of B×B blocks (B
// = 2 or 3): one block row per node of a graph, an off-diagonal block per edge. The joints'
// J·W·Jᵀ is one (physics/joints/JointSolver.h: a node a joint, an edge two joints that hold a
// common body).
//
// BlockLdltPattern is the symbolic part, built once: the elimination order, and which blocks of
// L that order fills. BlockLdlt<B> is the numeric part: the caller assembles the diagonal
// blocks by elimination position and the off-diagonal ones by block index (blockIndex()),
// then factor() and solve(); neither allocates.

#include <Eigen/Dense>

#include <array>
#include <cstddef>
#include <set>
#include <vector>

namespace phasebox {

class BlockLdltPattern {
public:
    // The elimination order of the graph (adjacency[i]: node i's neighbours, symmetric, without
    // i itself) and the blocks of L after fill. Minimum fill, ties to the smaller degree, then
    // to the node that has waited longest (see BlockLdlt.cpp). Nodes marked in late (empty:
    // none) come after every other: their pivot is zero until their neighbours are eliminated
    // (a joint that holds only bodies kept as nodes of the system, JointSolver.h).
    void analyse(std::vector<std::set<int>> adjacency, const std::vector<char>& late = {});
    // Past this degree a node's fill is not counted but bounded, d·(d − 1)/2: counting it is
    // O(d²) each time a neighbour goes, O(d³) over a star's leaves. A node of that degree goes
    // after the nodes of small fill either way.
    static constexpr int kCountedDegree = 64;

    int size() const { return static_cast<int>(order_.size()); }
    // Position → node, and node → position.
    int node(int position) const { return order_[position]; }
    int position(int node) const { return position_[node]; }
    // The off-diagonal blocks of L (the edges plus the fill). For a chordal graph (the joint
    // graph of a chain or a tree of bodies) there is no fill.
    int blockCount() const { return static_cast<int>(upper_.size()); }
    // Block (i, p), i a later position than p, that column p of L couples.
    int blockIndex(int p, int i) const;

    // Column p's blocks are upperStart()[p] .. upperStart()[p + 1], block t at the later
    // position upper()[t].
    const std::vector<int>& order() const { return order_; }
    const std::vector<int>& upperStart() const { return upperStart_; }
    const std::vector<int>& upper() const { return upper_; }
    // The updates eliminating position p makes: updates()[updateStart()[p] ..]. Block
    // target −= L[t1]·offᵀ[t2]; target −1: the diagonal block at upper()[t1] (then t2 = t1).
    struct Update {
        int t1, t2, target;
    };
    const std::vector<int>& updateStart() const { return updateStart_; }
    const std::vector<Update>& updates() const { return updates_; }

private:
    std::vector<int> order_;     // position → node
    std::vector<int> position_;  // node → position
    // upper_[upperStart_[p] ..]: the later positions column p couples, ascending, after fill.
    std::vector<int> upperStart_, upper_;
    std::vector<int> updateStart_;
    std::vector<Update> updates_;
};

// The factors' blocks, B×B. With B = 2 where no node has a third row, the common joint scenes
// (hinges, rods, ropes, pulleys, tracks) factor and solve 2×2 blocks instead of 3×3 ones
// padded with the identity: a hinged chain's factorization and solves take about half the
// instructions.
template <int B>
class BlockLdlt {
public:
    using Block = Eigen::Matrix<double, B, B>;
    using Column = Eigen::Matrix<double, B, 1>;

    // Blocks for a pattern of this many nodes and blocks (the diagonal's the identity, the rest
    // zero).
    void resize(int nodes, std::size_t blocks) {
        diag_.assign(nodes, Block::Identity());
        dinv_.assign(nodes, Block::Identity());
        off_.assign(blocks, Block::Zero());
        l_.assign(blocks, Block::Zero());
        y_.assign(nodes, Column::Zero());
    }

    // The matrix, assembled by the caller before factor(): the diagonal block at elimination
    // position p, and off-diagonal block t (BlockLdltPattern::blockIndex).
    Block& diag(int p) { return diag_[p]; }
    Block& off(int t) { return off_[t]; }
    void clearOff() {
        for (Block& o : off_) o.setZero();
    }

    // In place: L, D⁻¹ from the assembled blocks (which it overwrites). In BlockLdlt.cpp, for
    // B = 2 and 3.
    void factor(const BlockLdltPattern& pattern);

    // Solves with the factors: rhs(p) is the right-hand side's block at position p (a B-vector),
    // and put(p, x) takes the solution's, x a std::array<double, B>, last position first.
    template <class Rhs, class Put>
    void solve(const BlockLdltPattern& pattern, Rhs&& rhs, Put&& put);

private:
    std::vector<Block> diag_, dinv_, off_, l_;
    std::vector<Column> y_;  // the solve's right-hand side by position
};

template <int B>
template <class Rhs, class Put>
void BlockLdlt<B>::solve(const BlockLdltPattern& pattern, Rhs&& rhs, Put&& put) {
    const int m = pattern.size();
    const std::vector<int>& upperStart = pattern.upperStart();
    const std::vector<int>& upper = pattern.upper();
    auto& y = y_;
    for (int p = 0; p < m; ++p) y[p] = rhs(p);
    // Forward (y[p] is complete once the earlier positions are done), then the diagonal.
    for (int p = 0; p < m; ++p) {
        for (int t = upperStart[p]; t < upperStart[p + 1]; ++t) y[upper[t]] -= l_[t] * y[p];
        y[p] = dinv_[p] * y[p];
    }
    // Backward (y[p] is final once the later positions are done).
    for (int p = m - 1; p >= 0; --p) {
        // In scalars throughout: Eigen's Lᵀ·y went through memory in halves, and a block
        // written in halves and read back whole stalls the store forwarding (with those two
        // stalls a joint the solves took a fifth of the whip's time at a tenth of its
        // instructions).
        std::array<double, B> yp;
        for (int i = 0; i < B; ++i) yp[i] = y[p][i];
        for (int t = upperStart[p]; t < upperStart[p + 1]; ++t) {
            const auto& l = l_[t];
            const auto& later = y[upper[t]];
            for (int i = 0; i < B; ++i) {
                double dot = l(0, i) * later[0];
                for (int j = 1; j < B; ++j) dot += l(j, i) * later[j];
                yp[i] -= dot;
            }
        }
        for (int i = 0; i < B; ++i) y[p][i] = yp[i];
        put(p, yp);
    }
}

}  // namespace phasebox
