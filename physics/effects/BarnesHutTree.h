#pragma once
// A Barnes–Hut quadtree (Barnes & Hut 1986) for softened mutual gravity among many bodies:
// O(N log N) per evaluation instead of the O(N²) of summing every pair.
//
// Build: the bodies are sorted along a Morton (Z-order) curve of their positions quantised to
// 2²¹ steps per axis over the bounding square, so every cell of the tree is one contiguous run
// of the sorted bodies and is split by binary search on the keys. Nodes, keys and the sorted
// copies of positions and masses live in arrays that keep their capacity from build to build:
// after the first evaluations a build allocates nothing.
//
// Walk: a cell of side s whose centre of mass lies at distance d from the body is taken whole
// (its monopole and quadrupole) when d > s/θ + δ, with δ the distance from the cell's centre of
// mass to its geometric centre (Barnes 1994: without δ a lopsided cell can pass the test while the
// body sits next to its mass). Cells that fail are opened; leaves of a few bodies are summed
// directly. The self-term is skipped.
//
// Error against direct summation, relative force error per body on 5,000 clustered bodies
// (bench_barnes_hut and tests/physics/tst_barnes_hut.cpp, which holds the tree to twice these):
//   θ = 0.3: median 7e-5, 99th percentile 7e-4, max 5e-3; potential energy 5e-6
//   θ = 0.5: median 5e-4, 99th percentile 5e-3, max 5e-2; potential energy 4e-5
//   θ = 0.7: median 2e-3, 99th percentile 2e-2, max 2e-1; potential energy 1.4e-4
// The maxima belong to the few bodies whose pulls nearly cancel (a small force, so a large
// relative error). The quadrupole terms cut the median error 18-fold at θ = 0.5 (40-fold at
// θ = 0.3) against monopoles alone.
// The walk is not symmetric (body i may see j's cell whole while j sees i alone), so the total
// momentum is conserved only to within that error, not to round-off as with direct summation.

#include <cstdint>
#include <utility>
#include <vector>

namespace phasebox {

class WorkerPool;

class BarnesHutTree {
public:
    // Builds the tree over `count` bodies: positions interleaved (x₀, y₀, x₁, y₁, …) as in the
    // state, masses per coordinate (m₀, m₀, m₁, m₁, …) as in the world's mass vector. θ is the
    // opening angle of the walks that follow. Returns false, leaving no usable tree, when a
    // position is not finite.
    bool build(const double* positions, const double* massPerDof, int count, double theta);

    // force[2i, 2i+1] += −G·m_i·Σ_j m_j·(p_i − p_j)/(‖p_i − p_j‖² + ε²)^{3/2}, the sum taken over
    // the tree (cells far enough away as one body at their centre of mass). Each body's walk is
    // its own and writes only its own force, so pool's workers share the bodies in chunks of
    // kWalkGrain with the same bits for any number of them.
    void addForces(double G, double softening2, double* force, WorkerPool* pool = nullptr) const;
    // Bodies per shared chunk of walks: a walk costs microseconds, a chunk hundreds of them.
    static constexpr int kWalkGrain = 256;

    // −½·G·Σ_i m_i·Σ_j m_j/√(‖p_i − p_j‖² + ε²) over the same walk: each pair is seen from both
    // ends and halved.
    double potentialEnergy(double G, double softening2) const;

    int nodeCount() const { return static_cast<int>(nodes_.size()); }

    // Deepest level: the quantisation of the keys (21 bits per axis fill 42 bits of 64).
    static constexpr int kLevels = 21;
    // Bodies per leaf: fewer means more cells to test, more means more direct pairs; in
    // bench_barnes_hut at 5,000 bodies 8 and 16 run equally fast and 4 is 1.7 times slower.
    static constexpr int kLeafSize = 8;

private:
    struct Node {
        double comX = 0.0, comY = 0.0, mass = 0.0;
        double qxx = 0.0, qxy = 0.0, qyy = 0.0;  // Σm·(x − x̄)², Σm·(x − x̄)(y − ȳ), Σm·(y − ȳ)²
        double open2 = 0.0;  // (s/θ + δ)²: the walk takes the cell whole beyond this distance²
        int begin = 0, end = 0;  // bodies, in sorted order
        int firstChild = -1;     // children are contiguous; −1 for a leaf
        int childCount = 0;
    };

    void buildNode(int node, int begin, int end, int level, double x0, double y0, double size);
    // addForces() for the bodies first … last − 1 in sorted order.
    void addForcesOf(int first, int last, double G, double softening2, double* force) const;
    // Calls visit(node) for every cell taken whole and leaf(begin, end) for every leaf that
    // has to be summed directly, for the body at sorted index s.
    template <typename Far, typename Near>
    void walk(int s, Far&& far, Near&& near) const;

    double theta_ = 0.5;
    std::vector<std::uint64_t> keys_;  // sorted Morton keys
    std::vector<std::pair<std::uint64_t, int>> order_;
    std::vector<double> x_, y_, m_;  // bodies in sorted order
    std::vector<int> original_;      // sorted index → body index
    std::vector<Node> nodes_;
};

}  // namespace phasebox
