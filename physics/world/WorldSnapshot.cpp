#include "physics/world/WorldSnapshot.h"

namespace phasebox {

namespace {

std::size_t vectorBytes(const Vec& v) {
    return static_cast<std::size_t>(v.size()) * sizeof(double);
}

// Whether the world has the bodies sleepers names.
bool holdsSleepers(const World& world, const std::shared_ptr<const Sleepers>& sleepers) {
    if (!sleepers) return true;
    for (const Sleepers::Body& b : sleepers->bodies) {
        const std::size_t count = b.rigid ? world.rigidBodies().size() : world.particles().size();
        if (b.index < 0 || static_cast<std::size_t>(b.index) >= count) return false;
    }
    return true;
}

bool sameSettings(const SimulationSettings& a, const SimulationSettings& b) {
    return a.integrator == b.integrator && a.dt == b.dt && a.substeps == b.substeps &&
           a.tolerance == b.tolerance && a.newtonIterations == b.newtonIterations &&
           a.contactModel == b.contactModel && a.contactStiffness == b.contactStiffness &&
           a.contactDamping == b.contactDamping && a.contacts.substeps == b.contacts.substeps &&
           a.contacts.iterations == b.contacts.iterations &&
           a.contacts.relaxIterations == b.contacts.relaxIterations &&
           a.contacts.hertz == b.contacts.hertz &&
           a.contacts.dampingRatio == b.contacts.dampingRatio &&
           a.contacts.pushOut == b.contacts.pushOut &&
           a.contacts.restitutionThreshold == b.contacts.restitutionThreshold &&
           a.contacts.speculativeDistance == b.contacts.speculativeDistance &&
           a.contacts.keepStillContacts == b.contacts.keepStillContacts;
}

}  // namespace

FrameState FrameState::of(const World& world) {
    FrameState f;
    f.q = world.positions();
    f.u = world.velocities();
    f.time = world.time();
    f.stepCount = world.stepCount();
    f.ledger = world.energy();
    world.contactForces(f.forces);
    if (world.jointSolver()) {
        const int count = static_cast<int>(world.joints().size());
        f.forces.joints.resize(static_cast<std::size_t>(count));
        for (int j = 0; j < count; ++j)
            f.forces.joints[static_cast<std::size_t>(j)] = {
                world.jointForce(j), world.jointForceOn(j, false), world.jointForceOn(j, true)};
    }
    f.sleepers = world.sleepers();
    return f;
}

bool WorldSnapshot::show(World& world, const FrameState& frame) {
    if (world.layoutDirty_ || frame.u.size() != frame.q.size() ||
        !holdsSleepers(world, frame.sleepers))
        return false;
    // The layout of the frame's sleepers first: the frame's q and u are of it.
    world.putToSleep(frame.sleepers);
    if (world.layout_.dimension() != frame.q.size()) return false;
    world.q_[world.current_] = frame.q;
    world.u_[world.current_] = frame.u;
    world.clock_.time = frame.time;
    world.clock_.stepCount = frame.stepCount;
    world.ledger_ = frame.ledger;
    world.shownForces_ = frame.forces;
    world.showingFrame_ = true;
    return true;
}

WorldSnapshot::WorldSnapshot() = default;
WorldSnapshot::~WorldSnapshot() = default;
WorldSnapshot::WorldSnapshot(WorldSnapshot&&) noexcept = default;
WorldSnapshot& WorldSnapshot::operator=(WorldSnapshot&&) noexcept = default;

WorldSnapshot WorldSnapshot::take(const World& world) {
    WorldSnapshot s;
    s.dimension_ = world.layout_.dimension();
    s.settings_ = world.settings_;
    for (int b = 0; b < 2; ++b) {
        s.q_[b] = world.q_[b];
        s.u_[b] = world.u_[b];
    }
    s.current_ = world.current_;
    s.force_ = world.force_;
    s.clock_ = world.clock_;
    s.forceEvaluations_ = world.forceEvaluations_;
    s.ledger_ = world.ledger_;
    s.guard_ = world.guard_;
    s.divergence_ = world.divergence_;
    if (world.contacts_) s.contacts_ = std::make_unique<ContactStage>(*world.contacts_);
    if (world.joints_) s.joints_ = std::make_unique<JointSolver>(*world.joints_);
    s.penaltyVelocity_ = world.penaltyVelocity_;
    s.kinematicImpulse_ = world.kinematicImpulse_;
    s.heldForce_ = world.heldForce_;
    s.unappliedJointForce_ = world.unappliedJointForce_;
    s.heldWork_ = world.heldWork_;
    s.holding_ = world.holding_;
    s.heldValid_ = world.heldValid_;
    s.penaltyPairsStale_ = world.penaltyPairsStale_;
    s.jointSubsteps_ = world.jointSubsteps_;
    s.jointSubstepsSince_ = world.jointSubstepsSince_;
    s.pulledSubsteps_ = world.pulledSubsteps_;
    s.pulledPeak_ = world.pulledPeak_;
    s.pulledSince_ = world.pulledSince_;
    s.integratorCarried_ = world.integrator_->carriedState();
    s.integratorStats_ = world.integrator_->stats();
    s.particles_ = world.bodies_.particles.size();
    s.rigidBodies_ = world.bodies_.rigidBodies.size();
    s.sleepers_ = world.sleepers_;
    if (world.settings_.sleep) {
        s.restingSeconds_ = world.restingSeconds_;
        s.sleepingIsland_ = world.sleepingIsland_;
    }
    s.nextIsland_ = world.nextIsland_;
    // The contact stage and the joints' solver are estimated, not walked: the contact stage
    // keeps its constraints several times over (this step's, the previous step's for warm
    // starting, a sorted copy, the solver's own), and per collider a few records of about a
    // state's size; the joints' solver its rows and factorisation, a few states' worth.
    const std::size_t perState = vectorBytes(world.q_[0]);
    const std::size_t constraints =
        s.contacts_ ? s.contacts_->contacts().size() * sizeof(ContactConstraint) : 0;
    s.bytes_ = sizeof(WorldSnapshot) + 6 * perState + vectorBytes(s.penaltyVelocity_) +
               vectorBytes(s.kinematicImpulse_) + vectorBytes(s.heldForce_) +
               vectorBytes(s.unappliedJointForce_) +
               (s.contacts_ ? sizeof(ContactStage) + 4 * constraints + 24 * perState : 0) +
               (s.joints_ ? sizeof(JointSolver) + 8 * perState : 0) +
               (s.sleepers_ ? s.sleepers_->bytes() : 0) +
               s.restingSeconds_.size() * (sizeof(double) + sizeof(int));
    return s;
}

bool WorldSnapshot::hasSettingsOf(const World& world) const {
    return sameSettings(world.settings(), settings_);
}

bool WorldSnapshot::restoreInto(World& world) const {
    if (world.layoutDirty_ || world.bodies_.particles.size() != particles_ ||
        world.bodies_.rigidBodies.size() != rigidBodies_ ||
        (world.contacts_ != nullptr) != (contacts_ != nullptr) ||
        (world.joints_ != nullptr) != (joints_ != nullptr))
        return false;
    // Without a sleeper on either side the layouts must match as they are; otherwise the
    // layout is rebuilt around the snapshot's sleepers, and must then match.
    if (!sleepers_ && !world.sleepers_ && world.layout_.dimension() != dimension_) return false;
    // Switching back to the saved settings rebuilds the method (and the contact model's
    // parameters); what they carry is put back below. A switch wakes every island: the
    // sleepers are put back after it.
    if (!sameSettings(world.settings_, settings_) || world.settings_.sleep != settings_.sleep)
        world.setSettings(settings_);
    world.putToSleep(sleepers_);
    if (world.layout_.dimension() != dimension_) return false;
    const std::size_t bodies = particles_ + rigidBodies_;
    world.restingSeconds_ = restingSeconds_;
    world.sleepingIsland_ = sleepingIsland_;
    world.restingSeconds_.resize(bodies, 0.0);
    world.sleepingIsland_.resize(bodies, -1);
    world.nextIsland_ = nextIsland_;
    for (int b = 0; b < 2; ++b) {
        world.q_[b] = q_[b];
        world.u_[b] = u_[b];
    }
    world.current_ = current_;
    world.force_ = force_;
    world.clock_ = clock_;
    world.forceEvaluations_ = forceEvaluations_;
    world.ledger_ = ledger_;
    world.guard_ = guard_;
    world.divergence_ = divergence_;
    if (contacts_) *world.contacts_ = *contacts_;
    if (joints_) *world.joints_ = *joints_;
    world.penaltyVelocity_ = penaltyVelocity_;
    world.kinematicImpulse_ = kinematicImpulse_;
    world.heldForce_ = heldForce_;
    world.unappliedJointForce_ = unappliedJointForce_;
    world.heldWork_ = heldWork_;
    world.holding_ = holding_;
    world.heldValid_ = heldValid_;
    world.penaltyPairsStale_ = penaltyPairsStale_;
    world.jointSubsteps_ = jointSubsteps_;
    world.jointSubstepsSince_ = jointSubstepsSince_;
    world.pulledSubsteps_ = pulledSubsteps_;
    world.pulledPeak_ = pulledPeak_;
    world.pulledSince_ = pulledSince_;
    world.integrator_->restoreCarriedState(integratorCarried_);
    world.integrator_->restoreStats(integratorStats_);
    world.showingFrame_ = false;
    return true;
}

}  // namespace phasebox
