#include "physics/effects/DragEffect.h"

namespace phasebox {

namespace {
// Calls fn(dof) for the first translational dof of every dynamic particle and box.
template <typename Fn>
void forEachBody(const StateLayout& layout, Fn&& fn) {
    for (int p = 0; p < layout.dynamicParticles; ++p) fn(layout.particleDof(p));
    for (int b = 0; b < layout.dynamicRigidBodies; ++b) fn(layout.rigidDof(b));
}
}  // namespace

double DragEffect::addForces(double, const Vec&, const Vec& u, Vec& force) {
    double power = 0.0;
    forEachBody(*view_.layout, [&](int i) {
        const Vec2 v = u.segment<2>(i);
        const double speed = v.norm();
        const Vec2 f = -(linear_ + quadratic_ * speed) * v;
        force.segment<2>(i) += f;
        power += f.dot(v);
    });
    if (angular_ != 0.0) {
        const StateLayout& layout = *view_.layout;
        for (int b = 0; b < layout.dynamicRigidBodies; ++b) {
            const int i = layout.rigidDof(b) + 2;
            force[i] -= angular_ * u[i];
            power -= angular_ * u[i] * u[i];
        }
    }
    return power;
}

double DragEffect::nonConservativePower(double, const Vec&, const Vec& u) {
    double power = 0.0;
    forEachBody(*view_.layout, [&](int i) {
        const double speed = u.segment<2>(i).norm();
        power -= (linear_ + quadratic_ * speed) * speed * speed;
    });
    const StateLayout& layout = *view_.layout;
    for (int b = 0; b < layout.dynamicRigidBodies; ++b) {
        const double w = u[layout.rigidDof(b) + 2];
        power -= angular_ * w * w;
    }
    return power;
}

void DragEffect::addJacobians(double, const Vec&, const Vec& u, ForceJacobians& jacobians) {
    // ∂F/∂v = −b·I − c·(‖v‖·I + v·vᵀ/‖v‖): symmetric.
    forEachBody(*view_.layout, [&](int i) {
        const Vec2 v = u.segment<2>(i);
        const double speed = v.norm();
        Mat2 d = -(linear_ + quadratic_ * speed) * Mat2::Identity();
        if (quadratic_ != 0.0 && speed > 0.0) d -= (quadratic_ / speed) * (v * v.transpose());
        jacobians.addDampingBlock(i, i, d);
    });
    if (angular_ != 0.0) {
        const StateLayout& layout = *view_.layout;
        for (int b = 0; b < layout.dynamicRigidBodies; ++b) {
            const int i = layout.rigidDof(b) + 2;
            jacobians.addDamping(i, i, -angular_);
        }
    }
}

}  // namespace phasebox
