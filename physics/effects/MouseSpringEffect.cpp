#include "physics/effects/MouseSpringEffect.h"

#include "physics/core/Bodies.h"

#include <algorithm>
#include <cmath>

namespace phasebox {

MouseSpringEffect::MouseSpringEffect(std::string objectId, const Vec2& localPoint,
                                     const Vec2& target, double stiffness, double dampingRatio)
    : Effect("mouse_spring"),
      objectId_(std::move(objectId)),
      localPoint_(localPoint),
      target_(target),
      stiffness_(stiffness),
      dampingRatio_(dampingRatio) {}

double MouseSpringEffect::effectiveMass(double mass, double inertia, const Vec2& localPoint) {
    if (!(inertia > 0.0)) return mass;
    return 1.0 / (1.0 / mass + localPoint.squaredNorm() / inertia);
}

void MouseSpringEffect::setStiffness(double stiffness) {
    stiffness_ = stiffness;
    updateDamping();
}

void MouseSpringEffect::updateDamping() {
    damping_ = 2.0 * dampingRatio_ * std::sqrt(std::max(stiffness_ * effectiveMass_, 0.0));
}

void MouseSpringEffect::bind(const EffectWorldView& view) {
    Effect::bind(view);
    // The world also binds right after addEffect(), before its layout is rebuilt; a dof that
    // does not fit the current mass vector is stale then, and the commit that follows binds
    // again with the true one. Until then the effect stays detached rather than read past the end.
    point_ = BodyPoint{};
    effectiveMass_ = 0.0;
    const Eigen::Index size = view.mass ? view.mass->size() : 0;
    for (const Particle& p : *view.particles) {
        if (p.id != objectId_) continue;
        if (p.dof >= 0 && p.dof + 2 <= size) point_ = BodyPoint::particle(p.dof);
        break;
    }
    if (!point_.isDynamic()) {
        for (const RigidBody& b : *view.rigidBodies) {
            if (b.id != objectId_) continue;
            if (b.dof >= 0 && b.dof + 3 <= size) point_ = BodyPoint::rigid(b.dof, localPoint_);
            break;
        }
    }
    if (point_.kind == BodyPoint::Kind::Particle) effectiveMass_ = (*view.mass)[point_.dof];
    if (point_.kind == BodyPoint::Kind::Rigid)
        effectiveMass_ =
            effectiveMass((*view.mass)[point_.dof], (*view.mass)[point_.dof + 2], localPoint_);
    updateDamping();
}

Vec2 MouseSpringEffect::grabbedPoint(const Vec& q) const {
    Vec2 position = target_, velocity = Vec2::Zero(), arm = Vec2::Zero();
    if (point_.isDynamic() && point_.dof < q.size()) point_.evaluate(q, q, position, velocity, arm);
    return position;
}

bool MouseSpringEffect::evaluate(const Vec& q, const Vec& u, Vec2& f, Vec2& velocity,
                                 Vec2& arm) const {
    if (!point_.isDynamic()) return false;
    Vec2 position = Vec2::Zero();
    point_.evaluate(q, u, position, velocity, arm);
    f = -stiffness_ * (position - target_) - damping_ * velocity;
    return true;
}

double MouseSpringEffect::addForces(double, const Vec& q, const Vec& u, Vec& force) {
    Vec2 f = Vec2::Zero(), velocity = Vec2::Zero(), arm = Vec2::Zero();
    if (!evaluate(q, u, f, velocity, arm)) return 0.0;
    point_.applyForce(f, arm, force);
    return f.dot(velocity);  // the whole force is external work (see the header)
}

double MouseSpringEffect::nonConservativePower(double, const Vec& q, const Vec& u) {
    Vec2 f = Vec2::Zero(), velocity = Vec2::Zero(), arm = Vec2::Zero();
    if (!evaluate(q, u, f, velocity, arm)) return 0.0;
    return f.dot(velocity);
}

void MouseSpringEffect::addJacobians(double, const Vec& q, const Vec& u, ForceJacobians& jac) {
    // With p = X + R(θ)·l and J = ∂p/∂(X, Y, θ) = [I | perp(r)], the generalised force Jᵀ·F has
    // K = −k·JᵀJ and D = −c·JᵀJ (symmetric, negative semi-definite: implicit methods stay
    // stable however stiff the spring), plus the torque's turning with the box,
    // ∂(r × F)/∂θ = −r·F, as in SpringEffect. For a particle J = I: K = −k·I, D = −c·I.
    Vec2 f = Vec2::Zero(), velocity = Vec2::Zero(), arm = Vec2::Zero();
    if (!evaluate(q, u, f, velocity, arm)) return;
    const int i = point_.dof;
    jac.addStiffnessBlock(i, i, -stiffness_ * Mat2::Identity());
    jac.addDampingBlock(i, i, -damping_ * Mat2::Identity());
    if (point_.kind != BodyPoint::Kind::Rigid) return;
    const Vec2 r = perp(arm);
    for (int a = 0; a < 2; ++a) {
        jac.addStiffness(i + a, i + 2, -stiffness_ * r[a]);
        jac.addStiffness(i + 2, i + a, -stiffness_ * r[a]);
        jac.addDamping(i + a, i + 2, -damping_ * r[a]);
        jac.addDamping(i + 2, i + a, -damping_ * r[a]);
    }
    // The turning term may be positive (the force pulls the arm away from the target), which
    // would make M − h·D − h²·K indefinite; implicit solvers that ask for a definite matrix get
    // only its stabilising part, and Newton's exact residual recovers the rest.
    double turning = -arm.dot(f);
    if (jac.definite) turning = std::min(turning, 0.0);
    jac.addStiffness(i + 2, i + 2, -stiffness_ * r.squaredNorm() + turning);
    jac.addDamping(i + 2, i + 2, -damping_ * r.squaredNorm());
}

}  // namespace phasebox
