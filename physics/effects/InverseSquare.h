#pragma once
// The pair law shared by Coulomb's force and Newton's gravity: for a pair at separation
// r = p_i − p_j with softened distance s = √(‖r‖² + ε²) and strength c (c = k·q_i·q_j for
// charges, c = −G·m_i·m_j for masses), the potential is c/s, the force on i is c·r/s³ (on j
// its opposite), and ∂F_i/∂p_i = c·(I/s³ − 3·r·rᵀ/s⁵). A pair at s = 0 (no softening,
// coincident points) contributes nothing, but still writes its (zero) Jacobian block so that
// the implicit solver's pattern does not change.

#include "physics/core/OdeSystem.h"
#include "physics/core/Types.h"

#include <cmath>

namespace phasebox::inverse_square {

inline void addForce(double strength, const Vec2& r, double softening2, int i, int j, Vec& force) {
    const double s2 = r.squaredNorm() + softening2;
    if (!(s2 > 0.0)) return;
    const Vec2 f = (strength / (s2 * std::sqrt(s2))) * r;
    force.segment<2>(i) += f;
    if (j >= 0) force.segment<2>(j) -= f;
}

inline void addJacobian(double strength, const Vec2& r, double softening2, int i, int j,
                        ForceJacobians& jac) {
    const double s2 = r.squaredNorm() + softening2;
    Mat2 k = Mat2::Zero();
    if (s2 > 0.0) {
        const double s3 = s2 * std::sqrt(s2);
        k = strength * (Mat2::Identity() / s3 - (3.0 / (s3 * s2)) * (r * r.transpose()));
    }
    jac.addStiffnessPair(i, j, k);
}

inline double potential(double strength, const Vec2& r, double softening2) {
    const double s2 = r.squaredNorm() + softening2;
    return s2 > 0.0 ? strength / std::sqrt(s2) : 0.0;
}

}  // namespace phasebox::inverse_square
