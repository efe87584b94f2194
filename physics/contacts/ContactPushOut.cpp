// The contact solver's position correction beyond its velocities: overlap deeper than a
// constraint's deepOverlap (bodies started inside each other) pushed out in positions alone, and
// the step's whole push-out, which the world takes off to book its energy as correction.
#include "physics/contacts/ContactSolver.h"

#include <algorithm>
#include <cmath>

namespace phasebox {

void ContactSolver::deepPushOut(double h, const ContactSettings& settings) {
    // Gauss-Seidel on positions, translation only (Box2D 2.4's position solver without its
    // Baumgarte factor): each deep row moves its bodies apart in proportion to their inverse
    // masses, by the overlap beyond deepOverlap but at most pushOut·h per pass. Separations
    // are where the last inner sub-step left them, plus these moves.
    const int world = static_cast<int>(bodies_.size());
    bool any = false;
    for (std::size_t i = 0; i < rows_.size() && !any; ++i)
        for (int k = 0; k < rows_[i].pointCount; ++k)
            any = any || separationOf(i, k) < -setup_[i].deepOverlap;
    if (!any) return;
    deepShift_.assign(bodies_.size() + 1, Vec2::Zero());
    const double step = settings.pushOut * h;
    for (int pass = 0; pass < kDeepPushOutPasses; ++pass) {
        for (std::size_t i = 0; i < rows_.size(); ++i) {
            const Row& c = rows_[i];
            const Vec2 n(c.nx, c.ny);
            const double moved = n.dot(deepShift_[c.b] - deepShift_[c.a]);
            double deepest = 0.0;
            for (int k = 0; k < c.pointCount; ++k)
                deepest = std::min(deepest, separationOf(i, k) + moved);
            const double excess = -(deepest + setup_[i].deepOverlap);
            if (!(excess > 0.0)) continue;
            const double wA = c.a < world ? state_[c.a].invMass : 0.0;
            const double wB = c.b < world ? state_[c.b].invMass : 0.0;
            if (!(wA + wB > 0.0)) continue;
            const double push = std::min(excess, step) / (wA + wB);
            deepShift_[c.a] -= push * wA * n;
            deepShift_[c.b] += push * wB * n;
        }
    }
    for (int k = 0; k < world; ++k) {
        bodies_[k].shift += deepShift_[k];
        bodies_[k].pushOut += deepShift_[k];
    }
}

void ContactSolver::addPushOut(Vec& q, double scale) const {
    for (const SolverBody& b : bodies_) {
        q.segment<2>(b.dof) += scale * b.pushOut;
        if (b.rotates) q[b.dof + 2] += scale * b.pushOutAngle;
    }
}

}  // namespace phasebox
