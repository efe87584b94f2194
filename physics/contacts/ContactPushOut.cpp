// The contact solver's position correction beyond its velocities: overlap deeper than a
// constraint's deepOverlap (bodies started inside each other) pushed out in positions alone, and
// the step's whole push-out, which the world takes off to book its energy as correction.
#include "physics/contacts/ContactChunks.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace phasebox {

const double* ContactSolver::gatherSeparations() {
    if (!lanesHold_) return separation_.data();
    gathered_.resize(2 * rows_.size());
    for (std::size_t r = 0; r < wideCold_.size(); ++r) {
        const ContactSolver::WideCold& w = wideCold_[r];
        const int* rows = order_.data() + kLanes * r;
        for (int l = 0; l < kLanes; ++l) {
            const int i = rows[l];
            if (i < 0) continue;
            gathered_[2 * i] = w.p[0].separation[l];
            gathered_[2 * i + 1] = w.points[l] == 2 ? w.p[1].separation[l] : 0.0;
        }
    }
    for (const int i : overflow_) {  // solved alone: separationOf() reads separation_
        gathered_[2 * i] = separation_[2 * i];
        gathered_[2 * i + 1] = separation_[2 * i + 1];
    }
    return gathered_.data();
}

void ContactSolver::deepPushOut(double h, const ContactSettings& settings) {
    // Gauss-Seidel on positions, translation only (Box2D 2.4's position solver without its
    // Baumgarte factor): each deep row moves its bodies apart in proportion to their inverse
    // masses, by the overlap beyond deepOverlap but at most pushOut·h per pass. Separations
    // are where the last inner sub-step left them, plus these moves.
    const int world = static_cast<int>(bodies_.size());
    ++pushOuts_;
    // Whether any point is that deep, most often not: where the lanes hold the coloured rows,
    // looked for in their separations and deep overlaps, lane by lane and shared, instead of in
    // the constraints' scattered lines (on the 100-row pyramid that walk was 2% of the step, on
    // the calling thread alone). The rows no colour took are in separation_.
    const auto deepPoint = [&](std::size_t i, const double* separation) {
        for (int k = 0; k < constraints_[i].pointCount; ++k)
            if (separation[2 * i + k] < -constraints_[i].deepOverlap) return true;
        return false;
    };
    std::atomic<bool> any{false};
    if (lanesHold_) {
        forColours([&](std::size_t first, std::size_t end) {
            bool found = false;
            for (std::size_t r = first; r < end; ++r) {
                const WideCold& u = wideCold_[r];
                const WideSetup& setup = wideSetup_[r];
                for (int k = 0; k < 2; ++k)
                    for (int l = 0; l < kLanes; ++l)
                        found |= k < u.points[l] && u.p[k].separation[l] < -setup.deepOverlap[l];
            }
            if (found) any.store(true, std::memory_order_relaxed);
        });
        for (const int i : overflow_)
            if (deepPoint(static_cast<std::size_t>(i), separation_.data())) any = true;
    } else {
        for (std::size_t i = 0; i < constraints_.size() && !any; ++i)
            if (deepPoint(i, separation_.data())) any = true;
    }
    if (!any) return;
    const double* separation = gatherSeparations();
    deep_.resize(constraints_.size());
    for (std::size_t i = 0; i < constraints_.size(); ++i) {
        const ContactConstraint& c = constraints_[i];
        DeepRow& d = deep_[i];
        d.a = c.bodyA >= 0 ? c.bodyA : world;
        d.b = c.bodyB >= 0 ? c.bodyB : world;
        d.nx = c.normal.x();
        d.ny = c.normal.y();
        d.separation = std::numeric_limits<double>::infinity();
        for (int k = 0; k < c.pointCount; ++k)
            d.separation = std::min(d.separation, separation[2 * i + k]);
        d.deepOverlap = c.deepOverlap;
    }
    deepShift_.assign(bodies_.size() + 1, Vec2::Zero());
    const double step = settings.pushOut * h;
    for (int pass = 0; pass < kDeepPushOutPasses; ++pass) {
        for (const DeepRow& c : deep_) {
            const Vec2 n(c.nx, c.ny);
            const double moved = n.dot(deepShift_[c.b] - deepShift_[c.a]);
            const double deepest = std::min(0.0, c.separation + moved);
            const double excess = -(deepest + c.deepOverlap);
            if (!(excess > 0.0)) continue;
            const double wA = c.a < world ? state_[c.a].invMass : 0.0;
            const double wB = c.b < world ? state_[c.b].invMass : 0.0;
            if (!(wA + wB > 0.0)) continue;
            const double push = std::min(excess, step) / (wA + wB);
            deepShift_[c.a] -= push * wA * n;
            deepShift_[c.b] += push * wB * n;
            if (c.a != world && c.b != world) continue;
            // Out of static geometry: one more solve running (counted once a call).
            const int dof = bodies_[c.a == world ? c.b : c.a].dof;
            if (static_cast<std::size_t>(dof) >= jammed_.size()) jammed_.resize(dof + 1);
            Jammed& jam = jammed_[dof];
            if (jam.at == pushOuts_) continue;
            jam.solves = jam.at + 1 == pushOuts_ ? jam.solves + 1 : 1;
            jam.at = pushOuts_;
        }
    }
    for (int k = 0; k < world; ++k) {
        bodies_[k].shift += deepShift_[k];
        bodies_[k].pushOut += deepShift_[k];
    }
}

bool ContactSolver::jammedWeights(const Vec& weights, double factor, Vec& out) const {
    bool any = false;
    for (const SolverBody& b : bodies_) {
        const auto dof = static_cast<std::size_t>(b.dof);
        if (dof >= jammed_.size() || jammed_[dof].at != pushOuts_ ||
            jammed_[dof].solves < kJammedSolves)
            continue;
        if (!any) out = weights;  // the same size after the first: no allocation
        any = true;
        out.segment<2>(b.dof) *= factor;
        if (b.rotates) out[b.dof + 2] *= factor;
    }
    return any;
}

void ContactSolver::addPushOut(Vec& q, double scale) const {
    for (const SolverBody& b : bodies_) {
        q.segment<2>(b.dof) += scale * b.pushOut;
        if (b.rotates) q[b.dof + 2] += scale * b.pushOutAngle;
    }
}

}  // namespace phasebox
