#include "physics/world/World.h"

#include "physics/contacts/ContactStage.h"
#include "physics/contacts/PenaltyContacts.h"
#include "physics/core/WorkerPool.h"
#include "physics/effects/SpringEffect.h"
#include "physics/scene/SceneSchema.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace phasebox {

namespace {
using Clock = ProfileClock;
}  // namespace

World::World() : pool_(std::make_unique<WorkerPool>()) {
    integrator_ = makeIntegrator(settings_.integrator);
}
World::~World() = default;

void World::setWorkers(int workers) {
    pool_->setWorkers(workers);
}

int World::workers() const {
    return pool_->workers();
}

// ---- objects ------------------------------------------------------------------------------

int World::addParticle(const Particle& particle) {
    storeStateInObjects();
    bodies_.particles.push_back(particle);
    layoutDirty_ = true;
    return static_cast<int>(bodies_.particles.size()) - 1;
}

int World::addRigidBody(const RigidBody& body) {
    storeStateInObjects();
    bodies_.rigidBodies.push_back(body);
    layoutDirty_ = true;
    return static_cast<int>(bodies_.rigidBodies.size()) - 1;
}

int World::addPlane(const Plane& plane) {
    bodies_.planes.push_back(plane);
    return static_cast<int>(bodies_.planes.size()) - 1;
}

int World::addSpring(const Spring& spring) {
    storeStateInObjects();
    bodies_.springs.push_back(spring);
    layoutDirty_ = true;
    return static_cast<int>(bodies_.springs.size()) - 1;
}

int World::addJoint(const Joint& joint) {
    storeStateInObjects();
    bodies_.joints.push_back(joint);
    layoutDirty_ = true;
    return static_cast<int>(bodies_.joints.size()) - 1;
}

int World::addCloth(const Cloth& cloth) {
    bodies_.cloths.push_back(cloth);
    return static_cast<int>(bodies_.cloths.size()) - 1;
}

void World::storeStateInObjects() {
    if (layoutDirty_) return;  // the objects already hold the newest values
    const Vec& q = q_[current_];
    const Vec& u = u_[current_];
    for (Particle& p : bodies_.particles) {
        if (p.dof < 0) continue;
        p.position = q.segment<2>(p.dof);
        p.velocity = u.segment<2>(p.dof);
    }
    for (RigidBody& b : bodies_.rigidBodies) {
        if (b.dof < 0) continue;
        b.position = q.segment<2>(b.dof);
        b.angle = q[b.dof + 2];
        b.velocity = u.segment<2>(b.dof);
        b.angularVelocity = u[b.dof + 2];
    }
}

