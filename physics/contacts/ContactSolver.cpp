#include "physics/contacts/ContactSolver.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace phasebox {

namespace {
constexpr int kMaxCollisionPasses = 32;

Vec2 tangentOf(const Vec2& n) { return {n.y(), -n.x()}; }

// Velocity of a body's point with arm r (zero for a static body).
Vec2 pointVelocity(const SolverBody* b, const Vec2& r) {
    if (!b) return Vec2::Zero();
    return b->v + b->w * perp(r);
}

// Moves a body as a positional impulse would, without changing its velocity.
void shiftBody(SolverBody* b, const Vec2& r, const Vec2& impulse) {
    if (!b) return;
    b->timeShift += b->invMass * impulse;
    b->angleTimeShift += b->invInertia * cross(r, impulse);
}

void applyImpulse(SolverBody* b, const Vec2& r, const Vec2& impulse) {
    if (!b) return;
    b->v += b->invMass * impulse;
    b->w += b->invInertia * cross(r, impulse);
}
}  // namespace

// Soft constraint coefficients (Box2D v3's b2MakeSoft): a spring-damper of frequency ω and
// damping ratio ζ, integrated implicitly over h, expressed as a bias rate and the scales of
// the effective mass and of the accumulated impulse.
ContactSolver::Softness ContactSolver::makeSoft(double hertz, double zeta, double h) {
    const double omega = 2.0 * std::numbers::pi * hertz;
    const double a1 = 2.0 * zeta + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

void ContactSolver::prepare() {
    for (SolverBody& b : bodies_) b.contactCount = 0;
    for (const ContactConstraint& c : constraints_) {
        if (c.bodyA >= 0) ++bodies_[c.bodyA].contactCount;
        if (c.bodyB >= 0) ++bodies_[c.bodyB].contactCount;
    }
    for (ContactConstraint& c : constraints_) {
        const SolverBody* a = c.bodyA >= 0 ? &bodies_[c.bodyA] : nullptr;
        const SolverBody* b = c.bodyB >= 0 ? &bodies_[c.bodyB] : nullptr;
        const double mA = a ? a->invMass : 0.0, iA = a ? a->invInertia : 0.0;
        const double mB = b ? b->invMass : 0.0, iB = b ? b->invInertia : 0.0;
        // A contact's stiffness follows the heavier of its bodies: the spring that holds a heavy
        // box on a light one must be as stiff as for the heavy box, or the light one is
        // squashed in (its effective mass sets the soft constraint's spring). Contacts with the
        // static world are twice as stiff (Box2D v3): they carry whole stacks.
        if (a && b) {
            const double heavy = std::max(1.0 / a->invMass, 1.0 / b->invMass);
            const double light = std::min(1.0 / a->invMass, 1.0 / b->invMass);
            c.stiffness = std::sqrt(heavy / light);
        } else {
            c.stiffness = 2.0;
        }
        const Vec2 t = tangentOf(c.normal);
        for (int k = 0; k < c.pointCount; ++k) {
            ContactPoint& p = c.points[k];
            const double rnA = cross(p.anchorA, c.normal), rnB = cross(p.anchorB, c.normal);
            const double kn = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
            p.normalMass = kn > 0.0 ? 1.0 / kn : 0.0;
            const double rtA = cross(p.anchorA, t), rtB = cross(p.anchorB, t);
            const double kt = mA + mB + iA * rtA * rtA + iB * rtB * rtB;
            p.tangentMass = kt > 0.0 ? 1.0 / kt : 0.0;
        }
    }
}

void ContactSolver::loadBodies(const Vec& q0, const Vec& u0, const Vec& u) {
    for (SolverBody& b : bodies_) {
        b.v0 = b.v = u0.segment<2>(b.dof);
        b.smoothDv = u.segment<2>(b.dof) - b.v0;
        b.startOffset = q0.segment<2>(b.dof) - b.collidePosition;
        b.shift = b.path = b.timeShift = b.pushOut = b.bounceDv = Vec2::Zero();
        b.angleShift = b.anglePath = b.angleTimeShift = b.pushOutAngle = b.bounceDw = 0.0;
        if (b.rotates) {
            b.w0 = b.w = u0[b.dof + 2];
            b.smoothDw = u[b.dof + 2] - b.w0;
            b.startAngle = q0[b.dof + 2] - b.collideAngle;
        }
    }
}

void ContactSolver::updateSeparations() {
    // Bodies hold still while the solver iterates (positions move once per inner sub-step), so
    // each point's separation is computed once per phase, not once per iteration: the rotations
    // alone (a sine and a cosine per body and point) were a quarter of the solver's time.
    for (SolverBody& b : bodies_) {
        b.dp = b.startOffset + b.path + b.timeShift;
        b.dRotation =
            b.rotates ? rotation(b.startAngle + b.anglePath + b.angleTimeShift) : Mat2::Identity();
    }
    for (ContactConstraint& c : constraints_) {
        const SolverBody* a = c.bodyA >= 0 ? &bodies_[c.bodyA] : nullptr;
        const SolverBody* b = c.bodyB >= 0 ? &bodies_[c.bodyB] : nullptr;
        for (int k = 0; k < c.pointCount; ++k) {
            ContactPoint& p = c.points[k];
            // The anchors turn with their bodies: s = s₀ + n·(Δp_B − Δp_A), Δp = Δx + R(Δθ)·r − r.
            Vec2 d = Vec2::Zero();
            if (a) d -= a->dp + (a->dRotation * p.anchorA - p.anchorA);
            if (b) d += b->dp + (b->dRotation * p.anchorB - p.anchorB);
            p.separation = p.baseSeparation + c.normal.dot(d);
        }
    }
}

void ContactSolver::warmStart() {
    for (ContactConstraint& c : constraints_) {
        SolverBody* a = c.bodyA >= 0 ? &bodies_[c.bodyA] : nullptr;
        SolverBody* b = c.bodyB >= 0 ? &bodies_[c.bodyB] : nullptr;
        const Vec2 t = tangentOf(c.normal);
        for (int k = 0; k < c.pointCount; ++k) {
            const ContactPoint& p = c.points[k];
            const Vec2& rA = p.anchorA;
            const Vec2& rB = p.anchorB;
            const Vec2 impulse = p.normalImpulse * c.normal + p.tangentImpulse * t;
            applyImpulse(a, rA, -impulse);
            applyImpulse(b, rB, impulse);
        }
    }
}

void ContactSolver::bounce(double h, const ContactSettings& settings) {
    // Passes on the current velocities until no contact that meets within this inner sub-step
    // approaches faster than the threshold: v_n ← −e·v_n. Each application conserves energy
    // exactly when e = 1 whatever else touches the bodies, and the passes let a row of touching
    // balls hand an impact on ball by ball (Newton's cradle). Bouncing in the inner sub-steps
    // puts the impact within 1/kInnerRate s of its true time whatever the frame: the velocity
    // reflected is the one of the impact, not the end of a long step's (a ball dropped 1 m at
    // dt = 1 s would otherwise leave at 9.8 m/s and climb far above where it fell from).
    for (ContactConstraint& c : constraints_)
        for (int k = 0; k < c.pointCount; ++k) c.points[k].shifted = false;
    for (int pass = 0; pass < kMaxCollisionPasses; ++pass) {
        bool any = false;
        for (ContactConstraint& c : constraints_) {
            if (c.restitution == 0.0) continue;
            SolverBody* a = c.bodyA >= 0 ? &bodies_[c.bodyA] : nullptr;
            SolverBody* b = c.bodyB >= 0 ? &bodies_[c.bodyB] : nullptr;
            for (int k = 0; k < c.pointCount; ++k) {
                ContactPoint& p = c.points[k];
                const double s = p.separation;
                const double vn = c.normal.dot(pointVelocity(b, p.anchorB) - pointVelocity(a, p.anchorA));
                // The threshold keeps resting contact quiet (gravity presses a box on the floor
                // at g·h per sub-step); it shrinks with 1 − e, so that e = 1 is exactly elastic
                // however slow the collision, as the lecture's e = 1 means.
                const double threshold = settings.restitutionThreshold * (1.0 - c.restitution);
                if (vn >= -threshold || vn >= 0.0 || s + h * vn > 0.0) continue;
                const double lambda = -p.normalMass * (1.0 + c.restitution) * vn;
                applyImpulse(a, p.anchorA, -lambda * c.normal);
                applyImpulse(b, p.anchorB, lambda * c.normal);
                any = true;
                // Time of impact: the bodies meet s/|v_n| into the sub-step and separate for the
                // rest of it, so they end (1 + e)·s closer than moving by h·v_new from the
                // sub-step's start implies; without this shift every rebound would start early
                // and rise (1 + e)·s too high. Only for an isolated pair: shifting a body that
                // touches others could push it into them.
                const bool isolated = (!a || a->contactCount == 1) && (!b || b->contactCount == 1);
                if (s > 0.0 && isolated && !p.shifted) {
                    p.shifted = true;
                    const Vec2 shift = (1.0 + c.restitution) * s * p.normalMass * c.normal;
                    shiftBody(a, p.anchorA, shift);
                    shiftBody(b, p.anchorB, -shift);
                }
            }
        }
        if (!any) break;
    }
}

bool ContactSolver::solveBlock(ContactConstraint& c, SolverBody* a, SolverBody* b,
                               const double bias[2], const double compliance[2]) {
    // The two points of a manifold solved together as a 2×2 linear complementarity problem,
    // as in Box2D 2.4's block solver, with the soft terms added: for each point the converged
    // soft constraint is v_n + bias + compliance·λ = 0 (λ ≥ 0, complementary). Solving the
    // points one after the other instead leaves an asymmetry that tips tall stacks over.
    ContactPoint& p1 = c.points[0];
    ContactPoint& p2 = c.points[1];
    const Vec2& n = c.normal;
    const double mA = a ? a->invMass : 0.0, iA = a ? a->invInertia : 0.0;
    const double mB = b ? b->invMass : 0.0, iB = b ? b->invInertia : 0.0;
    const double rn1A = cross(p1.anchorA, n), rn1B = cross(p1.anchorB, n);
    const double rn2A = cross(p2.anchorA, n), rn2B = cross(p2.anchorB, n);
    const double k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
    const double k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
    const double k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
    // Nearly coincident points make K singular: let the sequential solve handle them.
    if (k11 * k11 >= 1000.0 * (k11 * k22 - k12 * k12)) return false;
    const double a11 = k11 + compliance[0], a22 = k22 + compliance[1], a12 = k12;

    const double vn1 = n.dot(pointVelocity(b, p1.anchorB) - pointVelocity(a, p1.anchorA));
    const double vn2 = n.dot(pointVelocity(b, p2.anchorB) - pointVelocity(a, p2.anchorA));
    const double old1 = p1.normalImpulse, old2 = p2.normalImpulse;
    // w = v_n(λ = 0) + bias: the velocity the points would have without any normal impulse.
    const double w1 = vn1 - (k11 * old1 + k12 * old2) + bias[0];
    const double w2 = vn2 - (k12 * old1 + k22 * old2) + bias[1];

    double x1 = 0.0, x2 = 0.0;
    const double det = a11 * a22 - a12 * a12;
    x1 = (-w1 * a22 + w2 * a12) / det;
    x2 = (-w2 * a11 + w1 * a12) / det;
    if (!(x1 >= 0.0 && x2 >= 0.0)) {
        x1 = -w1 / a11;  // point 1 alone
        x2 = 0.0;
        if (!(x1 >= 0.0 && a12 * x1 + w2 >= 0.0)) {
            x1 = 0.0;  // point 2 alone
            x2 = -w2 / a22;
            if (!(x2 >= 0.0 && a12 * x2 + w1 >= 0.0)) {
                x2 = 0.0;  // neither
                if (!(w1 >= 0.0 && w2 >= 0.0)) return false;
            }
        }
    }
    const double d1 = x1 - old1, d2 = x2 - old2;
    applyImpulse(a, p1.anchorA, -d1 * n);
    applyImpulse(b, p1.anchorB, d1 * n);
    applyImpulse(a, p2.anchorA, -d2 * n);
    applyImpulse(b, p2.anchorB, d2 * n);
    p1.normalImpulse = x1;
    p2.normalImpulse = x2;
    return true;
}

void ContactSolver::solve(double h, bool useBias, const ContactSettings& settings) {
    const double invH = 1.0 / h;
    for (ContactConstraint& c : constraints_) {
        SolverBody* a = c.bodyA >= 0 ? &bodies_[c.bodyA] : nullptr;
        SolverBody* b = c.bodyB >= 0 ? &bodies_[c.bodyB] : nullptr;
        const Softness& soft = softness_[&c - constraints_.data()];
        // Per point: the bias velocity, and the soft parameters (a speculative point, or a
        // penetrating one during relax, is rigid).
        double bias[2] = {0.0, 0.0}, massScale[2] = {1.0, 1.0}, impulseScale[2] = {0.0, 0.0};
        double compliance[2] = {0.0, 0.0};
        bool active[2] = {true, true};
        for (int k = 0; k < c.pointCount; ++k) {
            const double s = c.points[k].separation;
            if (s > 0.0) {
                // Speculative: close at most the gap. Only while solving: relaxing a gap would
                // brake an approaching body a sub-step early (the next solve sees the gap anew).
                bias[k] = s * invH;
                active[k] = useBias;
            } else if (useBias) {
                bias[k] = std::max(soft.biasRate * s, -settings.pushOut);
                massScale[k] = soft.massScale;
                impulseScale[k] = soft.impulseScale;
                // Converged, the soft update −m·s·(v_n + b) − r·λ = 0 is v_n + b + (r/(s·m))·λ = 0.
                compliance[k] = soft.impulseScale / (soft.massScale * c.points[k].normalMass);
            }
        }
        const bool block = c.pointCount == 2 && active[0] && active[1];
        if (!block || !solveBlock(c, a, b, bias, compliance)) {
            for (int k = 0; k < c.pointCount; ++k) {
                if (!active[k]) continue;
                ContactPoint& p = c.points[k];
                const double vn = c.normal.dot(pointVelocity(b, p.anchorB) - pointVelocity(a, p.anchorA));
                double impulse = -p.normalMass * massScale[k] * (vn + bias[k]) -
                                 impulseScale[k] * p.normalImpulse;
                const double accumulated = std::max(p.normalImpulse + impulse, 0.0);
                impulse = accumulated - p.normalImpulse;
                p.normalImpulse = accumulated;
                applyImpulse(a, p.anchorA, -impulse * c.normal);
                applyImpulse(b, p.anchorB, impulse * c.normal);
            }
        }
        // Coulomb friction, each point bounded by its own normal impulse.
        const Vec2 t = tangentOf(c.normal);
        for (int k = 0; k < c.pointCount; ++k) {
            ContactPoint& p = c.points[k];
            const double vt = t.dot(pointVelocity(b, p.anchorB) - pointVelocity(a, p.anchorA));
            const double limit = c.friction * p.normalImpulse;
            double impulse = -p.tangentMass * vt;
            const double accumulated = std::clamp(p.tangentImpulse + impulse, -limit, limit);
            impulse = accumulated - p.tangentImpulse;
            p.tangentImpulse = accumulated;
            applyImpulse(a, p.anchorA, -impulse * t);
            applyImpulse(b, p.anchorB, impulse * t);
        }
    }
}

int ContactSolver::innerSubsteps(double h, const ContactSettings& settings) {
    if (settings.substeps > 0) return settings.substeps;
    // At least kInnerRate sub-steps per second whatever the frame: a soft contact's stiffness
    // is bounded by a quarter of the sub-step rate, and a stack sags by load/(m·ω²), so the
    // rate is what holds a tower. The world's own sub-steps count towards it.
    const int n = static_cast<int>(std::ceil(h * kInnerRate - 1e-9));
    return std::clamp(n, 1, kMaxInnerSubsteps);
}

void ContactSolver::solveStep(double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                              const ContactSettings& settings, double positionWeight) {
    if (constraints_.empty()) return;
    const int n = innerSubsteps(h, settings);
    const double hi = h / n;
    // Each contact's softness for the inner sub-step (its stiffness multiplier: see prepare()).
    const double hertz = std::min(settings.hertz, 0.25 / hi);
    softness_.resize(constraints_.size());
    for (std::size_t i = 0; i < constraints_.size(); ++i)
        softness_[i] = makeSoft(constraints_[i].stiffness * hertz, settings.dampingRatio, hi);
    // The smooth step's velocity change is spread evenly over the inner sub-steps (the
    // smooth forces held constant over the step); its position change is the integrator's, and
    // the solver adds to it only what the contact impulses change.
    loadBodies(q0, u0, u);
    for (int i = 1; i <= n; ++i) {
        const double f = double(i) / n;
        for (SolverBody& b : bodies_) {
            b.v += b.smoothDv / n;
            b.w += b.smoothDw / n;
            b.pushV = b.v;  // before the bounces
            b.pushW = b.w;
        }
        updateSeparations();
        bounce(hi, settings);
        for (SolverBody& b : bodies_) {
            b.bounceDv += b.v - b.pushV;
            b.bounceDw += b.w - b.pushW;
        }
        updateSeparations();
        warmStart();
        for (int it = 0; it < settings.iterations; ++it) solve(hi, true, settings);
        for (SolverBody& b : bodies_) {
            // Contact-induced velocity, bounces included: what the impulses added to the
            // smooth path, which the integrator's positions do not know of.
            b.shift += hi * (b.v - (b.v0 + f * b.smoothDv));
            b.path += hi * b.v;
            if (b.rotates) {
                b.angleShift += hi * (b.w - (b.w0 + f * b.smoothDw));
                b.anglePath += hi * b.w;
            }
            b.pushV = b.v;
            b.pushW = b.w;
        }
        updateSeparations();
        for (int it = 0; it < settings.relaxIterations; ++it) solve(hi, false, settings);
        for (SolverBody& b : bodies_) {
            // What relax removed is the push-out's velocity: its displacement is the position
            // correction (the energy ledger's `correction`).
            b.pushOut += hi * (b.pushV - b.v);
            if (b.rotates) b.pushOutAngle += hi * (b.pushW - b.w);
        }
    }

    // A force held over the step moves a body by positionWeight·h·Δv under the user's method;
    // inner sub-stepping moved it by (n + 1)/(2n)·h·Δv. Moving it by the difference keeps a
    // resting body still whatever the integrator (the push-out, removed from the velocity by
    // relax, keeps its whole displacement: that is its purpose; a bounce acts at the instant
    // of impact, not as a force over the step).
    const double excess = positionWeight - (n + 1.0) / (2.0 * n);
    for (SolverBody& b : bodies_) {
        const Vec2 dv = b.v - (b.v0 + b.smoothDv + b.bounceDv);
        q.segment<2>(b.dof) += b.shift + excess * h * dv + b.timeShift;
        u.segment<2>(b.dof) = b.v;
        if (b.rotates) {
            const double dw = b.w - (b.w0 + b.smoothDw + b.bounceDw);
            q[b.dof + 2] += b.angleShift + excess * h * dw + b.angleTimeShift;
            u[b.dof + 2] = b.w;
        }
    }
}

void ContactSolver::addPushOut(Vec& q, double scale) const {
    for (const SolverBody& b : bodies_) {
        q.segment<2>(b.dof) += scale * b.pushOut;
        if (b.rotates) q[b.dof + 2] += scale * b.pushOutAngle;
    }
}

}  // namespace phasebox
