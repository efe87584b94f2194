#pragma once
// The penalty contact model (CONTRACT §6): every overlapping point of two shapes is a damped
// spring along the normal, F = k·d + c·ḋ (d the overlap, ḋ its rate of growth), with
// regularised Coulomb friction along the tangent. It is a smooth force: the integrators
// evaluate it like any other, the implicit ones with its Jacobians, and its potential ½·k·d² is
// part of the potential energy. The force is not clamped while d > 0 (damping may pull when the
// bodies part fast): that is what makes the closed forms of a linear damped oscillator hold.
//
// The world owns it beside the effects (it is not a scene effect and has no key of its own):
// the contact stage finds candidate pairs once per frame, and every evaluation asks it which
// of them overlap at the state being evaluated.

#include "physics/contacts/ContactStage.h"
#include "physics/effects/Effect.h"

namespace phasebox {

struct Bodies;

class PenaltyContacts final : public Effect {
public:
    PenaltyContacts() : Effect("penalty contacts") {}

    void attach(ContactStage* stage, const Bodies* bodies) {
        stage_ = stage;
        bodies_ = bodies;
    }
    // k per contact point (N/m), c (N·s/m), and the sub-step h, which sets how sharp friction's
    // regularisation may be (its slope μ·F_n/ε stays within what an explicit step can take).
    void setParameters(double stiffness, double damping, double h) {
        stiffness_ = stiffness;
        damping_ = damping;
        step_ = h;
    }
    double stiffness() const { return stiffness_; }
    double damping() const { return damping_; }

    double addForces(double t, const Vec& q, const Vec& u, Vec& force) override;
    double nonConservativePower(double t, const Vec& q, const Vec& u) override;
    void addJacobians(double t, const Vec& q, const Vec& u, ForceJacobians& jacobians) override;
    double addForcesAndJacobians(double t, const Vec& q, const Vec& u, Vec& force,
                                 ForceJacobians& jacobians) override;
    double potentialEnergy(const Vec& q) const override;
    bool hasNonConservativePart() const override { return true; }
    // How many points overlap at q.
    int overlappingPoints(const Vec& q) const;
    // The force on the (x, y) of the body whose state begins at dof, at (q, u).
    Vec2 forceOn(const Vec& q, const Vec& u, int dof) const;

    // The automatic stiffness: the lightest of the given masses gets ω·h = 0.5 on one point.
    static double automaticStiffness(double lightestMass, double h) {
        const double omega = 0.5 / h;
        return lightestMass * omega * omega;
    }
    // The slowest slip friction's regularisation allows (m/s): below it friction grows linearly
    // with the slip speed.
    static constexpr double kMinSlip = 1e-3;

private:
    struct Sums {
        double power = 0.0;      // of the non-conservative part (damping, friction)
        double potential = 0.0;  // Σ ½·k·d²
    };
    // Adds each point's force into force; with only >= 0, just the terms on that dof and the
    // next (one body's (x, y), for forceOn).
    Sums evaluate(const Vec& q, const Vec* u, Vec* force, ForceJacobians* jacobians,
                  int only = -1) const;

    ContactStage* stage_ = nullptr;
    const Bodies* bodies_ = nullptr;
    double stiffness_ = 0.0;
    double damping_ = 0.0;
    double step_ = 1.0 / 60.0;
};

}  // namespace phasebox
