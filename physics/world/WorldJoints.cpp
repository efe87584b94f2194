// The world's joint stages (CONTRACT §6): how many sub-steps the joints need in a frame, the
// joints completing the integrator's step, and the joints put back onto what the contacts
// moved, each with its energy booked. The solver itself is physics/joints/JointSolver.
#include "physics/contacts/ContactStage.h"
#include "physics/integrators/Integrator.h"
#include "physics/joints/JointSolver.h"
#include "physics/world/World.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace phasebox {

namespace {
// Seconds a joint sub-step count is held after the need for it has passed
// (jointSubstepsForFrame()).
constexpr double kJointSubstepHold = 2.0;
// The share of an explicit method's stability bound on ω·h that the joints' fastest mode may
// use (jointSubstepsForFrame()).
constexpr double kJointStabilityShare = 0.5;
// And for the sub-steps of the methods that meet that mode explicitly, ω estimated from the
// joints' geometric stiffness alone: the estimate leaves out how the constraint forces change
// with the configuration. At half the bound, 1000 kg on 20 hinged links pushed at 5 m/s
// diverged under velocity Verlet at 28 s (5000 kg at 16 s) and 5000 kg under implicit
// midpoint in its fourth step; at a quarter, both weights held over 30 s under velocity
// Verlet, RK4 and implicit midpoint, their drift within 9 J (jointSubstepsForFrame()).
constexpr double kPulledStabilityShare = 0.25;
// A jammed body's inverse mass in the joints' position correction after the contacts (rejoin()).
constexpr double kJammedInverseMassShare = 0.01;
// The joints as the contacts' joined relax sees them (rejoin()).
class JointTangent final : public TangentProjection {
public:
    JointTangent(JointSolver& joints, const Vec& invMass) : joints_(joints), invMass_(invMass) {}
    void project(Vec& x) const override { joints_.projectChange(x, invMass_); }

private:
    JointSolver& joints_;
    const Vec& invMass_;
};
}  // namespace

int World::jointSubstepsForFrame() {
    // The joints take sub-steps of their own, chosen from the frame's start (the user's dt
    // stays what it is), for two needs, and the larger count wins.
    const double h = settings_.dt / settings_.substeps;
    const Vec& q = q_[current_];
    const Vec& u = u_[current_];

    // 1. Joints that turn fast (a chain's whip): SHAKE's directions of the step's start must
    // not turn far. A count goes up at once; down at once only to less than half of it (a whip
    // calming down), otherwise after kJointSubstepHold seconds without need: a swing that needs
    // two near the bottom and one elsewhere would change its step twice a swing, and a
    // symplectic method with a changing step loses its energy (a pendulum at 90° that needs
    // two at its bottom, under symplectic Euler, kept 70% of it after 30 s and swung 5% short;
    // tst_joints jointSubstepsDoNotDrainAShortPendulum).
    const int turning = joints_->substepsFor(h, q, u);
    // Contacts already make the step non-smooth: there the count follows the need.
    const bool smooth = !contacts_ || !contacts_->touching();
    if (!smooth || turning >= jointSubsteps_ || 2 * turning < jointSubsteps_ ||
        (jointSubstepsSince_ += settings_.dt) > kJointSubstepHold) {
        jointSubsteps_ = turning;
        jointSubstepsSince_ = 0.0;
    }

    // 2. Joints pulled hard (a heavy weight on a light chain, a whip's root): an explicit method
    // is stable only while ω·h stays below its bound, for ω the fastest mode the joints' forces
    // make (JointSolver::geometricFrequency). kPulledStabilityShare of the bound leaves room for
    // the force to grow within the frame and for what the estimate leaves out; a method that
    // gains energy at any step (bound 0) gets ω·h ≤ kPulledStabilityShare. The implicit methods'
    // Newton iterations see the forces' Jacobians but not this stiffness, which they meet
    // explicitly, as symplectic Euler does (bound 2: without it a 1000 kg weight on 20 links broke
    // implicit Euler within 1.3 s); the adaptive methods choose their own steps (bound ∞) and need
    // none. This count goes up at once and down only to the most the last kJointSubstepHold seconds
    // needed: a tension that swings with a pendulum would otherwise change the step every swing.
    const IntegratorInfo& info = integrator_->info();
    const double bound = info.implicit && !info.adaptive ? 2.0 : info.stabilityBound;
    // A method whose step ends x' = x + h·v' takes the hinges' and welds' share implicitly
    // instead (JointSolver::setImplicitStiffness): w = (ω·h)² up to the same share of its bound.
    const double share = kJointStabilityShare * bound;
    joints_->setImplicitStiffness(info.positionWeight == 1.0 && std::isfinite(bound) ? share * share
                                                                                     : 0.0);
    int pulled = 1;
    if (std::isfinite(bound)) {
        if (!joints_->forcesKnown()) {
            // The first frame: the joints' forces at the start, from one evaluation (not
            // counted as one of the method's).
            double power = 0.0;
            if (!addAccelerations(clock_.time, q, u, jointScratch_, fieldEffects_, power))
                jointScratch_.setZero();
            joints_->constrainAccelerations(q, u, invMass_, jointScratch_);
        }
        const double limit = kPulledStabilityShare * (bound > 0.0 ? bound : 1.0);
        pulled = JointSolver::substepCount(
            std::ceil(h * joints_->geometricFrequency(q, invMass_) / limit));
    }
    if (pulled >= pulledSubsteps_) {
        pulledSubsteps_ = pulled;
        pulledSince_ = 0.0;
        pulledPeak_ = 1;
    } else {
        pulledPeak_ = std::max(pulledPeak_, pulled);
        if ((pulledSince_ += settings_.dt) > kJointSubstepHold) {
            pulledSubsteps_ = pulledPeak_;
            pulledSince_ = 0.0;
            pulledPeak_ = 1;
        }
    }
    return std::max(jointSubsteps_, pulledSubsteps_);
}

