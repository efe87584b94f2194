#pragma once
// Coulomb's law between charged particles: F_i = k·q_i·q_j·r/(‖r‖² + ε²)^{3/2}, r = p_i − p_j
// (like charges repel). Only particles with a charge take part; a pinned charged particle is a
// fixed source that the others feel. Conservative, potential k·q_i·q_j/√(‖r‖² + ε²): the force
// above is exactly its gradient. (The form k·q_i·q_j·r̂/(‖r‖² + ε²) is not the gradient of any
// softened potential, so with ε > 0 it would show up as drift that is not the integrator's.)
//
// buildWorld constructs the effect only when the scene has two charged particles, at least one
// of them free to move; otherwise it would cost a pass that finds nothing. Pairs are summed
// directly, O(M²) in the M charged particles: classroom scenes charge a handful of particles,
// and a tree code does poorly with charges of both signs (their monopoles cancel).

#include "physics/effects/Effect.h"

#include <vector>

namespace phasebox {

class CoulombEffect final : public Effect {
public:
    // Coulomb's constant in N·m²/C².
    static constexpr double kCoulombConstant = 8.9875517923e9;

    explicit CoulombEffect(double k = kCoulombConstant, double softening = 0.0)
        : Effect(effectName::coulomb), k_(k), softening2_(softening * softening) {}

    double addForces(double t, const Vec& q, const Vec& u, Vec& force) override;
    void addJacobians(double t, const Vec& q, const Vec& u, ForceJacobians& jacobians) override;
    double potentialEnergy(const Vec& q) const override;
    bool couplesBodies() const override { return true; }
    void bind(const EffectWorldView& view) override;

private:
    template <typename Fn>
    void forEachPair(const Vec& q, Fn&& fn) const;

    double k_;
    double softening2_;
    // The charged particles, gathered by bind(): free ones by state index, pinned ones by their
    // fixed position.
    struct FreeCharge {
        int dof;
        double charge;
    };
    struct FixedCharge {
        Vec2 position;
        double charge;
    };
    std::vector<FreeCharge> free_;
    std::vector<FixedCharge> fixed_;
};

}  // namespace phasebox
