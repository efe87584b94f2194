// The contacts' relax where they meet joints (ContactSolver::relaxJoined): one projected
// Gauss-Seidel over the contact rows with the joint rows eliminated. A contact impulse dp on a
// row g moves the state by dp·W'·gᵀ, W' = W − W·Jᵀ·(J·W·Jᵀ)⁻¹·J·W: the bodies' response with the
// joints held (the Schur complement of the joint rows in the system of both). So the joints hold
// exactly at every update, and the contacts see the effective mass of everything jointed to
// them: a car's wheel is pressed into the ground by the whole car through its hinge. The
// response W'·gᵀ of a row touching a jointed body is one solve with the joints' factors (O(n) for
// chains and trees) and is kept for the sweeps; a row between bodies no joint holds moves only
// its own two bodies (there J·W·gᵀ = 0 and W' = W).
#include "physics/contacts/ContactSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace phasebox {

namespace {
double crossOf(double rx, double ry, double dx, double dy) {
    return rx * dy - ry * dx;
}
}  // namespace

void ContactSolver::addFreeResponse(const JoinedRow& r, double scale, Vec& x) const {
    const auto side = [&](int dof, bool turns, const double* g, const double* w) {
        if (dof < 0) return;
        x[dof] += scale * w[0] * g[0];
        x[dof + 1] += scale * w[1] * g[1];
        if (turns) x[dof + 2] += scale * w[2] * g[2];
    };
    side(r.dofA, r.turnsA, r.ga, r.wa);
    side(r.dofB, r.turnsB, r.gb, r.wb);
}

double ContactSolver::joinedVelocity(const JoinedRow& r, const Vec& u) const {
    double v = 0.0;
    if (r.dofA >= 0) {
        v += r.ga[0] * u[r.dofA] + r.ga[1] * u[r.dofA + 1];
        if (r.turnsA) v += r.ga[2] * u[r.dofA + 2];
    }
    if (r.dofB >= 0) {
        v += r.gb[0] * u[r.dofB] + r.gb[1] * u[r.dofB + 1];
        if (r.turnsB) v += r.gb[2] * u[r.dofB + 2];
    }
    return v;
}

void ContactSolver::applyJoined(const JoinedRow& r, double dp, Vec& u,
                                const TangentProjection& joints) {
    if (r.column >= 0) {
        const double* w = joinedColumns_.data() + static_cast<std::size_t>(r.column) * u.size();
        for (int i = r.from; i < r.to; ++i) u[i] += dp * w[i];
    } else if (!r.jointed) {
        addFreeResponse(r, dp, u);
    } else {
        joinedScratch_.setZero();
        addFreeResponse(r, dp, joinedScratch_);
        joints.project(joinedScratch_);
        u += joinedScratch_;
    }
}

double ContactSolver::joinedCoupling(const JoinedRow& r, const JoinedRow& s,
                                     const TangentProjection& joints) {
    // g_r·(W'·g_sᵀ): the response of s read through r's row.
    joinedScratch_.setZero();
    applyJoined(s, 1.0, joinedScratch_, joints);
    return joinedVelocity(r, joinedScratch_);
}

