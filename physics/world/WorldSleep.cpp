// Sleeping (simulation.sleep, CONTRACT §6): islands at rest leave the state until something
// wakes them. A body asleep is out of the flat state like a static body, so the method, the
// effects, the contact solve and the joint solver never see it (a joint between two fixed ends
// leaves the joint solver's system, JointSolver::bind): it costs nothing, as an absent effect
// does. Its
// record keeps its position and velocity, and the ledger keeps its energy as a constant, so it
// wakes exactly as it fell asleep and nothing is booked for it.
//
// Rejected: zeroing the velocities of an island that falls asleep (Box2D's way). The energy it
// removes is neither physical work nor the method's error, and the ledger would have to hide it.
#include "physics/contacts/ContactStage.h"
#include "physics/effects/SpringEffect.h"
#include "physics/world/World.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace phasebox {

void World::resetSleep() {
    for (Particle& p : bodies_.particles) p.asleep = false;
    for (RigidBody& b : bodies_.rigidBodies) b.asleep = false;
    const std::size_t count = bodies_.particles.size() + bodies_.rigidBodies.size();
    restingSeconds_.assign(count, 0.0);
    sleepingIsland_.assign(count, -1);
    islandRest_.assign(count, 0.0);
    islandHeld_.assign(count, 0);
    islandId_.assign(count, -1);
    islands_.reset(static_cast<int>(count));
    sleepingBodies_ = 0;
    sleepingKinetic_ = sleepingPotential_ = 0.0;
    sleepers_.reset();
}

void World::wakeAll() {
    if (sleepingBodies_ == 0) return;
    if (layoutDirty_) {  // the edit's commit wakes them
        resetSleep();
        return;
    }
    const int particles = static_cast<int>(bodies_.particles.size());
    for (int i = 0; i < static_cast<int>(sleepingIsland_.size()); ++i) {
        if (sleepingIsland_[i] < 0) continue;
        sleepingIsland_[i] = -1;
        restingSeconds_[i] = 0.0;
        (i < particles ? bodies_.particles[i].asleep : bodies_.rigidBodies[i - particles].asleep) =
            false;
    }
    relayoutForSleep();
}

bool World::wakeBody(bool rigid, int index) {
    const int body = rigid ? static_cast<int>(bodies_.particles.size()) + index : index;
    if (body < 0 || body >= static_cast<int>(sleepingIsland_.size())) return false;
    if (!wakeIsland(sleepingIsland_[body])) return false;
    relayoutForSleep();
    return true;
}

bool World::wakeIsland(int island) {
    if (island < 0) return false;
    const int particles = static_cast<int>(bodies_.particles.size());
    bool woke = false;
    for (int i = 0; i < static_cast<int>(sleepingIsland_.size()); ++i) {
        if (sleepingIsland_[i] != island) continue;
        sleepingIsland_[i] = -1;
        restingSeconds_[i] = 0.0;
        (i < particles ? bodies_.particles[i].asleep : bodies_.rigidBodies[i - particles].asleep) =
            false;
        woke = true;
    }
    return woke;
}

// After a good step: sleepers an awake body reached wake, every awake body's time at rest
// grows or restarts, and islands whose every body has rested long enough fall asleep.
void World::updateSleep() {
    bool changed = false;
    if (contacts_ && sleepingBodies_ > 0)
        for (int body : contacts_->reachedSleepers()) changed |= wakeIsland(sleepingIsland_[body]);
    const int particles = static_cast<int>(bodies_.particles.size());
    const double dt = settings_.dt;
    const Vec& u = u_[current_];
    constexpr double speed2 = kSleepSpeed * kSleepSpeed;
    bool ripe = false;
    for (int k : dynamicParticles_) {
        const int dof = bodies_.particles[k].dof;
        double& rest = restingSeconds_[k];
        rest = u.segment<2>(dof).squaredNorm() < speed2 ? rest + dt : 0.0;
        ripe = ripe || rest >= kSleepSeconds;
    }
    for (int k : dynamicRigidBodies_) {
        const int dof = bodies_.rigidBodies[k].dof;
        double& rest = restingSeconds_[particles + k];
        const bool slow =
            u.segment<2>(dof).squaredNorm() < speed2 && std::abs(u[dof + 2]) < kSleepTurnRate;
        rest = slow ? rest + dt : 0.0;
        ripe = ripe || rest >= kSleepSeconds;
    }
    // A body driven by hand (the mouse spring) stays awake while it is held.
    for (const auto& effect : effects_) {
        const int dof = effect->drivenDof();
        if (dof < 0 || dof >= layout_.dimension()) continue;
        const int body = dof < layout_.rigidBase()
                             ? dynamicParticles_[dof / 2]
                             : particles + dynamicRigidBodies_[(dof - layout_.rigidBase()) / 3];
        restingSeconds_[body] = 0.0;
    }
    if (ripe) changed |= fallAsleep();
    if (changed) relayoutForSleep();
}

