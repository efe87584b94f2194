// The contact forces held over the method's step (CONTRACT §3: contacts act inside it): each
// point's force from the last solve, the bound that keeps impacts out, the forces as the world
// adds them to every evaluation, and their share of the smooth step as the solver takes it.
#include "physics/contacts/ContactChunks.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace phasebox {

Vec2 ContactSolver::forceOf(const ContactPoint& p, double perSubstep, double perStep) {
    // The solve's impulses act once per inner sub-step, what relaxJoined() added after it
    // (the joints' rounds) once per step.
    return {perSubstep * p.solvedNormal + perStep * (p.normalImpulse - p.solvedNormal),
            perSubstep * p.solvedTangent + perStep * (p.tangentImpulse - p.solvedTangent)};
}

void ContactSolver::primeHeld() {
    // Only where a body was placed touching (within a hundredth of the deep overlap): a force
    // that pushes bodies started inside each other apart is the push-out's, not a support's.
    if (!(lastInnerH_ > 0.0) || !(lastStepH_ > 0.0)) return;
    const double perSubstep = 1.0 / lastInnerH_, perStep = 1.0 / lastStepH_;
    for (ContactConstraint& c : constraints_)
        for (int k = 0; k < c.pointCount; ++k) {
            ContactPoint& p = c.points[k];
            const bool placed = p.baseSeparation >= -0.01 * c.deepOverlap;
            const Vec2 force = placed ? forceOf(p, perSubstep, perStep) : Vec2::Zero();
            if (!placed)  // nor does the trial warm-start them: the step meets them afresh
                p.normalImpulse = p.tangentImpulse = p.solvedNormal = p.solvedTangent = 0.0;
            p.lastNormal = static_cast<float>(force.x());
            p.lastTangent = static_cast<float>(force.y());
        }
    refreshHeld();
}

void ContactSolver::refreshHeld() {
    // A resting contact's force is the same step after step; an impact's is there in one step
    // only (a body caught in the last inner sub-step). Held over the next step as the lesser of
    // the last two, an impact is never held: the solver meets it as before, from the smooth
    // step alone, and the force held is what the contact has shown it keeps up. Nor is an
    // overlap deeper than a resting stack's (bodies started inside each other): its force is
    // the push-out's, which acts on positions only.
    // Where two bodies that joints hold touch (a ragdoll's torso on its forearm, a chain heaped
    // on itself), the force is held too: left to the solve after the step, the bodies fell
    // into each other in every method's step while their other contacts' held forces pushed
    // them apart, the joints caught the difference and the solve put it back, a lying ragdoll
    // booking about 1 J of correction and −1 J of work_nc a step (docs/robustness.md). Its
    // overlap may be deeper than the deep-overlap bound (the joints hold a limb there, at its
    // stop), and it is held there too, as is a jointed body's deep point on anything else: a
    // lying doll's shin 13.7 mm into the floor held nothing there, its leg fell about the hip
    // in every method step and rejoin lifted the thigh 7.6 mm back onto the knee, 25 J of
    // correction a second under symplectic Euler (docs/robustness.md). But where the joints
    // close a loop through the contact (a link pressed between its neighbours' neighbours), the
    // force they balance has no bound of its own: it grew by a tenth a step, a 1 kg link's
    // contact reached 900 N and the heap diverged. It is held up to kJointedHoldWeights times
    // the two bodies' weight.
    // A point of a jointed body that the frame's collide found open (kHeldOpenShare) holds
    // nothing: the force held over the method's step had pushed the body off it. Held again,
    // that force fed itself: the joints pulled the body back, the solve caught it harder, and
    // the larger force was held. A 2 kg forearm off a stair of the ragdoll example was held at
    // 1,400 N and then 4,400 N over three frames, spun at 32 and then 40 rad/s in the method's
    // steps, and the fall booked 1,100 J of correction (docs/robustness.md). A free body pushed
    // off leaves its contact, whose force then falls to nothing; a body that joints hold is
    // brought back.
    if (!(lastInnerH_ > 0.0) || !(lastStepH_ > 0.0)) return;
    const double perSubstep = 1.0 / lastInnerH_, perStep = 1.0 / lastStepH_;
    forChunks(constraints_.size(), kRowGrain, [&](std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i) holdConstraint(i, perSubstep, perStep);
    });
}