void ContactSolver::buildJoinedRows(int n) {
    const int world = static_cast<int>(bodies_.size());
    joined_.clear();
    // Room for as many rows as the contacts were reserved for, at the first joined step (a
    // scene without joints never comes here): the counts' new largest values allocate nothing.
    const std::size_t room = constraints_.capacity();
    if (joined_.capacity() < 4 * room) joined_.reserve(4 * room);
    if (joinedStart_.capacity() < room + 1) joinedStart_.reserve(room + 1);
    if (blockCoupling_.capacity() < room) blockCoupling_.reserve(room);
    joinedStart_.assign(rows_.size() + 1, 0);
    joinedScratch_.setZero(n);
    joinedCached_ = 0;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        const Row& c = rows_[i];
        joinedStart_[i] = static_cast<int>(joined_.size());
        const bool jointed =
            (c.a < world && bodies_[c.a].jointed) || (c.b < world && bodies_[c.b].jointed);
        const auto add = [&](int k, bool normal) {
            const RowPoint& p = c.p[k];
            const double dx = normal ? c.nx : c.ny, dy = normal ? c.ny : -c.nx;
            JoinedRow r{};
            r.row = static_cast<int>(i);
            r.point = k;
            r.normal = normal;
            r.dofA = c.a < world ? bodies_[c.a].dof : -1;
            r.dofB = c.b < world ? bodies_[c.b].dof : -1;
            const auto masses = [&](int body, double* w) {
                const bool dynamic = body < world;
                w[0] = w[1] = dynamic ? bodies_[body].invMass : 0.0;
                w[2] = dynamic ? bodies_[body].invInertia : 0.0;
                return dynamic && bodies_[body].rotates;
            };
            const bool turnsA = r.turnsA = masses(c.a, r.wa);
            const bool turnsB = r.turnsB = masses(c.b, r.wb);
            r.ga[0] = -dx;
            r.ga[1] = -dy;
            r.ga[2] = turnsA ? -crossOf(p.rAx, p.rAy, dx, dy) : 0.0;
            r.gb[0] = dx;
            r.gb[1] = dy;
            r.gb[2] = turnsB ? crossOf(p.rBx, p.rBy, dx, dy) : 0.0;
            r.jointed = jointed;
            r.column = -1;
            r.from = 0;
            r.to = n;
            r.inverseMass = -1.0;  // not yet needed (readyJoined())
            joined_.push_back(r);
        };
        for (int k = 0; k < c.pointCount; ++k)
            if (effectiveMassOf(i, k) != 0.0) add(k, true);
        if (c.friction > 0.0)
            for (int k = 0; k < c.pointCount; ++k) add(k, false);
    }
    joinedStart_[rows_.size()] = static_cast<int>(joined_.size());
}

bool ContactSolver::readyJoined(JoinedRow& r, const TangentProjection& joints) {
    // A row's response is worked out the first time the row would act: most rows of a chain
    // folding onto itself are speculative or separating and never do.
    if (r.inverseMass >= 0.0) return r.inverseMass > 0.0;
    const int n = static_cast<int>(joinedScratch_.size());
    const std::size_t cacheable = n > 0 ? kJoinedCacheEntries / static_cast<std::size_t>(n) : 0;
    if (r.jointed && joinedCached_ < cacheable) {
        r.column = static_cast<int>(joinedCached_++);
        // Grows only (kept from step to step), by doubling: the columns before stay.
        const Eigen::Index need = static_cast<Eigen::Index>(joinedCached_) * n;
        if (joinedColumns_.size() < need)
            joinedColumns_.conservativeResize(std::max(need, 2 * joinedColumns_.size()));
        joinedScratch_.setZero();
        addFreeResponse(r, 1.0, joinedScratch_);
        joints.project(joinedScratch_);
        double* w = joinedColumns_.data() + static_cast<std::size_t>(r.column) * n;
        r.from = n;
        r.to = 0;
        for (int d = 0; d < n; ++d) {
            w[d] = joinedScratch_[d];
            if (w[d] != 0.0) {
                r.from = std::min(r.from, d);
                r.to = d + 1;
            }
        }
        if (r.from > r.to) r.from = r.to = 0;
    }
    joinedScratch_.setZero();
    addFreeResponse(r, 1.0, joinedScratch_);
    const double free = joinedVelocity(r, joinedScratch_);
    joinedScratch_.setZero();
    applyJoined(r, 1.0, joinedScratch_, joints);
    r.inverseMass = joinedVelocity(r, joinedScratch_);
    // A row the joints hold still (between two welded bodies, on a body welded to the ground)
    // takes no impulse: what is left of its inverse mass is round-off.
    if (r.inverseMass > kJoinedRankFloor * free) return true;
    r.inverseMass = 0.0;
    RowPoint& p = rows_[r.row].p[r.point];
    (r.normal ? p.normalImpulse : p.tangentImpulse) = 0.0;
    return false;
}