// Islands among the awake bodies; those whose every body has rested kSleepSeconds and that no
// motor drives fall asleep, their joints with them. Returns whether any did.
bool World::fallAsleep() {
    const int particles = static_cast<int>(bodies_.particles.size());
    islands_.reset(static_cast<int>(restingSeconds_.size()));
    const auto awakeBody = [&](bool rigid, int index) {
        if (rigid) return bodies_.rigidBodies[index].dof >= 0 ? particles + index : -1;
        return bodies_.particles[index].dof >= 0 ? index : -1;
    };
    const auto tie = [&](int a, int b) {
        if (a >= 0 && b >= 0) islands_.unite(a, b);
    };
    // An effect that couples bodies at a distance makes every awake body one island.
    const bool coupled = std::any_of(effects_.begin(), effects_.end(),
                                     [](const auto& e) { return e->couplesBodies(); });
    int first = -1;
    if (coupled) {
        for (int k : dynamicParticles_) tie(first < 0 ? (first = k) : first, k);
        for (int k : dynamicRigidBodies_)
            tie(first < 0 ? (first = particles + k) : first, particles + k);
    }
    const auto springEnd = [&](const SpringEnd& end) {
        if (end.kind == SpringEnd::Kind::Anchor) return -1;
        return awakeBody(end.kind == SpringEnd::Kind::Rigid, end.index);
    };
    for (const Spring& s : bodies_.springs) tie(springEnd(s.a), springEnd(s.b));
    const auto jointEnd = [&](const JointBody& end) {
        if (end.kind == JointBody::Kind::World) return -1;
        return awakeBody(end.kind == JointBody::Kind::Rigid, end.index);
    };
    for (const Joint& j : bodies_.joints) tie(jointEnd(j.a), jointEnd(j.b));
    if (contacts_) {
        const bool fromSolver = settings_.contactModel == ContactModel::Impulse;
        contacts_->forEachTouchingPair(fromSolver, [&](int a, int b) {
            const bool awakeA = sleepingIsland_[a] < 0, awakeB = sleepingIsland_[b] < 0;
            if (awakeA && awakeB) tie(a, b);
        });
    }
    // Each island's least time at rest, and whether a joint holds it.
    const auto each = [&](auto&& fn) {
        for (int k : dynamicParticles_) fn(k);
        for (int k : dynamicRigidBodies_) fn(particles + k);
    };
    each([&](int body) {
        const int root = islands_.find(body);
        islandRest_[root] = std::numeric_limits<double>::infinity();
        islandHeld_[root] = 0;
        islandId_[root] = -1;
    });
    each([&](int body) {
        double& rest = islandRest_[islands_.find(body)];
        rest = std::min(rest, restingSeconds_[body]);
    });
    // A motor drives its island: stalled against a limit or a load it is slow, not at rest.
    for (const Joint& j : bodies_.joints)
        if (j.hasMotor)
            for (const JointBody* end : {&j.a, &j.b})
                if (const int body = jointEnd(*end); body >= 0)
                    islandHeld_[islands_.find(body)] = 1;
    bool any = false;
    each([&](int body) {
        const int root = islands_.find(body);
        if (islandHeld_[root] || islandRest_[root] < kSleepSeconds) return;
        if (islandId_[root] < 0) islandId_[root] = nextIsland_++;
        sleepingIsland_[body] = islandId_[root];
        (body < particles ? bodies_.particles[body].asleep
                          : bodies_.rigidBodies[body - particles].asleep) = true;
        any = true;
    });
    return any;
}

