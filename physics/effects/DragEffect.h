#pragma once
// Drag: F = −b·v − c·‖v‖·v on every dynamic particle and box, torque −β·ω on boxes.
// Non-conservative: its power −b‖v‖² − c‖v‖³ − β·ω² enters work_nc.

#include "physics/effects/Effect.h"

namespace phasebox {

class DragEffect final : public Effect {
public:
    DragEffect(double linear, double quadratic, double angular)
        : Effect(effectName::drag), linear_(linear), quadratic_(quadratic), angular_(angular) {}

    double addForces(double t, const Vec& q, const Vec& u, Vec& force) override;
    double nonConservativePower(double t, const Vec& q, const Vec& u) override;
    void addJacobians(double t, const Vec& q, const Vec& u, ForceJacobians& jacobians) override;
    bool hasNonConservativePart() const override { return true; }

private:
    double linear_, quadratic_, angular_;
};

}  // namespace phasebox