void ContactSolver::relaxJoined(Vec& u, const TangentProjection& joints) {
    if (rows_.empty()) return;
    unpackRows();
    buildJoinedRows(static_cast<int>(u.size()));
    // Each row's diagonal with its compliance (kJoinedCompliance).
    constexpr double kSoft = 1.0 + kJoinedCompliance;
    const auto impulseOf = [&](const JoinedRow& r) -> double& {
        RowPoint& p = rows_[r.row].p[r.point];
        return r.normal ? p.normalImpulse : p.tangentImpulse;
    };
    const auto update = [&](JoinedRow& r, double dp) {
        if (dp == 0.0) return 0.0;
        impulseOf(r) += dp;
        r.applied += dp;
        applyJoined(r, dp, u, joints);
        return std::abs(dp) * r.inverseMass;
    };
    // The two normal rows of a manifold as a block (Box2D's block solver: the four cases of
    // the 2×2 complementarity problem), which keeps a body resting on two points from rocking
    // between them over the sweeps; their coupling through W', once both are ready.
    blockCoupling_.assign(rows_.size(), std::numeric_limits<double>::quiet_NaN());
    const auto solveBlock = [&](std::size_t i, JoinedRow& r1, JoinedRow& r2) {
        const double l1 = impulseOf(r1), l2 = impulseOf(r2);
        const double v1 = joinedVelocity(r1, u), v2 = joinedVelocity(r2, u);
        if (l1 == 0.0 && l2 == 0.0 && v1 >= 0.0 && v2 >= 0.0) return 0.0;  // neither acts
        if (!readyJoined(r1, joints) || !readyJoined(r2, joints)) return -1.0;
        if (std::isnan(blockCoupling_[i])) blockCoupling_[i] = joinedCoupling(r1, r2, joints);
        const double a11 = kSoft * r1.inverseMass, a22 = kSoft * r2.inverseMass;
        const double a12 = blockCoupling_[i];
        // b = v − A·λ: the velocities with the accumulated impulses taken away.
        const double b1 = v1 - (a11 * l1 + a12 * l2), b2 = v2 - (a12 * l1 + a22 * l2);
        const double det = a11 * a22 - a12 * a12;
        double x1 = -1.0, x2 = -1.0;
        if (det > 1e-9 * a11 * a22) {
            x1 = (-b1 * a22 + b2 * a12) / det;
            x2 = (-b2 * a11 + b1 * a12) / det;
        }
        if (!(x1 >= 0.0 && x2 >= 0.0)) {
            x1 = -b1 / a11;
            x2 = 0.0;
            if (!(x1 >= 0.0 && a12 * x1 + b2 >= 0.0)) {
                x1 = 0.0;
                x2 = -b2 / a22;
                if (!(x2 >= 0.0 && a12 * x2 + b1 >= 0.0)) x1 = x2 = 0.0;
            }
        }
        return std::max(update(r1, x1 - l1), update(r2, x2 - l2));
    };
    const auto solveScalar = [&](std::size_t i, JoinedRow& r) {
        const double v = joinedVelocity(r, u);
        const double old = impulseOf(r);
        // A normal row with no impulse whose point separates, or a friction row with no normal
        // impulse to bound it, does not act.
        const double limit = r.normal ? 0.0 : rows_[i].friction * rows_[i].p[r.point].normalImpulse;
        if (old == 0.0 && (r.normal ? v >= 0.0 : limit == 0.0)) return 0.0;
        if (!readyJoined(r, joints)) return 0.0;
        double next = old - v / (kSoft * r.inverseMass);
        next = r.normal ? std::max(next, 0.0) : std::clamp(next, -limit, limit);
        return update(r, next - old);
    };
    for (int sweep = 0; sweep < kJoinedSweeps; ++sweep) {
        double change = 0.0;  // the largest change of a row's own velocity in the sweep
        for (std::size_t i = 0; i < rows_.size(); ++i) {
            const int start = joinedStart_[i], end = joinedStart_[i + 1];
            int t = start;
            if (end - start >= 2 && joined_[start].normal && joined_[start + 1].normal) {
                const double block = solveBlock(i, joined_[start], joined_[start + 1]);
                if (block >= 0.0) {
                    change = std::max(change, block);
                    t = start + 2;
                }
            }
            for (; t < end; ++t) change = std::max(change, solveScalar(i, joined_[t]));
        }
        if (change <= kJoinedTolerance) break;
    }
    // What the contacts gave each body in this solve (probes' contact force).
    const int world = static_cast<int>(bodies_.size());
    for (const JoinedRow& r : joined_) {
        const Row& c = rows_[r.row];
        const Vec2 dir = r.normal ? Vec2(c.nx, c.ny) : Vec2(c.ny, -c.nx);
        if (c.a < world) bodies_[c.a].stepImpulse -= r.applied * dir;
        if (c.b < world) bodies_[c.b].stepImpulse += r.applied * dir;
    }
}

}  // namespace phasebox
