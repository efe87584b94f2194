#pragma once
// Where each dynamic object lives in the flat state, and the fixed geometry of what is not in
// it. Particles come first (x, y each), then rigid bodies (x, y, θ each):
//   q = [x₀ y₀ x₁ y₁ … | X₀ Y₀ θ₀ X₁ Y₁ θ₁ …]
// Static rigid bodies, planes and pinned particles are not in the state.

#include "physics/core/Types.h"

namespace phasebox {

struct StateLayout {
    int dynamicParticles = 0;
    int dynamicRigidBodies = 0;

    int particleDof(int dynamicParticle) const { return 2 * dynamicParticle; }
    int rigidDof(int dynamicBody) const { return 2 * dynamicParticles + 3 * dynamicBody; }
    int rigidBase() const { return 2 * dynamicParticles; }
    int dimension() const { return 2 * dynamicParticles + 3 * dynamicRigidBodies; }
};

// A point that a force acts on or is measured at: a dynamic particle, a point fixed in a
// dynamic rigid body's frame, or a fixed world point (an anchor, a pinned particle, a static body).
struct BodyPoint {
    enum class Kind : unsigned char { Particle, Rigid, Fixed };
    Kind kind = Kind::Fixed;
    int dof = -1;          // first state index (Particle, Rigid)
    Vec2 local{0.0, 0.0};  // Rigid: point in the body's frame; Fixed: the world point

    static BodyPoint particle(int dof) { return {Kind::Particle, dof, Vec2::Zero()}; }
    static BodyPoint rigid(int dof, const Vec2& local) { return {Kind::Rigid, dof, local}; }
    static BodyPoint fixed(const Vec2& world) { return {Kind::Fixed, -1, world}; }

    // World position and velocity of the point for state (q, u). For a rigid body's point,
    // r = R(θ)·local is its arm from the centre, needed for torques and Jacobians.
    void evaluate(const Vec& q, const Vec& u, Vec2& position, Vec2& velocity, Vec2& arm) const {
        switch (kind) {
            case Kind::Particle:
                position = q.segment<2>(dof);
                velocity = u.segment<2>(dof);
                arm.setZero();
                return;
            case Kind::Rigid: {
                arm = rotation(q[dof + 2]) * local;
                position = q.segment<2>(dof) + arm;
                velocity = u.segment<2>(dof) + u[dof + 2] * perp(arm);
                return;
            }
            case Kind::Fixed:
                position = local;
                velocity.setZero();
                arm.setZero();
                return;
        }
    }

    // Adds a world force applied at this point to the generalised force vector.
    void applyForce(const Vec2& f, const Vec2& arm, Vec& force) const {
        if (kind == Kind::Fixed) return;
        force.segment<2>(dof) += f;
        if (kind == Kind::Rigid) force[dof + 2] += cross(arm, f);
    }
    bool isDynamic() const { return kind != Kind::Fixed; }
};

}  // namespace phasebox
