#include "physics/effects/NewtonianGravityEffect.h"

#include "physics/effects/InverseSquare.h"

#include <cmath>
#include <limits>

namespace phasebox {

bool NewtonianGravityEffect::usesTree() const {
    return mutual_ && view_.layout && view_.layout->dynamicParticles > treeThreshold_;
}

// Calls fn(i, j, r, GMm) for every pair summed directly: body dof i against an attractor
// (j = −1), and with mutualPairs, particle dof i against particle dof j > i. r = p_i − p_j.
template <typename Fn>
void NewtonianGravityEffect::forEachPair(const Vec& q, bool mutualPairs, Fn&& fn) const {
    const StateLayout& layout = *view_.layout;
    const Vec& m = *view_.mass;
    auto body = [&](int i) {
        for (const Attractor& at : attractors_)
            fn(i, -1, Vec2(q.segment<2>(i) - at.position), G_ * at.mass * m[i]);
    };
    for (int p = 0; p < layout.dynamicParticles; ++p) body(layout.particleDof(p));
    for (int b = 0; b < layout.dynamicRigidBodies; ++b) body(layout.rigidDof(b));
    if (!mutualPairs) return;
    for (int a = 0; a < layout.dynamicParticles; ++a) {
        const int i = layout.particleDof(a);
        for (int b = a + 1; b < layout.dynamicParticles; ++b) {
            const int j = layout.particleDof(b);
            fn(i, j, Vec2(q.segment<2>(i) - q.segment<2>(j)), G_ * m[i] * m[j]);
        }
    }
}

double NewtonianGravityEffect::addForces(double, const Vec& q, const Vec&, Vec& force) {
    const bool tree = usesTree();
    if (tree) {
        const int n = view_.layout->dynamicParticles;
        if (tree_.build(q.data(), view_.mass->data(), n, openingAngle_)) {
            tree_.addForces(G_, softening2_, force.data(), view_.pool);
        } else {
            // A non-finite position: the forces are not finite either, which the world reports
            // as a divergence (the tree cannot sort such a body into a cell).
            force.head(2 * n).setConstant(std::numeric_limits<double>::quiet_NaN());
        }
    }
    forEachPair(q, mutual_ && !tree, [&](int i, int j, const Vec2& r, double gmm) {
        inverse_square::addForce(-gmm, r, softening2_, i, j, force);
    });
    return 0.0;
}

void NewtonianGravityEffect::addJacobians(double, const Vec& q, const Vec&, ForceJacobians& jac) {
    // ∂F_i/∂p_i = −G·M·m·(I/s³ − 3·r·rᵀ/s⁵), s² = ‖r‖² + ε² (inverse_square). None for the
    // tree's pairs.
    forEachPair(q, mutual_ && !usesTree(), [&](int i, int j, const Vec2& r, double gmm) {
        inverse_square::addJacobian(-gmm, r, softening2_, i, j, jac);
    });
}

double NewtonianGravityEffect::potentialEnergy(const Vec& q) const {
    double energy = 0.0;
    const bool tree = usesTree();
    if (tree) {
        if (!tree_.build(q.data(), view_.mass->data(), view_.layout->dynamicParticles,
                         openingAngle_))
            return std::numeric_limits<double>::quiet_NaN();
        energy += tree_.potentialEnergy(G_, softening2_);
    }
    forEachPair(q, mutual_ && !tree, [&](int, int, const Vec2& r, double gmm) {
        energy += inverse_square::potential(-gmm, r, softening2_);
    });
    return energy;
}

}  // namespace phasebox