void World::commit() {
    if (!layoutDirty_) return;
    const bool hadLayout = committed_;
    committed_ = true;
    showingFrame_ = false;
    if (!sleepRelayout_) resetSleep();  // an edit wakes every island

    dynamicParticles_.clear();
    dynamicRigidBodies_.clear();
    for (int i = 0; i < static_cast<int>(bodies_.particles.size()); ++i)
        if (!bodies_.particles[i].pinned && !bodies_.particles[i].asleep)
            dynamicParticles_.push_back(i);
    for (int i = 0; i < static_cast<int>(bodies_.rigidBodies.size()); ++i)
        if (!bodies_.rigidBodies[i].isStatic && !bodies_.rigidBodies[i].asleep)
            dynamicRigidBodies_.push_back(i);
    layout_.dynamicParticles = static_cast<int>(dynamicParticles_.size());
    layout_.dynamicRigidBodies = static_cast<int>(dynamicRigidBodies_.size());

    const int n = layout_.dimension();
    for (int k = 0; k < 2; ++k) {
        q_[k].setZero(n);
        u_[k].setZero(n);
    }
    current_ = 0;
    mass_.setZero(n);
    invMass_.setZero(n);
    force_.setZero(n);
    heldForce_.setZero(n);
    heldMotor_.setZero(n);
    motorsHeld_ = false;
    heldValid_ = false;  // the contact solver's bodies are of the old layout until a collide
    Vec& q = q_[0];
    Vec& u = u_[0];
    for (Particle& p : bodies_.particles) p.dof = -1;
    for (RigidBody& b : bodies_.rigidBodies) b.dof = -1;
    for (int k = 0; k < layout_.dynamicParticles; ++k) {
        Particle& p = bodies_.particles[dynamicParticles_[k]];
        p.dof = layout_.particleDof(k);
        q.segment<2>(p.dof) = p.position;
        u.segment<2>(p.dof) = p.velocity;
        mass_.segment<2>(p.dof).setConstant(p.mass);
    }
    for (int k = 0; k < layout_.dynamicRigidBodies; ++k) {
        RigidBody& b = bodies_.rigidBodies[dynamicRigidBodies_[k]];
        b.dof = layout_.rigidDof(k);
        q.segment<2>(b.dof) = b.position;
        q[b.dof + 2] = b.angle;
        u.segment<2>(b.dof) = b.velocity;
        u[b.dof + 2] = b.angularVelocity;
        mass_.segment<2>(b.dof).setConstant(b.mass);
        mass_[b.dof + 2] = b.inertia;
    }
    invMass_ = mass_.cwiseInverse();

    rebuildSpringEffect();
    bindEffects();
    if (ContactStage::needed(bodies_, particleCollisions_)) {
        if (sleepRelayout_ && contacts_) {
            contacts_->rebind(bodies_);
        } else {
            if (!contacts_)
                contacts_ =
                    std::make_unique<ContactStage>(particleCollisions_, particleRestitution_);
            contacts_->bind(bodies_);
        }
    } else {
        contacts_.reset();
    }
    configureContactModel();
    if (!bodies_.joints.empty()) {
        if (!joints_) joints_ = std::make_unique<JointSolver>();
        joints_->bind(bodies_, sleepRelayout_);
        jointScratch_.setZero(n);
        if (contacts_) {  // step(): the state the contacts start from, where both act
            beforeContactsQ_.setZero(n);
            beforeContactsU_.setZero(n);
        }
    } else {
        joints_.reset();
    }
    integrator_->reset(n);
    layoutDirty_ = false;

    // Keep the drift continuous across an edit: the edit itself is not integration error.
    if (hadLayout) {
        ledger_.carryOver(kineticEnergy(), potentialEnergy());
    } else {
        resetEnergyBaseline();
    }
}

void World::rebuildSpringEffect() {
    if (bodies_.springs.empty()) {
        if (springEffect_) {
            std::erase_if(effects_, [this](const auto& e) { return e.get() == springEffect_; });
            springEffect_ = nullptr;
        }
        return;
    }
    if (!springEffect_) {
        auto effect = std::make_unique<SpringEffect>();
        springEffect_ = effect.get();
        effects_.push_back(std::move(effect));
    }
    std::vector<SpringTerm> terms;
    terms.reserve(bodies_.springs.size());
    auto resolve = [this](const SpringEnd& end) -> BodyPoint {
        switch (end.kind) {
            case SpringEnd::Kind::Particle: {
                const Particle& p = bodies_.particles[end.index];
                return p.dof >= 0 ? BodyPoint::particle(p.dof) : BodyPoint::fixed(p.position);
            }
            case SpringEnd::Kind::Rigid: {
                const RigidBody& b = bodies_.rigidBodies[end.index];
                if (b.dof >= 0) return BodyPoint::rigid(b.dof, end.point);
                return BodyPoint::fixed(b.position + rotation(b.angle) * end.point);
            }
            case SpringEnd::Kind::Anchor:
                break;
        }
        return BodyPoint::fixed(end.point);
    };
    for (const Spring& s : bodies_.springs)
        terms.push_back({resolve(s.a), resolve(s.b), s.stiffness, s.damping, s.restLength});
    springEffect_->setTerms(std::move(terms));
}

