#pragma once
// Wind: F = b·(w − v) on every dynamic particle, a linear drag toward the wind's velocity.
// Non-conservative (its power enters work_nc).

#include "physics/effects/Effect.h"

namespace phasebox {

class WindEffect final : public Effect {
public:
    WindEffect(const Vec2& velocity, double drag)
        : Effect(effectName::wind), wind_(velocity), drag_(drag) {}

    double addForces(double t, const Vec& q, const Vec& u, Vec& force) override;
    double nonConservativePower(double t, const Vec& q, const Vec& u) override;
    void addJacobians(double t, const Vec& q, const Vec& u, ForceJacobians& jacobians) override;
    bool hasNonConservativePart() const override { return true; }

private:
    Vec2 wind_;
    double drag_;
};

}  // namespace phasebox
