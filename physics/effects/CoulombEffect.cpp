#include "physics/effects/CoulombEffect.h"

#include "physics/core/Bodies.h"
#include "physics/effects/InverseSquare.h"

#include <cmath>

namespace phasebox {

void CoulombEffect::bind(const EffectWorldView& view) {
    Effect::bind(view);
    free_.clear();
    fixed_.clear();
    if (!view.particles) return;
    const int end = view.layout->rigidBase();
    for (const Particle& p : *view.particles) {
        if (p.charge == 0.0) continue;
        if (p.pinned) fixed_.push_back({p.position, p.charge});
        // A dof outside the layout is stale (bound before the commit that rebinds): skipped.
        else if (p.dof >= 0 && p.dof < end)
            free_.push_back({p.dof, p.charge});
    }
}

// Calls fn(i, j, r, kqq) for every interacting pair: a free charge at dof i against a fixed one
// (j = −1), and free charges i < j against each other; r = p_i − p_j.
template <typename Fn>
void CoulombEffect::forEachPair(const Vec& q, Fn&& fn) const {
    const std::size_t n = free_.size();
    for (std::size_t a = 0; a < n; ++a) {
        const int i = free_[a].dof;
        const Vec2 pi = q.segment<2>(i);
        const double kq = k_ * free_[a].charge;
        for (const FixedCharge& source : fixed_)
            fn(i, -1, Vec2(pi - source.position), kq * source.charge);
        for (std::size_t b = a + 1; b < n; ++b) {
            const int j = free_[b].dof;
            fn(i, j, Vec2(pi - q.segment<2>(j)), kq * free_[b].charge);
        }
    }
}

double CoulombEffect::addForces(double, const Vec& q, const Vec&, Vec& force) {
    forEachPair(q, [&](int i, int j, const Vec2& r, double kqq) {
        inverse_square::addForce(kqq, r, softening2_, i, j, force);
    });
    return 0.0;
}

void CoulombEffect::addJacobians(double, const Vec& q, const Vec&, ForceJacobians& jac) {
    // ∂F_i/∂p_i = k·q_i·q_j·(I/s³ − 3·r·rᵀ/s⁵), s² = ‖r‖² + ε² (inverse_square).
    forEachPair(q, [&](int i, int j, const Vec2& r, double kqq) {
        inverse_square::addJacobian(kqq, r, softening2_, i, j, jac);
    });
}

double CoulombEffect::potentialEnergy(const Vec& q) const {
    double energy = 0.0;
    forEachPair(q, [&](int, int, const Vec2& r, double kqq) {
        energy += inverse_square::potential(kqq, r, softening2_);
    });
    return energy;
}

}  // namespace phasebox
