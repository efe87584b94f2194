#include "physics/effects/NewtonianGravityEffect.h"

#include <cmath>

namespace phasebox {

// Calls fn(i, j, r, GMm) for every interacting pair: body dof i against an attractor (j = −1),
// and with mutual, particle dof i against particle dof j > i. r = p_i − p_j.
template <typename Fn>
void NewtonianGravityEffect::forEachPair(const Vec& q, Fn&& fn) const {
    const StateLayout& layout = *view_.layout;
    const Vec& m = *view_.mass;
    auto body = [&](int i) {
        for (const Attractor& at : attractors_)
            fn(i, -1, Vec2(q.segment<2>(i) - at.position), G_ * at.mass * m[i]);
    };
    for (int p = 0; p < layout.dynamicParticles; ++p) body(layout.particleDof(p));
    for (int b = 0; b < layout.dynamicBoxes; ++b) body(layout.boxDof(b));
    if (!mutual_) return;
    for (int a = 0; a < layout.dynamicParticles; ++a) {
        const int i = layout.particleDof(a);
        for (int b = a + 1; b < layout.dynamicParticles; ++b) {
            const int j = layout.particleDof(b);
            fn(i, j, Vec2(q.segment<2>(i) - q.segment<2>(j)), G_ * m[i] * m[j]);
        }
    }
}

double NewtonianGravityEffect::addForces(double, const Vec& q, const Vec&, Vec& force) {
    forEachPair(q, [&](int i, int j, const Vec2& r, double gmm) {
        const double s2 = r.squaredNorm() + softening2_;
        if (!(s2 > 0.0)) return;
        const Vec2 f = (-gmm / (s2 * std::sqrt(s2))) * r;
        force.segment<2>(i) += f;
        if (j >= 0) force.segment<2>(j) -= f;
    });
    return 0.0;
}

void NewtonianGravityEffect::addJacobians(double, const Vec& q, const Vec&,
                                          ForceJacobians& jac) {
    // ∂F_i/∂p_i = −G·M·m·(I/s³ − 3·r·rᵀ/s⁵), s² = ‖r‖² + ε².
    forEachPair(q, [&](int i, int j, const Vec2& r, double gmm) {
        const double s2 = r.squaredNorm() + softening2_;
        if (!(s2 > 0.0)) return;
        const double s3 = s2 * std::sqrt(s2);
        const Mat2 k = -gmm * (Mat2::Identity() / s3 - (3.0 / (s3 * s2)) * (r * r.transpose()));
        jac.addStiffnessBlock(i, i, k);
        if (j < 0) return;
        jac.addStiffnessBlock(j, j, k);
        jac.addStiffnessBlock(i, j, -k);
        jac.addStiffnessBlock(j, i, -k);
    });
}

double NewtonianGravityEffect::potentialEnergy(const Vec& q) const {
    double energy = 0.0;
    forEachPair(q, [&](int, int, const Vec2& r, double gmm) {
        const double s2 = r.squaredNorm() + softening2_;
        if (s2 > 0.0) energy -= gmm / std::sqrt(s2);
    });
    return energy;
}

}  // namespace phasebox
