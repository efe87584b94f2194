#pragma once
// Newtonian gravity: F = −G·M·m·r/(‖r‖² + ε²)^{3/2} toward each fixed attractor (on every
// dynamic particle and box), and with `mutual` between every pair of dynamic particles.
// Conservative, potential −G·M·m/√(‖r‖² + ε²).
//
// Mutual pairs are summed directly, O(N²), up to treeThreshold() particles (1,000 by default),
// and above it by a Barnes–Hut tree, O(N log N) (BarnesHutTree.h). With the tree:
// - the forces carry its error: at the default opening angle θ = 0.5 on 5,000 clustered bodies
//   a median relative error of 5e-4, 5e-3 at the 99th percentile, 5e-2 at worst (figures for
//   other θ in BarnesHutTree.h and docs/architecture.md; tst_barnes_hut holds the tree to them);
// - the potential energy for the ledger comes from the same walk (O(N log N) per step, where
//   the exact sum would cost a direct summation every step), so the drift then also holds the
//   tree's potential error, about 4e-5 of |U| at θ = 0.5: a drift well above that is the
//   integrator's, one of that size may be the tree's (lower θ to tell them apart);
// - the mutual pairs get no Jacobian (a dense N×N block would cost more than the step it
//   serves): the implicit methods treat them explicitly. The attractors keep theirs.

#include "physics/effects/BarnesHutTree.h"
#include "physics/effects/Effect.h"

#include <vector>

namespace phasebox {

struct Attractor {
    Vec2 position;
    double mass;
};

class NewtonianGravityEffect final : public Effect {
public:
    NewtonianGravityEffect(double G, std::vector<Attractor> attractors, bool mutual,
                           double softening)
        : Effect(effectName::newtonianGravity),
          G_(G),
          attractors_(std::move(attractors)),
          mutual_(mutual),
          softening2_(softening * softening) {}

    double addForces(double t, const Vec& q, const Vec& u, Vec& force) override;
    void addJacobians(double t, const Vec& q, const Vec& u, ForceJacobians& jacobians) override;
    double potentialEnergy(const Vec& q) const override;
    bool couplesBodies() const override { return mutual_; }

    const std::vector<Attractor>& attractors() const { return attractors_; }

    // Above this many dynamic particles mutual gravity is summed by the tree.
    static constexpr int kDefaultTreeThreshold = 1000;
    int treeThreshold() const { return treeThreshold_; }
    void setTreeThreshold(int particles) { treeThreshold_ = particles; }
    double openingAngle() const { return openingAngle_; }
    void setOpeningAngle(double theta) { openingAngle_ = theta; }
    // Whether mutual gravity is summed by the tree in the current layout.
    bool usesTree() const;

private:
    // Calls fn(i, j, r, GMm) for every pair the direct sum handles (see the .cpp).
    template <typename Fn>
    void forEachPair(const Vec& q, bool mutualPairs, Fn&& fn) const;

    double G_;
    std::vector<Attractor> attractors_;
    bool mutual_;
    double softening2_;
    int treeThreshold_ = kDefaultTreeThreshold;
    double openingAngle_ = 0.5;
    // Rebuilt at each evaluation; mutable because the ledger's potentialEnergy() (const) walks
    // it too. It keeps its arrays, so rebuilding allocates nothing once warmed up.
    mutable BarnesHutTree tree_;
};

}  // namespace phasebox