void World::solveJoints(double h, int next) {
    // Straight after the integrator. The booking (CONTRACT §6): SHAKE (along the directions of
    // the step's start, or of its end where those do not converge, velocities moved with the
    // positions, on the scaled inertia of setImplicitStiffness) and the velocities' projection
    // onto the tangent are the discrete constraint forces of the method, so what they change
    // is the method's own (it stays in drift); moving positions further (what
    // SHAKE could not reach, inequalities past their bounds) is error correction; an inequality
    // catching a body takes energy out like an inelastic contact (work_nc) and never puts it in
    // (correction); a motor's push is work.
    Vec& q = q_[next];
    Vec& u = u_[next];
    const bool shaken = joints_->shake(h, q_[current_], u_[current_], q, u, invMass_,
                                       integrator_->info().constraintsAtEnd);
    const double beforeCorrection = mechanicalEnergy(q, u);
    double afterCorrection = beforeCorrection;
    // A converged SHAKE has left the equalities on C = 0: only inequalities can remain.
    if (!shaken || joints_->hasInequalities()) {
        joints_->correctPositions(q, u, invMass_);
        afterCorrection = mechanicalEnergy(q, u);
    }
    const bool caught = joints_->projectVelocities(q, u, joints_->shakeWeights(invMass_));
    const double projected = caught ? mechanicalEnergy(q, u) : afterCorrection;
    // Every method's step but backward Euler's had the motors' held torques in it
    // (holdMotorTorques()).
    const double motorWork =
        joints_->driveMotors(h, q, u, mass_, invMass_, !integrator_->info().constraintsAtEnd);
    if (!std::isfinite(projected) || !std::isfinite(motorWork)) return;  // the guard reports it
    ledger_.correction += afterCorrection - beforeCorrection;
    const double catchEnergy = projected - afterCorrection;
    ledger_.workNc += std::min(catchEnergy, 0.0) + motorWork;
    ledger_.correction += std::max(catchEnergy, 0.0);
}

void World::rejoin(int next) {
    // After the contacts: the joints back onto what the contacts moved (positions, then
    // velocities), then one solve of both: the contacts' relax rows with the joint rows
    // eliminated (ContactSolver::relaxJoined), so that a wheel on the ground is held up by the
    // contact and to the car by the hinge at once. step() books the net of contacts and joints.
    Vec& q = q_[next];
    Vec& u = u_[next];
    // A body jammed into static geometry (ContactSolver::jammedWeights) weighs
    // 1/kJammedInverseMassShare times its mass here: the joints bring the rest of the body to
    // where the push-out moved it, instead of pulling it back in, where the next step's method
    // put it again. Before, a ragdoll's shin went 2.7 cm in and out of a stair's corner every
    // step, the deep overlap's force was never held and the doll fell freely in each method
    // step: 0.45 J of correction a step, lying still (docs/robustness.md).
    const Vec* weights = &invMass_;
    if (contacts_->solver().jammedWeights(invMass_, kJammedInverseMassShare, rejoinWeights_)) {
        joints_->weightsChanged(rejoinWeights_);
        weights = &rejoinWeights_;
    }
    joints_->correctPositions(q, u, *weights);
    joints_->projectVelocities(q, u, invMass_);
    if (!contacts_->touching()) return;
    contacts_->relaxJoined(u, JointTangent(*joints_, invMass_));
    contacts_->keepImpulses();
}

JointErrors World::jointErrors() const {
    return joints_ && !layoutDirty_ ? joints_->errors(q_[current_]) : JointErrors{};
}

double World::jointForce(int j) const {
    if (showingFrame_)
        return j >= 0 && j < static_cast<int>(shownForces_.joints.size())
                   ? shownForces_.joints[static_cast<std::size_t>(j)].magnitude
                   : 0.0;
    return joints_ && j >= 0 && j < static_cast<int>(joints().size()) ? joints_->force(j) : 0.0;
}

