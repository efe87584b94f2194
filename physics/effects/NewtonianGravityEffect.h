#pragma once
// Newtonian gravity: F = −G·M·m·r/(‖r‖² + ε²)^{3/2} toward each fixed attractor (on every
// dynamic particle and box), and with `mutual` between every pair of dynamic particles.
// Conservative, potential −G·M·m/√(‖r‖² + ε²). Mutual pairs are summed directly, O(N²).

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
        : Effect("newtonian_gravity"),
          G_(G),
          attractors_(std::move(attractors)),
          mutual_(mutual),
          softening2_(softening * softening) {}

    double addForces(double t, const Vec& q, const Vec& u, Vec& force) override;
    void addJacobians(double t, const Vec& q, const Vec& u, ForceJacobians& jacobians) override;
    double potentialEnergy(const Vec& q) const override;

    const std::vector<Attractor>& attractors() const { return attractors_; }

private:
    template <typename Fn>
    void forEachPair(const Vec& q, Fn&& fn) const;

    double G_;
    std::vector<Attractor> attractors_;
    bool mutual_;
    double softening2_;
};

}  // namespace phasebox