// Rebuilds the state around the bodies asleep now. The ledger's kinetic and potential energy
// stay what they were: what the sleepers hold is set aside as constants, and drift, work_nc and
// correction are untouched. The contacts keep their impulses and held forces
// (ContactStage::rebind) and the effects their timings.
void World::relayoutForSleep() {
    if (!committed_ || layoutDirty_) return;  // the next commit() lays out what the flags say
    const double kinetic = kineticEnergy(), potential = potentialEnergy();  // every body's
    sleepingKinetic_ = sleepingPotential_ = 0.0;
    storeStateInObjects();
    rebuildForSleep();
    if (contacts_ && settings_.contactModel == ContactModel::Impulse) {
        // The contacts found again at once, on the new layout, with the impulses and held forces
        // carried: the next step holds what the last one held. A trial step (what follows a load
        // or an edit, primeContactForces()) would start a pile over from one sub-step's forces:
        // a woken pyramid sagged and rocked as it did when first placed.
        const Vec& q = q_[current_];
        const Vec& u = u_[current_];
        contacts_->collide(bodies_, invMass_, q, u, u, 1.0 / settings_.substeps, settings_.dt,
                           settings_.contacts);
        heldValid_ = true;
    }
    sleepingBodies_ = 0;
    for (const int island : sleepingIsland_) sleepingBodies_ += island >= 0;
    sleepers_.reset();
    if (sleepingBodies_ > 0) {
        sleepingKinetic_ = kinetic - kineticEnergy();
        sleepingPotential_ = potential - potentialEnergy();
        auto sleepers = std::make_shared<Sleepers>();
        sleepers->bodies.reserve(static_cast<std::size_t>(sleepingBodies_));
        for (int i = 0; i < static_cast<int>(bodies_.particles.size()); ++i)
            if (const Particle& p = bodies_.particles[i]; p.asleep)
                sleepers->bodies.push_back({false, i, p.position, p.velocity, 0.0, 0.0});
        for (int i = 0; i < static_cast<int>(bodies_.rigidBodies.size()); ++i)
            if (const RigidBody& b = bodies_.rigidBodies[i]; b.asleep)
                sleepers->bodies.push_back(
                    {true, i, b.position, b.velocity, b.angle, b.angularVelocity});
        sleepers->kinetic = sleepingKinetic_;
        sleepers->potential = sleepingPotential_;
        sleepers_ = std::move(sleepers);
    } else {
        nextIsland_ = 0;
    }
    ledger_.carryOver(kinetic, potential);
    guard_.forgetGrowth();
}

void World::rebuildForSleep() {
    keptEffectSeconds_ = effectSeconds_;
    layoutDirty_ = true;
    sleepRelayout_ = true;
    commit();
    sleepRelayout_ = false;
    effectSeconds_ = keptEffectSeconds_;
}

void World::putToSleep(const std::shared_ptr<const Sleepers>& s) {
    ensureLayout();
    if (s == sleepers_) return;
    storeStateInObjects();
    const int particles = static_cast<int>(bodies_.particles.size());
    bool changed = false;
    const auto setAsleep = [&](bool& flag, bool asleep) {
        changed = changed || flag != asleep;
        flag = asleep;
    };
    std::vector<char> asleep(sleepingIsland_.size(), 0);
    if (s)
        for (const Sleepers::Body& b : s->bodies) {
            const int body = b.rigid ? particles + b.index : b.index;
            if (body < 0 || body >= static_cast<int>(asleep.size())) continue;
            asleep[body] = 1;
            if (b.rigid) {
                RigidBody& r = bodies_.rigidBodies[b.index];
                r.position = b.position;
                r.velocity = b.velocity;
                r.angle = b.angle;
                r.angularVelocity = b.angularVelocity;
            } else {
                bodies_.particles[b.index].position = b.position;
                bodies_.particles[b.index].velocity = b.velocity;
            }
        }
    sleepingBodies_ = 0;
    for (int i = 0; i < static_cast<int>(asleep.size()); ++i) {
        setAsleep(
            i < particles ? bodies_.particles[i].asleep : bodies_.rigidBodies[i - particles].asleep,
            asleep[i] != 0);
        sleepingIsland_[i] = asleep[i] ? 0 : -1;
        sleepingBodies_ += asleep[i];
    }
    sleepingKinetic_ = s ? s->kinetic : 0.0;
    sleepingPotential_ = s ? s->potential : 0.0;
    sleepers_ = s;
    if (changed) rebuildForSleep();
}

}  // namespace phasebox