Vec2 World::jointForceOn(int j, bool onB) const {
    if (showingFrame_) {
        if (j < 0 || j >= static_cast<int>(shownForces_.joints.size())) return Vec2::Zero();
        const FrameForces::Joint& f = shownForces_.joints[static_cast<std::size_t>(j)];
        return onB ? f.onB : f.onA;
    }
    if (!joints_ || j < 0 || j >= static_cast<int>(joints().size())) return Vec2::Zero();
    return onB ? joints_->forceOnB(j) : joints_->forceOnA(j);
}

void World::nameStraightChain(Divergence& d) const {
    // A chain: hinges and rods end to end, each body between two of them holding exactly those
    // two, from a fixed point (the world, a static or pinned body) to another. Pulled straight,
    // the path through its joints' points is as long as the line between its ends: it has no
    // slack to sag with, and gravity or any load across it asks an unbounded force of it as it
    // moves (held still, some methods at a small enough step keep it straight).
    if (!joints_) return;
    const std::vector<Joint>& joints = bodies_.joints;
    const auto linking = [&](const Joint& j) {
        return j.type == Joint::Type::Hinge || j.type == Joint::Type::Rod;
    };
    const auto fixed = [&](const JointBody& e) {
        switch (e.kind) {
            case JointBody::Kind::World:
                return true;
            case JointBody::Kind::Rigid:
                return bodies_.rigidBodies[static_cast<std::size_t>(e.index)].dof < 0;
            case JointBody::Kind::Particle:
                break;
        }
        return bodies_.particles[static_cast<std::size_t>(e.index)].dof < 0;
    };
    const auto same = [](const JointBody& a, const JointBody& b) {
        return a.kind == b.kind && a.index == b.index;
    };
    // Per body (particles first, then rigid bodies) how many linking joints hold it and the
    // first two of them: once, so that a chain of n links is walked in O(n).
    const std::size_t particleCount = bodies_.particles.size();
    const auto slot = [&](const JointBody& e) {
        return e.kind == JointBody::Kind::Rigid ? particleCount + static_cast<std::size_t>(e.index)
                                                : static_cast<std::size_t>(e.index);
    };
    const int count = static_cast<int>(joints.size());
    std::vector<int> held(particleCount + bodies_.rigidBodies.size(), 0);
    std::vector<std::array<int, 2>> links(held.size(), {-1, -1});
    for (int k = 0; k < count; ++k) {
        const Joint& j = joints[static_cast<std::size_t>(k)];
        if (!linking(j)) continue;
        for (const JointBody* e : {&j.a, &j.b}) {
            if (fixed(*e)) continue;
            const std::size_t i = slot(*e);
            if (held[i] < 2) links[i][static_cast<std::size_t>(held[i])] = k;
            ++held[i];
        }
    }
    // Straight when the path's length exceeds the distance between its ends by less than this
    // share: a chain hung with a sag of a hundredth of its span is longer by about 3e-4.
    constexpr double kTaut = 1e-5;
    const Vec& q = q_[current_];
    for (int first = 0; first < count; ++first) {
        const Joint& start = joints[static_cast<std::size_t>(first)];
        if (!linking(start) || fixed(start.a) == fixed(start.b)) continue;
        // Walk from the fixed end along bodies that hold exactly two linking joints.
        bool fromA = fixed(start.a);
        JointBody body = fromA ? start.b : start.a;
        std::vector<Vec2> points{fromA ? joints_->pointA(first, q) : joints_->pointB(first, q),
                                 fromA ? joints_->pointB(first, q) : joints_->pointA(first, q)};
        int previous = first, last = -1, bodies = 1;
        for (int walked = 0; walked < count && last < 0; ++walked) {
            const std::size_t i = slot(body);
            if (held[i] != 2) break;
            const int next = links[i][0] == previous ? links[i][1] : links[i][0];
            const Joint& j = joints[static_cast<std::size_t>(next)];
            fromA = same(j.a, body);
            points.push_back(fromA ? joints_->pointA(next, q) : joints_->pointB(next, q));
            points.push_back(fromA ? joints_->pointB(next, q) : joints_->pointA(next, q));
            body = fromA ? j.b : j.a;
            previous = next;
            if (fixed(body))
                last = next;
            else
                ++bodies;
        }
        // Only the walk that starts at the lower joint index reports a chain (each is walked
        // from both ends); a single body pinned at two points is merely held twice.
        if (last < 0 || last < first || bodies < 2) continue;
        double length = 0.0;
        for (std::size_t i = 1; i < points.size(); ++i)
            length += (points[i] - points[i - 1]).norm();
        const double span = (points.back() - points.front()).norm();
        if (!(span > 0.0) || !(length <= span * (1.0 + kTaut))) continue;
        d.straightFrom = start.id;
        d.straightTo = joints[static_cast<std::size_t>(last)].id;
        return;
    }
}

}  // namespace phasebox