void World::bindEffects() {
    const EffectWorldView view{&layout_, &mass_, &bodies_.particles, &bodies_.rigidBodies,
                               pool_.get()};
    for (auto& effect : effects_) effect->bind(view);
    if (penalty_) penalty_->bind(view);
    sortEffectsByChannel();
}

void World::sortEffectsByChannel() {
    forceEffects_.clear();
    fieldEffects_.clear();
    restFieldEffects_.clear();
    uniformEffects_.clear();
    nonConservative_.clear();
    for (int i = 0; i < static_cast<int>(effects_.size()); ++i) {
        Effect& e = *effects_[i];
        (e.isAccelerationField() ? fieldEffects_ : forceEffects_).push_back(i);
        Vec2 uniform = Vec2::Zero();
        if (e.isAccelerationField())
            (e.uniformAcceleration(uniform) ? uniformEffects_ : restFieldEffects_).push_back(i);
        if (e.hasNonConservativePart()) nonConservative_.push_back(i);
    }
    effectSeconds_.assign(effects_.size() + 1, 0.0);  // the last: contacts
}

Vec2 World::particlePosition(int i) const {
    const Particle& p = bodies_.particles.at(i);
    return p.dof >= 0 && !layoutDirty_ ? Vec2(q_[current_].segment<2>(p.dof)) : p.position;
}
Vec2 World::particleVelocity(int i) const {
    const Particle& p = bodies_.particles.at(i);
    return p.dof >= 0 && !layoutDirty_ ? Vec2(u_[current_].segment<2>(p.dof)) : p.velocity;
}
Vec2 World::bodyPosition(int i) const {
    const RigidBody& b = bodies_.rigidBodies.at(i);
    return b.dof >= 0 && !layoutDirty_ ? Vec2(q_[current_].segment<2>(b.dof)) : b.position;
}
double World::bodyAngle(int i) const {
    const RigidBody& b = bodies_.rigidBodies.at(i);
    return b.dof >= 0 && !layoutDirty_ ? q_[current_][b.dof + 2] : b.angle;
}
Vec2 World::bodyVelocity(int i) const {
    const RigidBody& b = bodies_.rigidBodies.at(i);
    return b.dof >= 0 && !layoutDirty_ ? Vec2(u_[current_].segment<2>(b.dof)) : b.velocity;
}
double World::bodyAngularVelocity(int i) const {
    const RigidBody& b = bodies_.rigidBodies.at(i);
    return b.dof >= 0 && !layoutDirty_ ? u_[current_][b.dof + 2] : b.angularVelocity;
}

Vec2 World::springEndPosition(const SpringEnd& end) const {
    switch (end.kind) {
        case SpringEnd::Kind::Particle:
            return particlePosition(end.index);
        case SpringEnd::Kind::Rigid:
            return bodyPosition(end.index) + rotation(bodyAngle(end.index)) * end.point;
        case SpringEnd::Kind::Anchor:
            break;
    }
    return end.point;
}

double World::springTension(int i) const {
    if (!springEffect_ || layoutDirty_) return 0.0;
    return springEffect_->tension(static_cast<std::size_t>(i), q_[current_], u_[current_]);
}

// ---- effects ------------------------------------------------------------------------------

void World::addEffect(std::unique_ptr<Effect> effect) {
    // A new effect changes the potential energy: rebuild so the drift stays continuous.
    storeStateInObjects();
    layoutDirty_ = true;
    effects_.push_back(std::move(effect));
    // The spring effect stays last so that scene effects keep their listed order.
    if (springEffect_) {
        auto it = std::find_if(effects_.begin(), effects_.end(),
                               [this](const auto& e) { return e.get() == springEffect_; });
        std::rotate(it, it + 1, effects_.end());
    }
    bindEffects();
}

std::unique_ptr<Effect> World::removeEffect(const Effect* effect) {
    if (effect == springEffect_) return nullptr;
    auto it = std::find_if(effects_.begin(), effects_.end(),
                           [effect](const auto& e) { return e.get() == effect; });
    if (it == effects_.end()) return nullptr;
    // Like adding one, removing an effect changes the potential energy: rebuild.
    storeStateInObjects();
    layoutDirty_ = true;
    std::unique_ptr<Effect> removed = std::move(*it);
    effects_.erase(it);
    bindEffects();
    return removed;
}

