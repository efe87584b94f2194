#include "physics/core/World.h"

#include "physics/contacts/ContactStage.h"
#include "physics/effects/GravityEffect.h"
#include "physics/effects/SpringEffect.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace phasebox {

namespace {
double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Divergence by runaway energy: the drift (the integrator's energy error) exceeds this many
// times the scene's energy scale and has grown by kGrowth per step kStreak steps in a row
// (exponential blow-up), or exceeds kAbsurd times the scale whatever its growth. The factor is
// high because a stable method near its limit swings far: symplectic Euler at ω·h = 1.99 is
// bounded but its energy error reaches 200 times the oscillator's energy.
constexpr double kRunawayFactor = 1e3;
constexpr double kGrowth = 1.5;
constexpr int kStreak = 3;
constexpr double kAbsurd = 1e8;
}  // namespace

std::string Divergence::message() const {
    std::ostringstream out;
    out << "the simulation diverged at t = " << time << " s";
    if (!objectId.empty()) out << " in object \"" << objectId << "\"";
    out << " (" << what << "); the state was restored to t = " << restoredTime
        << " s. Try a smaller dt, more sub-steps, or an implicit integrator (implicit_euler).";
    return out.str();
}

World::World() { integrator_ = makeIntegrator(settings_.integrator); }
World::~World() = default;

// ---- objects ------------------------------------------------------------------------------

int World::addParticle(const Particle& particle) {
    storeStateInObjects();
    particles_.push_back(particle);
    layoutDirty_ = true;
    return static_cast<int>(particles_.size()) - 1;
}

int World::addBox(const Box& box) {
    storeStateInObjects();
    boxes_.push_back(box);
    layoutDirty_ = true;
    return static_cast<int>(boxes_.size()) - 1;
}

int World::addPlane(const Plane& plane) {
    planes_.push_back(plane);
    return static_cast<int>(planes_.size()) - 1;
}

int World::addSpring(const Spring& spring) {
    storeStateInObjects();
    springs_.push_back(spring);
    layoutDirty_ = true;
    return static_cast<int>(springs_.size()) - 1;
}

int World::addCloth(const Cloth& cloth) {
    cloths_.push_back(cloth);
    return static_cast<int>(cloths_.size()) - 1;
}

void World::storeStateInObjects() {
    if (layoutDirty_) return;  // the objects already hold the newest values
    const Vec& q = q_[current_];
    const Vec& u = u_[current_];
    for (Particle& p : particles_) {
        if (p.dof < 0) continue;
        p.position = q.segment<2>(p.dof);
        p.velocity = u.segment<2>(p.dof);
    }
    for (Box& b : boxes_) {
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
    const double driftBefore = ledger_.drift;

    dynamicParticles_.clear();
    dynamicBoxes_.clear();
    for (int i = 0; i < static_cast<int>(particles_.size()); ++i)
        if (!particles_[i].pinned) dynamicParticles_.push_back(i);
    for (int i = 0; i < static_cast<int>(boxes_.size()); ++i)
        if (!boxes_[i].isStatic) dynamicBoxes_.push_back(i);
    layout_.dynamicParticles = static_cast<int>(dynamicParticles_.size());
    layout_.dynamicBoxes = static_cast<int>(dynamicBoxes_.size());

    const int n = layout_.dimension();
    for (int k = 0; k < 2; ++k) {
        q_[k].setZero(n);
        u_[k].setZero(n);
    }
    current_ = 0;
    mass_.setZero(n);
    invMass_.setZero(n);
    force_.setZero(n);
    Vec& q = q_[0];
    Vec& u = u_[0];
    for (Particle& p : particles_) p.dof = -1;
    for (Box& b : boxes_) b.dof = -1;
    for (int k = 0; k < layout_.dynamicParticles; ++k) {
        Particle& p = particles_[dynamicParticles_[k]];
        p.dof = layout_.particleDof(k);
        q.segment<2>(p.dof) = p.position;
        u.segment<2>(p.dof) = p.velocity;
        mass_.segment<2>(p.dof).setConstant(p.mass);
    }
    for (int k = 0; k < layout_.dynamicBoxes; ++k) {
        Box& b = boxes_[dynamicBoxes_[k]];
        b.dof = layout_.boxDof(k);
        q.segment<2>(b.dof) = b.position;
        q[b.dof + 2] = b.angle;
        u.segment<2>(b.dof) = b.velocity;
        u[b.dof + 2] = b.angularVelocity;
        mass_.segment<2>(b.dof).setConstant(b.mass);
        mass_[b.dof + 2] = b.inertia;
    }
    invMass_ = mass_.cwiseInverse();
    particleMass_.resize(layout_.dynamicParticles);
    for (int k = 0; k < layout_.dynamicParticles; ++k) particleMass_[k] = mass_[layout_.particleDof(k)];
    totalDofMass_ = mass_.sum();
    freeFallBound_.reset();

    rebuildSpringEffect();
    bindEffects();
    if (ContactStage::needed(*this, particleCollisions_)) {
        if (!contacts_)
            contacts_ = std::make_unique<ContactStage>(particleCollisions_, particleRestitution_);
        contacts_->bind(*this);
    } else {
        contacts_.reset();
    }
    integrator_->reset(n);
    layoutDirty_ = false;

    // Keep the drift continuous across an edit: the edit itself is not integration error.
    ledger_.kinetic = kineticEnergy();
    ledger_.potential = potentialEnergy();
    if (hadLayout) {
        ledger_.initial = ledger_.kinetic + ledger_.potential - ledger_.workNc - driftBefore;
        ledger_.drift = driftBefore;
    } else {
        resetEnergyBaseline();
    }
}

void World::rebuildSpringEffect() {
    if (springs_.empty()) {
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
    terms.reserve(springs_.size());
    auto resolve = [this](const SpringEnd& end) -> BodyPoint {
        switch (end.kind) {
            case SpringEnd::Kind::Particle: {
                const Particle& p = particles_[end.index];
                return p.dof >= 0 ? BodyPoint::particle(p.dof) : BodyPoint::fixed(p.position);
            }
            case SpringEnd::Kind::Box: {
                const Box& b = boxes_[end.index];
                if (b.dof >= 0) return BodyPoint::box(b.dof, end.point);
                return BodyPoint::fixed(b.position + rotation(b.angle) * end.point);
            }
            case SpringEnd::Kind::Anchor:
                break;
        }
        return BodyPoint::fixed(end.point);
    };
    for (const Spring& s : springs_)
        terms.push_back({resolve(s.a), resolve(s.b), s.stiffness, s.damping, s.restLength});
    springEffect_->setTerms(std::move(terms));
}

void World::bindEffects() {
    const EffectWorldView view{&layout_, &mass_, &particles_, &boxes_};
    for (auto& effect : effects_) effect->bind(view);
    sortEffectsByChannel();
}

void World::sortEffectsByChannel() {
    forceEffects_.clear();
    fieldEffects_.clear();
    nonConservative_.clear();
    for (int i = 0; i < static_cast<int>(effects_.size()); ++i) {
        Effect& e = *effects_[i];
        (e.isAccelerationField() ? fieldEffects_ : forceEffects_).push_back(i);
        if (e.hasNonConservativePart()) nonConservative_.push_back(i);
    }
    effectSeconds_.assign(effects_.size(), 0.0);
}

Vec2 World::particlePosition(int i) const {
    const Particle& p = particles_.at(i);
    return p.dof >= 0 && !layoutDirty_ ? Vec2(q_[current_].segment<2>(p.dof)) : p.position;
}
Vec2 World::particleVelocity(int i) const {
    const Particle& p = particles_.at(i);
    return p.dof >= 0 && !layoutDirty_ ? Vec2(u_[current_].segment<2>(p.dof)) : p.velocity;
}
Vec2 World::boxPosition(int i) const {
    const Box& b = boxes_.at(i);
    return b.dof >= 0 && !layoutDirty_ ? Vec2(q_[current_].segment<2>(b.dof)) : b.position;
}
double World::boxAngle(int i) const {
    const Box& b = boxes_.at(i);
    return b.dof >= 0 && !layoutDirty_ ? q_[current_][b.dof + 2] : b.angle;
}
Vec2 World::boxVelocity(int i) const {
    const Box& b = boxes_.at(i);
    return b.dof >= 0 && !layoutDirty_ ? Vec2(u_[current_].segment<2>(b.dof)) : b.velocity;
}
double World::boxAngularVelocity(int i) const {
    const Box& b = boxes_.at(i);
    return b.dof >= 0 && !layoutDirty_ ? u_[current_][b.dof + 2] : b.angularVelocity;
}

Vec2 World::springEndPosition(const SpringEnd& end) const {
    switch (end.kind) {
        case SpringEnd::Kind::Particle:
            return particlePosition(end.index);
        case SpringEnd::Kind::Box:
            return boxPosition(end.index) + rotation(boxAngle(end.index)) * end.point;
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
    time_ = t;
    timeBase_ = t;
    stepsSinceTimeBase_ = 0;
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
    if (!(settings.dt > 0.0) || !(settings.dt <= 1.0))
        throw std::invalid_argument("dt must be > 0 and <= 1");
    if (settings.substeps < 1) throw std::invalid_argument("substeps must be >= 1");
    if (!(settings.tolerance > 0.0) || !std::isfinite(settings.tolerance))
        throw std::invalid_argument("tolerance must be > 0");
    if (settings.newtonIterations < 1)
        throw std::invalid_argument("newton_iterations must be >= 1");
    const bool newMethod = settings.integrator != settings_.integrator;
    if (settings.dt != settings_.dt) {
        timeBase_ = time_;
        stepsSinceTimeBase_ = 0;
    }
    settings_ = settings;
    if (newMethod) {
        integrator_ = makeIntegrator(settings_.integrator);
        integrator_->reset(layout_.dimension());
    }
    integrator_->setSettings({settings_.tolerance, settings_.newtonIterations});
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
    bool written = false;
    if (!forceEffects_.empty()) {
        force_.setZero();
        for (int i : forceEffects_) {
            const auto start = Clock::now();
            power += effects_[i]->addForces(t, q, u, force_);
            effectSeconds_[i] += secondsSince(start);
        }
        accel.array() = invMass_.array() * force_.array();
        written = true;
    }
    for (int i : fieldEffects_) {
        const auto start = Clock::now();
        effects_[i]->addAccelerations(t, q, u, accel, !written);
        effectSeconds_[i] += secondsSince(start);
        written = true;
    }
    if (!written) accel.setZero();
    return power;
}

double World::nonConservativePower(double t, const Vec& q, const Vec& u) {
    double power = 0.0;
    for (int i : nonConservative_) power += effects_[i]->nonConservativePower(t, q, u);
    return power;
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
    return power;
}

void World::setState(const Vec& q, const Vec& u) {
    ensureLayout();
    if (q.size() != layout_.dimension() || u.size() != layout_.dimension())
        throw std::invalid_argument("state size does not match the world's layout");
    q_[current_] = q;
    u_[current_] = u;
    freeFallBound_.reset();
}

std::string World::objectAtDof(int dof) const {
    if (dof < 0 || dof >= layout_.dimension()) return {};
    if (dof < layout_.boxBase()) return particles_[dynamicParticles_[dof / 2]].id;
    return boxes_[dynamicBoxes_[(dof - layout_.boxBase()) / 3]].id;
}

// ---- stepping -----------------------------------------------------------------------------

bool World::step() {
    ensureLayout();
    divergence_.reset();
    const double h = settings_.dt / settings_.substeps;
    const auto stepStart = Clock::now();
    const bool fused = fusedFreeFall();
    // A free-fall frame that provably cannot diverge is stepped in place: with nothing to go
    // back to, the second buffer (half of the memory traffic of this memory-bound pass) is
    // not needed.
    const bool inPlace = fused && freeFallCannotDiverge();
    saveFrameStart(inPlace);
    if (contacts_) {
        const auto start = Clock::now();
        contacts_->collide(*this, q_[current_], u_[current_], settings_.dt, settings_.contacts);
        contactSeconds_ += secondsSince(start);
    }
    StateSummary summary;
    for (int s = 0; s < settings_.substeps; ++s) {
        const double t = frameStart_.time + s * h;
        const int next = inPlace ? current_ : 1 - current_;
        bool ok = true;
        if (fused) {
            const auto start = Clock::now();
            freeFallStep(h, q_[current_], u_[current_], q_[next], u_[next],
                         s + 1 == settings_.substeps ? &summary : nullptr);
            effectSeconds_[0] += secondsSince(start);
        } else {
            ok = integrator_->step(*this, t, h, q_[current_], u_[current_], q_[next], u_[next],
                                   ledger_.workNc);
        }
        if (ok && contacts_) ok = solveContacts(h, q_[current_], q_[next], u_[next]);
        if (!ok || (settings_.substeps > 1 && !(q_[next].allFinite() && u_[next].allFinite()))) {
            Divergence d;
            d.time = t + h;
            d.objectId = firstNonFinite(q_[next], u_[next]);
            d.what = ok ? "a non-finite value" : std::string(integrator_->info().name) + " failed";
            current_ = next;  // restoreFrameStart() reads the start from the right place
            restoreFrameStart();
            d.restoredTime = time_;
            divergence_ = d;
            integratorSeconds_ += secondsSince(stepStart);
            return false;
        }
        current_ = next;
    }
    integratorSeconds_ += secondsSince(stepStart);
    // Time as base + n·dt rather than a running sum, so that step 600 of dt = 1/60 is t = 10.
    ++stepsSinceTimeBase_;
    time_ = timeBase_ + static_cast<double>(stepsSinceTimeBase_) * settings_.dt;
    ++stepCount_;
    const bool good = checkEnergy(fused ? &summary : nullptr);
    if (fused && good) freeFallBound_ = summary;
    else freeFallBound_.reset();
    return good;
}

bool World::freeFallCannotDiverge() const {
    // Symplectic Euler in a uniform field changes the energy by exactly −½·h²·|g|²·Σm per
    // sub-step: it never grows, so only an overflow could diverge. From the last frame's
    // largest |v| and |x|, a frame of n sub-steps reaches at most |v| + n·h·|g| and
    // |x| + n·h·(that); when Σm times their squares stays far below the double range, no
    // value and no energy sum can overflow (or become NaN), and there is nothing to restore.
    if (!freeFallBound_ || !freeFallBound_->finite) return false;
    const Vec2 g = static_cast<const GravityEffect&>(*effects_[0]).g();
    const double gMax = std::max(std::abs(g.x()), std::abs(g.y()));
    const double v = freeFallBound_->maxAbsVelocity + settings_.dt * gMax;
    const double x = freeFallBound_->maxAbsPosition + settings_.dt * v;
    constexpr double kSafe = 1e280;
    const double m = std::max(totalDofMass_, 1.0);
    return v * v * m < kSafe && x * m < kSafe && x < kSafe;
}

bool World::fusedFreeFall() const {
    // Symplectic Euler under uniform gravity alone, nothing to touch: the commonest scene of
    // all (a fountain of particles, projectiles), and one where the generic step's separate
    // passes (write the accelerations, integrate, then sum the diagnostics) cost more than the
    // physics. The fused pass below computes exactly the same numbers in one sweep.
    return effects_.size() == 1 && dynamic_cast<const GravityEffect*>(effects_[0].get()) &&
           !contacts_ && integrator_->info().name == "symplectic_euler";
}

void World::freeFallStep(double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                         StateSummary* summary) {
    // v' = v + h·g, x' = x + h·v' (bit for bit what SymplecticEuler computes with a = g), and,
    // on a frame's last sub-step, the diagnostics of summarizeState() in the same pass.
    ++forceEvaluations_;
    const Vec2 g = static_cast<const GravityEffect&>(*effects_[0]).g();
    using A2 = Eigen::Array2d;
    const A2 hg(h * g.x(), h * g.y());
    const double* m = mass_.data();
    const double* q0p = q0.data();
    const double* u0p = u0.data();
    double* qp = q.data();
    double* up = u.data();
    const int particleEnd = layout_.boxBase();
    A2 ke0 = A2::Zero(), ke1 = A2::Zero(), mom0 = A2::Zero(), mom1 = A2::Zero();
    A2 xMax = A2::Zero(), vMax = A2::Zero();
    int i = 0;
    if (summary) {
        // Per-particle masses (half the bytes of the per-dof ones) for the diagnostics.
        const double* pm = particleMass_.data();
        for (; i + 4 <= particleEnd; i += 4) {
            const A2 v0 = Eigen::Map<const A2>(u0p + i) + hg;
            const A2 v1 = Eigen::Map<const A2>(u0p + i + 2) + hg;
            const A2 x0 = Eigen::Map<const A2>(q0p + i) + h * v0;
            const A2 x1 = Eigen::Map<const A2>(q0p + i + 2) + h * v1;
            Eigen::Map<A2>(up + i) = v0;
            Eigen::Map<A2>(up + i + 2) = v1;
            Eigen::Map<A2>(qp + i) = x0;
            Eigen::Map<A2>(qp + i + 2) = x1;
            const double m0 = pm[i / 2], m1 = pm[i / 2 + 1];
            ke0 += m0 * (v0 * v0);
            ke1 += m1 * (v1 * v1);
            mom0 += m0 * x0;
            mom1 += m1 * x1;
            vMax = vMax.max(v0.abs().max(v1.abs()));
            xMax = xMax.max(x0.abs().max(x1.abs()));
        }
    } else {
        for (; i + 2 <= particleEnd; i += 2) {
            const A2 v0 = Eigen::Map<const A2>(u0p + i) + hg;
            Eigen::Map<A2>(up + i) = v0;
            Eigen::Map<A2>(qp + i) = Eigen::Map<const A2>(q0p + i) + h * v0;
        }
    }
    for (; i < particleEnd; i += 2) {
        const A2 v0 = Eigen::Map<const A2>(u0p + i) + hg;
        const A2 x0 = Eigen::Map<const A2>(q0p + i) + h * v0;
        Eigen::Map<A2>(up + i) = v0;
        Eigen::Map<A2>(qp + i) = x0;
        if (summary) {
            const A2 m0 = Eigen::Map<const A2>(m + i);
            ke0 += m0 * v0 * v0;
            mom0 += m0 * x0;
            vMax = vMax.max(v0.abs());
            xMax = xMax.max(x0.abs());
        }
    }
    double angularKinetic = 0.0, angles = 0.0;
    for (int b = 0; b < layout_.dynamicBoxes; ++b) {
        const int k = layout_.boxDof(b);
        const A2 v0 = Eigen::Map<const A2>(u0p + k) + hg;
        const A2 x0 = Eigen::Map<const A2>(q0p + k) + h * v0;
        Eigen::Map<A2>(up + k) = v0;
        Eigen::Map<A2>(qp + k) = x0;
        up[k + 2] = u0p[k + 2];  // no torque: the spin is kept
        qp[k + 2] = q0p[k + 2] + h * up[k + 2];
        const A2 mb = Eigen::Map<const A2>(m + k);
        ke0 += mb * v0 * v0;
        mom0 += mb * x0;
        angularKinetic += m[k + 2] * up[k + 2] * up[k + 2];
        angles += qp[k + 2];
        vMax = vMax.max(v0.abs().max(A2::Constant(std::abs(up[k + 2]))));
        xMax = xMax.max(x0.abs().max(A2::Constant(std::abs(qp[k + 2]))));
    }
    if (!summary) return;
    // NaN compares false, so max() may drop it: finiteness is judged by the sums below, and
    // the bound is only used when they are finite.
    summary->maxAbsVelocity = vMax.maxCoeff();
    summary->maxAbsPosition = xMax.maxCoeff();
    summary->kinetic = 0.5 * ((ke0 + ke1).sum() + angularKinetic);
    const A2 moment = mom0 + mom1;
    summary->massMoment = Vec2(moment[0], moment[1]);
    summary->finite = std::isfinite(summary->kinetic) && moment.isFinite().all() && std::isfinite(angles);
}

bool World::solveContacts(double h, const Vec& q0, Vec& q, Vec& u) {
    // Contacts act after the smooth step as impulses (positions move by h·Δv); the energy
    // they add or remove is their work, booked in work_nc.
    const auto start = Clock::now();
    const double before = mechanicalEnergy(q, u);
    contacts_->solveSubstep(h, q0, q, u, settings_.contacts, integrator_->info().positionWeight);
    const double after = mechanicalEnergy(q, u);
    contactSeconds_ += secondsSince(start);
    if (!std::isfinite(after)) return true;  // reported by the finiteness check
    ledger_.workNc += after - before;
    return true;
}

void World::saveFrameStart(bool inPlace) {
    Checkpoint& c = frameStart_;
    c.inPlace = inPlace;
    c.time = time_;
    c.timeBase = timeBase_;
    c.stepsSinceTimeBase = stepsSinceTimeBase_;
    c.stepCount = stepCount_;
    c.ledger = ledger_;
    // With one sub-step the other state buffer keeps the frame start for free; with several it
    // is overwritten, so the start is copied (into memory sized once).
    c.hasState = settings_.substeps > 1 && !inPlace;
    if (c.hasState) {
        c.q = q_[current_];
        c.u = u_[current_];
    }
}

void World::restoreFrameStart() {
    const Checkpoint& c = frameStart_;
    // An in-place frame was proven unable to diverge (freeFallCannotDiverge); were it to
    // happen anyway, the other buffer holds an older good state, which is what is restored.
    assert(!c.inPlace);
    if (c.hasState) {
        q_[current_] = c.q;
        u_[current_] = c.u;
    } else {
        current_ = 1 - current_;
    }
    restoreScalars(c);
}

void World::restoreScalars(const Checkpoint& c) {
    time_ = c.time;
    timeBase_ = c.timeBase;
    stepsSinceTimeBase_ = c.stepsSinceTimeBase;
    stepCount_ = c.stepCount;
    ledger_ = c.ledger;
    growthStreak_ = 0;
    previousDrift_ = 0.0;
}

World::StateSummary World::summarizeState(const Vec& q, const Vec& u) const {
    // One pass over the state for the diagnostics: kinetic energy, the mass moment Σm·x (which
    // gives uniform gravity's potential without a pass of its own), and finiteness (a sum is
    // finite exactly when every term is). The particle range is [x y x y …], so 2-lane
    // accumulators keep x and y apart, and two of each let the adds overlap.
    const double* m = mass_.data();
    const double* qp = q.data();
    const double* up = u.data();
    using A2 = Eigen::Array2d;
    A2 ke0 = A2::Zero(), ke1 = A2::Zero(), mom0 = A2::Zero(), mom1 = A2::Zero();
    const int particleEnd = layout_.boxBase();
    int i = 0;
    for (; i + 4 <= particleEnd; i += 4) {
        const A2 m0 = Eigen::Map<const A2>(m + i), m1 = Eigen::Map<const A2>(m + i + 2);
        const A2 u0 = Eigen::Map<const A2>(up + i), u1 = Eigen::Map<const A2>(up + i + 2);
        ke0 += m0 * u0 * u0;
        ke1 += m1 * u1 * u1;
        mom0 += m0 * Eigen::Map<const A2>(qp + i);
        mom1 += m1 * Eigen::Map<const A2>(qp + i + 2);
    }
    for (; i < particleEnd; i += 2) {
        const A2 m0 = Eigen::Map<const A2>(m + i), u0 = Eigen::Map<const A2>(up + i);
        ke0 += m0 * u0 * u0;
        mom0 += m0 * Eigen::Map<const A2>(qp + i);
    }
    double angularKinetic = 0.0, angles = 0.0;
    for (int b = 0; b < layout_.dynamicBoxes; ++b) {
        const int k = layout_.boxDof(b);
        const A2 mb = Eigen::Map<const A2>(m + k), ub = Eigen::Map<const A2>(up + k);
        ke0 += mb * ub * ub;
        mom0 += mb * Eigen::Map<const A2>(qp + k);
        angularKinetic += m[k + 2] * up[k + 2] * up[k + 2];
        angles += qp[k + 2];
    }
    StateSummary summary;
    summary.kinetic = 0.5 * ((ke0 + ke1).sum() + angularKinetic);
    const A2 moment = mom0 + mom1;
    summary.massMoment = Vec2(moment[0], moment[1]);
    summary.finite = std::isfinite(summary.kinetic) && moment.isFinite().all() && std::isfinite(angles);
    return summary;
}

double World::kineticEnergy() const { return summarizeState(q_[current_], u_[current_]).kinetic; }

double World::potentialEnergy() const {
    return potentialEnergy(q_[current_], summarizeState(q_[current_], u_[current_]).massMoment);
}

double World::potentialEnergy(const Vec& q, const Vec2& massMoment) const {
    double energy = 0.0;
    for (const auto& e : effects_) {
        double fromMoment = 0.0;
        energy += e->potentialFromMassMoment(massMoment, fromMoment) ? fromMoment
                                                                     : e->potentialEnergy(q);
    }
    return energy;
}

double World::mechanicalEnergy(const Vec& q, const Vec& u) const {
    const StateSummary summary = summarizeState(q, u);
    return summary.kinetic + potentialEnergy(q, summary.massMoment);
}

void World::updateLedger(const Vec2& massMoment) {
    ledger_.potential = potentialEnergy(q_[current_], massMoment);
    ledger_.drift = ledger_.kinetic + ledger_.potential - ledger_.workNc - ledger_.initial;
    if (std::abs(ledger_.drift) > ledger_.maxAbsDrift) ledger_.maxAbsDrift = std::abs(ledger_.drift);
}

bool World::checkEnergy(const StateSummary* precomputed) {
    const StateSummary summary =
        precomputed ? *precomputed : summarizeState(q_[current_], u_[current_]);
    const bool finite = summary.finite;
    ledger_.kinetic = summary.kinetic;
    std::string what;
    bool runaway = false;
    if (finite) {
        updateLedger(summary.massMoment);
        const double drift = ledger_.drift;
        if (!std::isfinite(drift)) {
            what = "non-finite energy";
        } else {
            // The growth rule measures against the scene's own energy, not against work_nc: in
            // a damped blow-up the damping's work explodes as fast as the drift and would hide it.
            // (An in-place free-fall frame cannot gain energy: see freeFallCannotDiverge.)
            const bool growing = !frameStart_.inPlace && drift > kRunawayFactor * energyScale_ &&
                                 drift > kGrowth * previousDrift_;
            if (growing && growthStreak_ == 0) {
                // The growth may be a blow-up: remember where it started, the last good state.
                streakStart_ = frameStart_;
                streakStart_.hasState = true;
                if (!frameStart_.hasState) {
                    streakStart_.q = q_[1 - current_];
                    streakStart_.u = u_[1 - current_];
                }
            }
            growthStreak_ = growing ? growthStreak_ + 1 : 0;
            previousDrift_ = drift;
            runaway = growthStreak_ >= kStreak ||
                      (!frameStart_.inPlace &&
                       drift > kAbsurd * (energyScale_ + std::abs(ledger_.workNc)));
            if (runaway) what = "energy growing without bound";
        }
    } else {
        what = "a non-finite value";
    }
    if (what.empty()) return true;

    Divergence d;
    d.time = time_;
    d.objectId = finite ? mostEnergeticObject() : firstNonFinite(q_[current_], u_[current_]);
    if (d.objectId.empty()) d.objectId = mostEnergeticObject();  // energy overflowed first
    d.what = what;
    if (runaway && growthStreak_ >= kStreak) {
        q_[current_] = streakStart_.q;
        u_[current_] = streakStart_.u;
        restoreScalars(streakStart_);
    } else {
        restoreFrameStart();
    }
    d.restoredTime = time_;
    divergence_ = d;
    return false;
}

double World::estimateLocalError() {
    ensureLayout();
    const int n = layout_.dimension();
    if (n == 0) return 0.0;
    const IntegratorInfo& info = integrator_->info();
    if (!errorIntegrator_ || errorIntegrator_->info().name != info.name) {
        errorIntegrator_ = makeIntegrator(info.name);
        errorIntegrator_->reset(n);
    }
    for (int k = 0; k < 3; ++k) {
        if (errorQ_[k].size() != n) {
            errorQ_[k].resize(n);
            errorU_[k].resize(n);
            errorIntegrator_->reset(n);
        }
    }
    errorIntegrator_->setSettings(integrator_->settings());
    // The estimate is not part of the run: its force evaluations and time are not booked.
    const long long evaluations = forceEvaluations_;
    errorSavedSeconds_ = effectSeconds_;
    const double h = settings_.dt / settings_.substeps;
    const Vec& q = q_[current_];
    const Vec& u = u_[current_];
    double work = 0.0;
    bool ok = errorIntegrator_->step(*this, time_, h, q, u, errorQ_[0], errorU_[0], work);
    ok = ok && errorIntegrator_->step(*this, time_, 0.5 * h, q, u, errorQ_[1], errorU_[1], work);
    ok = ok && errorIntegrator_->step(*this, time_ + 0.5 * h, 0.5 * h, errorQ_[1], errorU_[1],
                                      errorQ_[2], errorU_[2], work);
    forceEvaluations_ = evaluations;
    effectSeconds_ = errorSavedSeconds_;
    if (!ok) return std::numeric_limits<double>::infinity();
    const double difference = (errorQ_[0] - errorQ_[2]).lpNorm<Eigen::Infinity>();
    const double p = std::max(1, info.order);
    return difference / (1.0 - std::pow(2.0, -p));
}

void World::resetEnergyBaseline() {
    ensureLayout();
    ledger_ = EnergyLedger{};
    ledger_.kinetic = kineticEnergy();
    ledger_.potential = potentialEnergy();
    ledger_.initial = ledger_.kinetic + ledger_.potential;
    // The scale against which drift is judged: every energy in the scene, and a floor of each
    // body moving at 1 m/s so that a scene at rest at the origin still has a scale.
    double scale = ledger_.kinetic + mass_.sum() * 0.5;
    for (const auto& e : effects_) scale += std::abs(e->potentialEnergy(q_[current_]));
    energyScale_ = scale;
    previousDrift_ = 0.0;
    growthStreak_ = 0;
}

std::string World::firstNonFinite(const Vec& q, const Vec& u) const {
    for (int i = 0; i < static_cast<int>(q.size()); ++i)
        if (!std::isfinite(q[i]) || !std::isfinite(u[i])) return objectAtDof(i);
    return {};
}

std::string World::mostEnergeticObject() const {
    const Vec& u = u_[current_];
    int best = -1;
    double bestEnergy = -1.0;
    for (int i = 0; i < static_cast<int>(u.size()); ++i) {
        const double e = mass_[i] * u[i] * u[i];
        if (e > bestEnergy) {
            bestEnergy = e;
            best = i;
        }
    }
    return objectAtDof(best);
}

std::vector<EffectCost> World::effectCosts() const {
    std::vector<EffectCost> costs;
    for (std::size_t i = 0; i < effects_.size(); ++i)
        costs.push_back({effects_[i]->name(), i < effectSeconds_.size() ? effectSeconds_[i] : 0.0});
    if (contacts_) costs.push_back({"contacts", contactSeconds_});
    return costs;
}

void World::resetProfile() {
    std::fill(effectSeconds_.begin(), effectSeconds_.end(), 0.0);
    contactSeconds_ = 0.0;
    integratorSeconds_ = 0.0;
}

}  // namespace phasebox
