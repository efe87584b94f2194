#include "physics/contacts/KinematicResponse.h"

#include <algorithm>
#include <cmath>

namespace phasebox {

namespace {

double cross(const Vec2& r, const Vec2& e) {
    return r.x() * e.y() - r.y() * e.x();
}

struct Side {
    int dof;
    bool rotates;
    Vec2 r;
    double invMass, invInertia;

    Vec2 velocity(const Vec& u) const {
        if (dof < 0) return Vec2::Zero();
        Vec2 v = u.segment<2>(dof);
        if (rotates) v += u[dof + 2] * Vec2(-r.y(), r.x());
        return v;
    }
    // 1/m_eff of this side along e, at the point.
    double inverseMassAlong(const Vec2& e) const {
        if (dof < 0) return 0.0;
        const double arm = cross(r, e);
        return invMass + (rotates ? invInertia * arm * arm : 0.0);
    }
    void applyImpulse(Vec& u, const Vec2& impulse) const {
        if (dof < 0) return;
        u.segment<2>(dof) += invMass * impulse;
        if (rotates) u[dof + 2] += invInertia * cross(r, impulse);
    }
};

}  // namespace

void separateKinematically(const std::vector<TouchingManifold>& overlaps, const Vec& invMass,
                           Vec& q) {
    for (const TouchingManifold& m : overlaps) {
        const double wA = m.dofA >= 0 ? invMass[m.dofA] : 0.0;
        const double wB = m.dofB >= 0 ? invMass[m.dofB] : 0.0;
        if (!(wA + wB > 0.0)) continue;
        // Apart along the normal by the deepest point's overlap, each body by its share of the
        // inverse mass (the lighter moves more; a static side not at all).
        double depth = 0.0;
        for (int p = 0; p < m.pointCount; ++p) depth = std::max(depth, m.points[p].depth);
        const Vec2 move = depth / (wA + wB) * m.normal;
        if (m.dofA >= 0) q.segment<2>(m.dofA) -= wA * move;
        if (m.dofB >= 0) q.segment<2>(m.dofB) += wB * move;
    }
}

namespace {

// Two points of one manifold answered together: the impulses j (one per point, along e) that
// change the relative velocities along e by target, from K·j = target with K the 2×2 coupling
// of the points through both bodies. False when K is singular (a particle's two points) or,
// for a normal (push-only) answer, when one impulse would pull.
bool solvePair(const Side (&a)[2], const Side (&b)[2], const Vec2& e, const double (&target)[2],
               bool pushOnly, double (&j)[2]) {
    double k[2][2];
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c) {
            double v = a[0].invMass + b[0].invMass;
            if (a[0].rotates) v += a[0].invInertia * cross(a[r].r, e) * cross(a[c].r, e);
            if (b[0].rotates) v += b[0].invInertia * cross(b[r].r, e) * cross(b[c].r, e);
            k[r][c] = v;
        }
    const double det = k[0][0] * k[1][1] - k[0][1] * k[1][0];
    if (!(det > 1e-12 * k[0][0] * k[1][1])) return false;
    j[0] = (k[1][1] * target[0] - k[0][1] * target[1]) / det;
    j[1] = (k[0][0] * target[1] - k[1][0] * target[0]) / det;
    return !pushOnly || (j[0] >= 0.0 && j[1] >= 0.0);
}

}  // namespace

void reflectKinematically(const std::vector<TouchingManifold>& overlaps, const Vec& invMass,
                          Vec& u) {
    for (const TouchingManifold& m : overlaps) {
        const double wA = m.dofA >= 0 ? invMass[m.dofA] : 0.0;
        const double wB = m.dofB >= 0 ? invMass[m.dofB] : 0.0;
        if (!(wA + wB > 0.0)) continue;
        const Vec2 n = m.normal, t(-n.y(), n.x());
        const double keep = std::max(0.0, 1.0 - m.friction);
        const double invIA = m.rotatesA ? invMass[m.dofA + 2] : 0.0;
        const double invIB = m.rotatesB ? invMass[m.dofB + 2] : 0.0;
        Side a[2], b[2];
        for (int p = 0; p < m.pointCount; ++p) {
            a[p] = {m.dofA, m.rotatesA, m.points[p].rA, wA, invIA};
            b[p] = {m.dofB, m.rotatesB, m.points[p].rB, wB, invIB};
        }
        const auto relative = [&](int p, const Vec2& e) {
            return (b[p].velocity(u) - a[p].velocity(u)).dot(e);
        };
        const auto apply = [&](int p, const Vec2& impulse) {
            a[p].applyImpulse(u, -impulse);
            b[p].applyImpulse(u, impulse);
        };
        // A face landing flat on a face (both points approaching) is answered at both points at
        // once, so that a symmetric landing gives no spin; otherwise point by point.
        if (m.pointCount == 2 && relative(0, n) < 0.0 && relative(1, n) < 0.0) {
            const double reflect[2] = {-(1.0 + m.restitution) * relative(0, n),
                                       -(1.0 + m.restitution) * relative(1, n)};
            double jn[2];
            if (solvePair(a, b, n, reflect, true, jn)) {
                apply(0, jn[0] * n);
                apply(1, jn[1] * n);
                const double slow[2] = {-(1.0 - keep) * relative(0, t),
                                        -(1.0 - keep) * relative(1, t)};
                double jt[2];
                if (solvePair(a, b, t, slow, false, jt)) {
                    apply(0, jt[0] * t);
                    apply(1, jt[1] * t);
                } else {
                    // One tangent velocity for both (no lever arm): scale it once.
                    apply(0, (slow[0] / (a[0].inverseMassAlong(t) + b[0].inverseMassAlong(t))) * t);
                }
                continue;
            }
        }
        for (int p = 0; p < m.pointCount; ++p) {
            const double vn = relative(p, n);
            if (vn >= 0.0) continue;  // separating or resting: nothing to reflect
            const double kn = a[p].inverseMassAlong(n) + b[p].inverseMassAlong(n);
            apply(p, (-(1.0 + m.restitution) * vn / kn) * n);
            // The tangential relative velocity, after the normal impulse, scaled by 1 − μ.
            const double kt = a[p].inverseMassAlong(t) + b[p].inverseMassAlong(t);
            apply(p, (-(1.0 - keep) * relative(p, t) / kt) * t);
        }
    }
}

}  // namespace phasebox