void World::setTime(double t) {
    clock_.time = t;
    clock_.timeBase = t;
    clock_.stepsSinceTimeBase = 0;
}

Effect* World::findEffect(const std::string& name) const {
    for (const auto& e : effects_)
        if (e->name() == name) return e.get();
    return nullptr;
}

// ---- settings -----------------------------------------------------------------------------

void World::setSettings(const SimulationSettings& settings) {
    if (!findIntegrator(settings.integrator))
        throw std::invalid_argument("unknown integrator \"" + settings.integrator +
                                    "\"; known: " + knownIntegratorNames());
    // The scene format's range (the schema's), so that a World runs every valid scene.
    const double maxDt = schema::simulationField(schema::key::dt).range.max;
    if (!(settings.dt > 0.0) || !(settings.dt <= maxDt)) {
        std::ostringstream message;
        message << "dt must be > 0 and <= " << maxDt;
        throw std::invalid_argument(message.str());
    }
    if (settings.substeps < 1) throw std::invalid_argument("substeps must be >= 1");
    if (!(settings.tolerance > 0.0) || !std::isfinite(settings.tolerance))
        throw std::invalid_argument("tolerance must be > 0");
    if (settings.newtonIterations < 1)
        throw std::invalid_argument("newton_iterations must be >= 1");
    if (!(settings.contactStiffness >= 0.0) || !std::isfinite(settings.contactStiffness))
        throw std::invalid_argument("contact_stiffness must be > 0");
    if (!(settings.contactDamping >= 0.0) || !std::isfinite(settings.contactDamping))
        throw std::invalid_argument("contact_damping must be >= 0");
    const bool newMethod = settings.integrator != settings_.integrator;
    const bool newModel = settings.contactModel != settings_.contactModel;
    if (settings.dt != settings_.dt) {
        clock_.timeBase = clock_.time;
        clock_.stepsSinceTimeBase = 0;
    }
    settings_ = settings;
    if (newMethod) {
        integrator_ = makeIntegrator(settings_.integrator);
        integrator_->reset(layout_.dimension());
    }
    integrator_->setSettings(
        {settings_.tolerance, settings_.newtonIterations, 1.0 / std::max(1, settings_.substeps)});
    // A switch of method or contact model wakes every island (CONTRACT §6), and so does
    // switching sleeping off.
    if (newMethod || newModel || !settings_.sleep) wakeAll();
    // A switch of contact model keeps the state: only the response changes. The penalty's
    // potential of the overlaps there are comes or goes with it, which is not integration error.
    if (committed_ && !layoutDirty_ && contacts_) {
        configureContactModel();
        ledger_.carryOver(kineticEnergy(), potentialEnergy());
    }
}

void World::setParticleCollisions(bool enabled, double restitution) {
    storeStateInObjects();
    particleCollisions_ = enabled;
    particleRestitution_ = restitution;
    contacts_.reset();  // rebuilt with the new pair rule
    layoutDirty_ = true;
}

void World::setIntegrator(const std::string& name) {
    SimulationSettings s = settings_;
    s.integrator = name;
    setSettings(s);
}

// ---- the ODE view -------------------------------------------------------------------------

double World::acceleration(double t, const Vec& q, const Vec& u, Vec& accel) {
    ++forceEvaluations_;
    double power = 0.0;
    if (!addAccelerations(t, q, u, accel, fieldEffects_, power)) accel.setZero();
    if (joints_) constrainJoints(q, u, accel, true);
    return power;
}

OdeSystem::SplitAcceleration World::accelerationSplit(double t, const Vec& q, const Vec& u,
                                                      Vec& rest) {
    SplitAcceleration split;
    if (joints_) {
        // The constraint forces answer the whole acceleration: nothing is split off.
        split.power = acceleration(t, q, u, rest);
        return split;
    }
    ++forceEvaluations_;
    split.uniform = uniformField();
    split.hasRest = addAccelerations(t, q, u, rest, restFieldEffects_, split.power);
    return split;
}