void ContactSolver::holdConstraint(std::size_t i, double perSubstep, double perStep) {
    ContactConstraint& c = constraints_[i];
    const bool jointedA = c.bodyA >= 0 && bodies_[c.bodyA].jointed;
    const bool jointedB = c.bodyB >= 0 && bodies_[c.bodyB].jointed;
    const bool jointed = jointedA && jointedB;  // both: the force's bound below
    const bool holdsJointed = jointedA || jointedB;
    const double most = jointed ? kJointedHoldWeights * weightField_ *
                                      (bodies_[c.bodyA].mass + bodies_[c.bodyB].mass)
                                : std::numeric_limits<double>::infinity();
    for (int k = 0; k < c.pointCount; ++k) {
        ContactPoint& p = c.points[k];
        p.heldNormal = p.heldTangent = 0.0;
        // Where the solver's path has left it (separation_ is of these rows).
        if (!holdsJointed && separationOf(i, k) < -c.deepOverlap) continue;
        // Where the frame's collide found it, after the method's step.
        if (holdsJointed && p.baseSeparation > kHeldOpenShare * c.deepOverlap) continue;
        const Vec2 force = forceOf(p, perSubstep, perStep);
        p.heldNormal =
            std::min(std::clamp(force.x(), 0.0, std::max(double(p.lastNormal), 0.0)), most);
        if (force.y() * p.lastTangent > 0.0)
            p.heldTangent = std::copysign(
                std::min({std::abs(force.y()), std::abs(double(p.lastTangent)), most}), force.y());
    }
}

namespace {
// Calls apply(body, sign, f, arm) for each side of each contact point that holds a force: the
// solver body's index, −1 for body A and +1 for body B, the point's held force f (on B) and the
// body's lever arm to the point. Returns whether any point holds one.
template <class Apply>
bool forEachHeldForce(const ConstraintList& constraints, Apply&& apply) {
    bool any = false;
    for (const ContactConstraint& c : constraints) {
        const Vec2 t = tangentOf(c.normal);
        for (int k = 0; k < c.pointCount; ++k) {
            const ContactPoint& p = c.points[k];
            if (p.heldNormal == 0.0 && p.heldTangent == 0.0) continue;
            any = true;
            const Vec2 f = p.heldNormal * c.normal + p.heldTangent * t;
            if (c.bodyA >= 0) apply(c.bodyA, -1.0, f, p.anchorA);
            if (c.bodyB >= 0) apply(c.bodyB, 1.0, f, p.anchorB);
        }
    }
    return any;
}
}  // namespace

bool ContactSolver::addHeldForces(Vec& force) const {
    // In scalars: as Eigen's segments this walk (twice a step) took a tenth of a pyramid's
    // contact solve beyond the solve itself.
    double* out = force.data();
    return forEachHeldForce(constraints_,
                            [&](int body, double sign, const Vec2& f, const Vec2& arm) {
                                const SolverBody& b = bodies_[body];
                                const double fx = sign * f.x(), fy = sign * f.y();
                                out[b.dof] += fx;
                                out[b.dof + 1] += fy;
                                if (b.rotates) out[b.dof + 2] += arm.x() * fy - arm.y() * fx;
                            });
}

void ContactSolver::holdBodies(double h) {
    for (SolverBody& b : bodies_) {
        b.heldDv = Vec2::Zero();
        b.heldDw = 0.0;
    }
    if (!holding_) return;
    forEachHeldForce(constraints_, [&](int body, double sign, const Vec2& f, const Vec2& arm) {
        SolverBody& b = bodies_[body];
        const Vec2 impulse = h * f;
        b.heldDv += sign * (b.invMass * impulse);
        b.heldDw += sign * (b.invInertia * cross(arm, impulse));
    });
}

}  // namespace phasebox
