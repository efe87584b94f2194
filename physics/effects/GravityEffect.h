#pragma once
// Uniform gravity: F = m·g on every dynamic particle and box. Conservative, with potential
// −m·g·x; constant force, so no Jacobian.

#include "physics/effects/Effect.h"

namespace phasebox {

class GravityEffect final : public Effect {
public:
    explicit GravityEffect(const Vec2& g) : Effect(effectName::gravity), g_(g) {}

    double addForces(double t, const Vec& q, const Vec& u, Vec& force) override;
    double potentialEnergy(const Vec& q) const override;
    bool potentialFromMassMoment(const Vec2& massMoment, double& energy) const override {
        energy = -g_.dot(massMoment);
        return true;
    }
    bool isAccelerationField() const override { return true; }
    bool uniformAcceleration(Vec2& a) const override {
        a = g_;
        return true;
    }
    void addAccelerations(double t, const Vec& q, const Vec& u, Vec& accel,
                          bool overwrite) override;

    const Vec2& g() const { return g_; }
    void setG(const Vec2& g) { g_ = g; }

private:
    Vec2 g_;
};

}  // namespace phasebox
