#pragma once
// The mouse spring: pulls one dynamic particle, or a point fixed in a dynamic box, toward a
// target the user moves with the mouse. F = −k·(p − target) − c·ṗ at the grabbed point, with
// c = 2·ζ·√(k·m_eff) (ζ = 1: critically damped, so a drag follows the mouse without ringing).
// m_eff is the mass the spring feels at the grabbed point: m for a particle, and for a box
// point at arm r the smallest effective mass 1/(1/m + |r|²/I). A box held by a corner moves
// faster there than its mass suggests; damping for m instead would overshoot the explicit
// methods' limit c·h/m_eff < 2 and make the drag itself blow up.
//
// Energy: the target moves, so the spring's "potential" depends on time and is not a
// potential at all. The whole force is booked as non-conservative: its power F·ṗ enters
// work_nc and kinetic + potential − work_nc stays constant up to integration error.
//
// The effect names its body by id, not by state index: the layout changes whenever objects
// are added or removed, and bind() finds the body again each time.

#include "physics/effects/Effect.h"

#include <string>

namespace phasebox {

class MouseSpringEffect final : public Effect {
public:
    // localPoint is the grabbed point in the box's own frame (ignored for a particle). The
    // object is found by id when the world binds the effect.
    MouseSpringEffect(std::string objectId, const Vec2& localPoint, const Vec2& target,
                      double stiffness, double dampingRatio = 1.0);

    // The mass the spring feels at a point at localPoint of a body (inertia 0: a particle).
    static double effectiveMass(double mass, double inertia, const Vec2& localPoint);

    void setTarget(const Vec2& target) { target_ = target; }
    const Vec2& target() const { return target_; }
    void setStiffness(double stiffness);
    double stiffness() const { return stiffness_; }
    double damping() const { return damping_; }
    const std::string& objectId() const { return objectId_; }
    const Vec2& localPoint() const { return localPoint_; }
    // False when the body is gone or not dynamic (pinned, static): the effect then does nothing.
    bool isAttached() const { return point_.isDynamic(); }
    // World position of the grabbed point in state q (for drawing the rubber band).
    Vec2 grabbedPoint(const Vec& q) const;

    double addForces(double t, const Vec& q, const Vec& u, Vec& force) override;
    double nonConservativePower(double t, const Vec& q, const Vec& u) override;
    void addJacobians(double t, const Vec& q, const Vec& u, ForceJacobians& jacobians) override;
    bool hasNonConservativePart() const override { return true; }
    int drivenDof() const override { return point_.dof; }
    void bind(const EffectWorldView& view) override;

private:
    // Force at the grabbed point and what it needs; false when not attached.
    bool evaluate(const Vec& q, const Vec& u, Vec2& f, Vec2& velocity, Vec2& arm) const;
    void updateDamping();

    std::string objectId_;
    Vec2 localPoint_;
    Vec2 target_;
    double stiffness_;
    double dampingRatio_;
    double damping_ = 0.0;
    double effectiveMass_ = 0.0;
    BodyPoint point_;  // Fixed (= detached) until bound to a dynamic body
};

}  // namespace phasebox