Vec2 World::uniformField() const {
    Vec2 field = Vec2::Zero();
    for (int i : uniformEffects_) {
        Vec2 a = Vec2::Zero();
        effects_[i]->uniformAcceleration(a);
        field += a;
    }
    return field;
}

// The force channel, then the given field effects; returns false (accel untouched) when there
// is nothing to evaluate.
bool World::addAccelerations(double t, const Vec& q, const Vec& u, Vec& accel,
                             const std::vector<int>& fields, double& power) {
    bool written = false;
    if (!forceEffects_.empty() || penalty_ || holding_ || motorsHeld_) {
        if (holding_) {
            force_ = heldForce_;
        } else {
            force_.setZero();
        }
        if (motorsHeld_) force_ += heldMotor_;
        for (int i : forceEffects_) {
            const auto start = Clock::now();
            power += effects_[i]->addForces(t, q, u, force_);
            effectSeconds_[i] += secondsSince(start);
        }
        if (penalty_) {
            const auto start = Clock::now();
            power += penalty_->addForces(t, q, u, force_);
            effectSeconds_.back() += secondsSince(start);
        }
        accel.array() = invMass_.array() * force_.array();
        written = true;
    }
    for (int i : fields) {
        const auto start = Clock::now();
        effects_[i]->addAccelerations(t, q, u, accel, !written);
        effectSeconds_[i] += secondsSince(start);
        written = true;
    }
    return written;
}

double World::nonConservativePower(double t, const Vec& q, const Vec& u) {
    double power = 0.0;
    for (int i : nonConservative_) power += effects_[i]->nonConservativePower(t, q, u);
    if (penalty_) power += penalty_->nonConservativePower(t, q, u);
    return power;
}

void World::addHeldForces(Vec& force) const {
    if (holding_) force += heldForce_;
    if (motorsHeld_) force += heldMotor_;
}

double World::forces(double t, const Vec& q, const Vec& u, Vec& force) {
    ++forceEvaluations_;
    force.setZero();
    double power = 0.0;
    for (int i = 0; i < static_cast<int>(effects_.size()); ++i) {
        const auto start = Clock::now();
        power += effects_[i]->addForces(t, q, u, force);
        effectSeconds_[i] += secondsSince(start);
    }
    if (penalty_) {
        const auto start = Clock::now();
        power += penalty_->addForces(t, q, u, force);
        effectSeconds_.back() += secondsSince(start);
    }
    addHeldForces(force);
    if (joints_) constrainJoints(q, u, force, false);
    return power;
}

double World::forcesAndJacobians(double t, const Vec& q, const Vec& u, Vec& force,
                                 ForceJacobians& jacobians) {
    ++forceEvaluations_;
    force.setZero();
    double power = 0.0;
    for (int i = 0; i < static_cast<int>(effects_.size()); ++i) {
        const auto start = Clock::now();
        power += effects_[i]->addForcesAndJacobians(t, q, u, force, jacobians);
        effectSeconds_[i] += secondsSince(start);
    }
    if (penalty_) {
        const auto start = Clock::now();
        power += penalty_->addForcesAndJacobians(t, q, u, force, jacobians);
        effectSeconds_.back() += secondsSince(start);
    }
    addHeldForces(force);  // constant over the step: no Jacobian
    if (joints_) constrainJoints(q, u, force, false);
    return power;
}

void World::constrainJoints(const Vec& q, const Vec& u, Vec& x, bool accelerations) {
    // A method that takes the joints' force at the step's end (backward Euler) meets it only in
    // its end projection (shake()): in its evaluations the joints are solved for their forces
    // (the probes, the sub-step count) and nothing is added. Taken at the start of the Newton
    // solve instead, the force was explicit and the step symplectic Euler's.
    Vec* target = &x;
    if (integrator_->info().constraintsAtEnd) {
        unappliedJointForce_ = x;  // same size after the first: no allocation
        target = &unappliedJointForce_;
    }
    if (accelerations)
        joints_->constrainAccelerations(q, u, invMass_, *target);
    else
        joints_->constrainForces(q, u, invMass_, *target, jointScratch_);
}

void World::setState(const Vec& q, const Vec& u) {
    ensureLayout();
    if (q.size() != layout_.dimension() || u.size() != layout_.dimension())
        throw std::invalid_argument("state size does not match the world's layout");
    q_[current_] = q;
    u_[current_] = u;
    showingFrame_ = false;
}

std::string World::objectAtDof(int dof) const {
    if (dof < 0 || dof >= layout_.dimension()) return {};
    if (dof < layout_.rigidBase()) return bodies_.particles[dynamicParticles_[dof / 2]].id;
    return bodies_.rigidBodies[dynamicRigidBodies_[(dof - layout_.rigidBase()) / 3]].id;
}

// ---- stepping -----------------------------------------------------------------------------

// One frame of dt, as a script of named stages (each timed into profile_, CONTRACT.md §7):
//   integrate       the method's step with every effect and the constraint forces inside it:
//                   the joints' in every evaluation, the contacts' as the forces of their last
//                   solve held over the step (holdContactForces())
//   solve joints    SHAKE and the velocity projection complete the method's step for joints
//   collide         find contacts once per frame, after the first sub-step (broad phase over
//                   how far each body can move, narrow phase, warm start)
//   solve contacts  what the held forces missed: impacts, friction, the overlap pushed out
//   ledger          the energy ledger of the end state
//   guard           divergence: a non-finite value or runaway energy restores a good frame
bool World::step() {
    ensureLayout();
    showingFrame_ = false;
    divergence_.reset();
    if (contacts_) contacts_->setPool(pool_.get());
    const int substeps = settings_.substeps * (joints_ ? jointSubstepsForFrame() : 1);
    const double h = settings_.dt / substeps;
    // With one sub-step the other state buffer keeps the frame start for free.
    guard_.beginFrame(clock_, ledger_, q_[current_], u_[current_], substeps > 1);
    StageTimer timer(profile_);
    ++profile_.steps;
    primeContactForces(timer);
    StateSummary summary;
    bool summed = false;
    for (int s = 0; s < substeps; ++s) {
        const double t = guard_.frameStart().clock.time + s * h;
        const int next = 1 - current_;
        // Where no constraint stage moves the bodies after it, the method's last pass sums the
        // frame's end state for the ledger.
        const bool sumHere = s + 1 == substeps && (!contacts_ || penalty_) && !joints_;
        if (penalty_ && s == 0) {  // the penalty force acts inside the method: pairs first
            timer.start(StepStage::Collide);
            findPenaltyPairs();
        }
        timer.start(StepStage::Integrate);
        holdContactForces();
        holdMotorTorques();
        const bool ok = integrate(t, h, next, sumHere ? &summary : nullptr);
        if (ok) solveConstraints(h, s == 0 ? substeps : 0, next, timer);
        if (!ok || (substeps > 1 && !(q_[next].allFinite() && u_[next].allFinite())))
            return failSubstep(t + h, !ok, next);
        current_ = next;
        summed = sumHere;
    }
    advanceClock();
    timer.start(StepStage::Ledger);
    summary = closeLedger(summed ? &summary : nullptr);
    checkInvariants(StepStage::Ledger);
    timer.start(StepStage::Guard);
    const bool good = guard(summary);
    checkInvariants(StepStage::Guard);
    if (good && settings_.sleep) updateSleep();  // timed with the guard
    return good;
}

void World::advanceClock() {
    ++clock_.stepsSinceTimeBase;
    clock_.time = clock_.timeBase + static_cast<double>(clock_.stepsSinceTimeBase) * settings_.dt;
    ++clock_.stepCount;
}

bool World::integrate(double t, double h, int next, StateSummary* summary) {
    if (joints_) joints_->holdLimitsFromNextEvaluation();
    return integrator_->step(*this, t, h, q_[current_], u_[current_], q_[next], u_[next],
                             ledger_.workNc, summary);
}

StateSummary World::closeLedger(const StateSummary* summed) {
    const Vec& q = q_[current_];
    const StateSummary summary =
        summed ? *summed : summarizeState(pointDofs(), mass_, q, u_[current_]);
    if (summary.finite) {
        StateSummary all = summary;  // with what the bodies asleep hold
        all.kinetic += sleepingKinetic_;
        ledger_.close(all, phasebox::potentialEnergy(effects_, q, summary.massMoment) +
                               contactPotential(q) + sleepingPotential_);
    }
    return summary;
}

bool World::guard(const StateSummary& summary) {
    std::string what;
    DivergenceGuard::Verdict verdict = guard_.onNonFinite();
    if (!summary.finite) {
        what = "a non-finite value";
    } else if (!std::isfinite(ledger_.drift)) {
        what = "non-finite energy";
    } else {
        verdict = guard_.judge(ledger_, q_[1 - current_], u_[1 - current_]);
        if (verdict == DivergenceGuard::Verdict::Good) return true;
        what = "energy growing without bound";  // past 10³·E₀ (CONTRACT §2)
    }
    Divergence d;
    d.time = clock_.time;
    d.objectId =
        summary.finite ? mostEnergeticObject() : firstNonFinite(q_[current_], u_[current_]);
    if (d.objectId.empty()) d.objectId = mostEnergeticObject();  // energy overflowed first
    d.what = what;
    if (verdict == DivergenceGuard::Verdict::RestoreRunawayStart)
        restore(guard_.runawayStart(), false);
    else
        restore(guard_.frameStart(), true);
    d.restoredTime = clock_.time;
    nameStraightChain(d);
    divergence_ = d;
    return false;
}

bool World::failSubstep(double t, bool integratorFailed, int next) {
    Divergence d;
    d.time = t;
    d.objectId = firstNonFinite(q_[next], u_[next]);
    const IntegratorInfo& info = integrator_->info();
    d.what = !integratorFailed ? std::string("a non-finite value")
             : info.adaptive   ? std::string(info.name) +
                                   " could not meet its tolerance within its budget of internal "
                                   "steps: the scene is too stiff for it"
                             : std::string(info.name) + " failed";
    holding_ = false;
    motorsHeld_ = false;
    current_ = next;  // restore() reads the frame start from the right place
    if (guard_.onNonFinite() == DivergenceGuard::Verdict::RestoreRunawayStart)
        restore(guard_.runawayStart(), false);
    else
        restore(guard_.frameStart(), true);
    d.restoredTime = clock_.time;
    nameStraightChain(d);
    divergence_ = d;
    return false;
}

void World::restore(const DivergenceGuard::Checkpoint& c, bool fromOtherBuffer) {
    if (c.hasState) {
        q_[current_] = c.q;
        u_[current_] = c.u;
    } else if (fromOtherBuffer) {
        current_ = 1 - current_;
    }
    clock_ = c.clock;
    ledger_ = c.ledger;
    guard_.forgetGrowth();
}

double World::kineticEnergy() const {
    return summarizeState(pointDofs(), mass_, q_[current_], u_[current_]).kinetic +
           sleepingKinetic_;
}

double World::potentialEnergy() const {
    const Vec& q = q_[current_];
    return phasebox::potentialEnergy(
               effects_, q, summarizeState(pointDofs(), mass_, q, u_[current_]).massMoment) +
           contactPotential(q) + sleepingPotential_;
}

double World::mechanicalEnergy(const Vec& q, const Vec& u) const {
    const StateSummary summary = summarizeState(pointDofs(), mass_, q, u);
    return summary.kinetic + phasebox::potentialEnergy(effects_, q, summary.massMoment) +
           contactPotential(q);
}

}  // namespace phasebox
