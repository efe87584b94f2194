// The world's contact stages under each contact model (CONTRACT §6): finding pairs, the impulse
// solver after the smooth step, the kinematic response, and the penalty force's set-up (the
// force itself runs inside the integrator, through the world's force channel).
#include "physics/contacts/ContactStage.h"
#include "physics/contacts/KinematicResponse.h"
#include "physics/contacts/PenaltyContacts.h"
#include "physics/world/World.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace phasebox {

void World::configureContactModel() {
    const ContactModel model = settings_.contactModel;
    if (contacts_ && model != ContactModel::Impulse) contacts_->forgetSolver();
    if (!contacts_ || model != ContactModel::Penalty) {
        penalty_.reset();
        return;
    }
    if (!penalty_) penalty_ = std::make_unique<PenaltyContacts>();
    penalty_->attach(contacts_.get(), &bodies_);
    penalty_->bind(EffectWorldView{&layout_, &mass_, &bodies_.particles, &bodies_.rigidBodies});
    penalty_->setParameters(penaltyStiffness(), settings_.contactDamping,
                            settings_.dt / settings_.substeps);
    // The pairs the force reads, found now so that the energy and the advisor see the overlaps
    // of the current state before the first step.
    penaltyVelocity_ = u_[current_];
    findPenaltyPairs();
}

double World::penaltyStiffness() const {
    if (settings_.contactStiffness > 0.0) return settings_.contactStiffness;
    double lightest = std::numeric_limits<double>::infinity();
    for (const Particle& p : bodies_.particles)
        if (!p.pinned && p.radius > 0.0) lightest = std::min(lightest, p.mass);
    for (const RigidBody& b : bodies_.rigidBodies)
        if (!b.isStatic) lightest = std::min(lightest, b.mass);
    if (!std::isfinite(lightest)) return 0.0;
    return PenaltyContacts::automaticStiffness(lightest, settings_.dt / settings_.substeps);
}

double World::anticipatedContactOmegaSquared() const {
    if (!penalty_) return 0.0;
    const double k = penalty_->stiffness();
    double omega2 = 0.0;
    for (const Particle& p : bodies_.particles)
        if (!p.pinned && p.radius > 0.0) omega2 = std::max(omega2, k / p.mass);
    for (const RigidBody& b : bodies_.rigidBodies) {
        if (b.isStatic) continue;
        if (b.shape == RigidShape::Disk) {
            omega2 = std::max(omega2, k / b.mass);
            continue;
        }
        // Two points a width w apart: 2k/m along the normal, and k·w²/(2·I) rocking on them;
        // the widest side down (a polygon's bounding square) rocks stiffest.
        const double w = std::max(b.size.x(), b.size.y());
        omega2 = std::max({omega2, 2.0 * k / b.mass, k * w * w / (2.0 * b.inertia)});
    }
    return omega2;
}

bool World::activeSetChanged(const Vec& q0, const Vec& q1) {
    return penalty_ && penalty_->overlappingPoints(q0) != penalty_->overlappingPoints(q1);
}

double World::contactPotential(const Vec& q) const {
    return penalty_ ? penalty_->potentialEnergy(q) : 0.0;
}

Vec2 World::contactForce(int dof) const {
    if (!contacts_ || layoutDirty_ || dof < 0 || dof + 1 >= layout_.dimension())
        return Vec2::Zero();
    if (showingFrame_) {
        const std::vector<int>& dofs = shownForces_.contactDofs;
        const auto at = std::lower_bound(dofs.begin(), dofs.end(), dof);
        if (at == dofs.end() || *at != dof) return Vec2::Zero();
        const std::size_t k = 2 * static_cast<std::size_t>(at - dofs.begin());
        return Vec2(shownForces_.contactXY[k], shownForces_.contactXY[k + 1]);
    }
    switch (settings_.contactModel) {
        case ContactModel::Penalty:
            return penalty_ ? penalty_->forceOn(q_[current_], u_[current_], dof) : Vec2::Zero();
        case ContactModel::Kinematic:
            return kinematicImpulse_.size() > dof + 1
                       ? Vec2(kinematicImpulse_.segment<2>(dof) / settings_.dt)
                       : Vec2::Zero();
        case ContactModel::Impulse:
            break;
    }
    // The solver's bodies are this step's touching ones: a scan, no lookup table to keep in
    // step with the solver's list.
    for (const SolverBody& b : contacts_->solver().bodies())
        if (b.dof == dof) return b.stepImpulse / settings_.dt;
    return Vec2::Zero();
}

void World::contactForces(FrameForces& out) const {
    out.contactDofs.clear();
    out.contactXY.clear();
    if (!contacts_ || layoutDirty_) return;
    // A -0.0 is kept too, so that a frame gives back the very bits contactForce() gave.
    const auto keep = [&](int dof, const Vec2& f) {
        if (f.x() == 0.0 && f.y() == 0.0 && !std::signbit(f.x()) && !std::signbit(f.y())) return;
        out.contactDofs.push_back(dof);
        out.contactXY.push_back(f.x());
        out.contactXY.push_back(f.y());
    };
    const int dimension = layout_.dimension();
    if (showingFrame_ || settings_.contactModel != ContactModel::Impulse) {
        // Penalty: one evaluation for every body (each entry sums its terms in the order
        // forceOn() does); kinematic and a shown frame: per body, as contactForce() reads them.
        Vec penalty;
        if (!showingFrame_ && settings_.contactModel == ContactModel::Penalty && penalty_) {
            penalty = Vec::Zero(dimension);
            penalty_->addForces(clock_.time, q_[current_], u_[current_], penalty);
        }
        const auto body = [&](int dof) {
            keep(dof, penalty.size() > 0 ? Vec2(penalty.segment<2>(dof)) : contactForce(dof));
        };
        for (int dof = 0; dof < layout_.rigidBase(); dof += 2) body(dof);
        for (int dof = layout_.rigidBase(); dof < dimension; dof += 3) body(dof);
        return;
    }
    // Impulse: the solver's bodies, in the order of their state, the first of a dof as
    // contactForce() finds it.
    const std::vector<SolverBody>& bodies = contacts_->solver().bodies();
    std::vector<std::pair<int, Vec2>> found;
    found.reserve(bodies.size());
    for (const SolverBody& b : bodies)
        if (b.dof >= 0 && b.dof + 1 < dimension)
            found.emplace_back(b.dof, b.stepImpulse / settings_.dt);
    std::stable_sort(found.begin(), found.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < found.size(); ++i)
        if (i == 0 || found[i].first != found[i - 1].first) keep(found[i].first, found[i].second);
}

void World::findPenaltyPairs() {
    const auto start = ProfileClock::now();
    const Vec& u = u_[current_];
    // Bounds grow by how far each body can move in the frame: its speed now, or at the frame's
    // end extrapolated from the last frame's change.
    if (penaltyVelocity_.size() != u.size()) penaltyVelocity_ = u;
    penaltyVelocity_ = 2.0 * u - penaltyVelocity_;
    contacts_->findPairs(bodies_, q_[current_], u, penaltyVelocity_, 1.0, settings_.dt,
                         settings_.contacts);
    if (sleepingBodies_ > 0) contacts_->findReachedSleepers(bodies_, settings_.contacts);
    penaltyVelocity_ = u;
    effectSeconds_.back() += secondsSince(start);
}

void World::collide(int next, int substeps) {
    const auto start = ProfileClock::now();
    if (settings_.contactModel == ContactModel::Kinematic) {
        contacts_->findPairs(bodies_, q_[current_], u_[current_], u_[next], 1.0 / substeps,
                             settings_.dt, settings_.contacts);
        if (sleepingBodies_ > 0) contacts_->findReachedSleepers(bodies_, settings_.contacts);
        kinematicImpulse_.setZero(layout_.dimension());  // summed over the frame's sub-steps
    } else {
        // The trial's contacts, where its inputs were these (primeContactForces()).
        const bool found = trialSubsteps_ == substeps && sameBits(trialNextU_, u_[next]);
        trialSubsteps_ = 0;
        if (!found)
            contacts_->collide(bodies_, invMass_, q_[current_], u_[current_], u_[next],
                               1.0 / substeps, settings_.dt, settings_.contacts);
        // What a jointed contact's held force is bounded by (ContactSolver::setWeightField).
        contacts_->setWeightField(uniformField().norm());
        heldValid_ = true;  // the solver's bodies are of this layout from now on
    }
    effectSeconds_.back() += secondsSince(start);
}

void World::solveKinematic(int next) {
    // No forces: the push-out moves positions (its energy is correction), the impulses reflect
    // and scale velocities (what they take out is work_nc; anything they put in, which only an
    // order of overlapping contacts can do, is correction).
    const auto start = ProfileClock::now();
    Vec& q = q_[next];
    Vec& u = u_[next];
    const std::vector<TouchingManifold>& overlaps = contacts_->overlaps(bodies_, q);
    if (!overlaps.empty()) {
        const double before = mechanicalEnergy(q, u);
        separateKinematically(overlaps, invMass_, q);
        const double separated = mechanicalEnergy(q, u);
        kinematicImpulse_ -= mass_.cwiseProduct(u);
        reflectKinematically(overlaps, invMass_, u);
        kinematicImpulse_ += mass_.cwiseProduct(u);
        const double after = mechanicalEnergy(q, u);
        if (std::isfinite(after)) {
            ledger_.correction += separated - before;
            ledger_.workNc += std::min(after - separated, 0.0);
            ledger_.correction += std::max(after - separated, 0.0);
        }
    }
    effectSeconds_.back() += secondsSince(start);
}

void World::primeContactForces(StageTimer& timer) {
    // The first step after a load or an edit knows no contact force to hold: a body placed on
    // the floor would fall into it in the method's step and be pushed back by the solve, and the
    // books would show both. So the forces are found first by a trial of the frame's first
    // sub-step from its start (the method, the contacts found and solved), which leaves the
    // state, the clock, the ledger and the counters as they were; the step then holds them.
    trialSubsteps_ = 0;  // a trial's contacts serve its own step only
    if (!contacts_ || heldValid_ || settings_.contactModel != ContactModel::Impulse) return;
    timer.start(StepStage::SolveContacts);
    const int next = 1 - current_;
    const int substeps = settings_.substeps;
    const double h = settings_.dt / substeps;
    const EnergyLedger ledger = ledger_;
    const long long evaluations = forceEvaluations_;
    const std::vector<double> seconds = effectSeconds_;
    holding_ = false;
    // Bodies started inside each other (a pile at one point) have no support to find: the trial
    // stops at the contacts, and the step meets them as it would have.
    if (integrate(clock_.time, h, next, nullptr)) {
        collide(next, substeps);
        if (!contacts_->anyDeepOverlap()) {
            contacts_->solveStep(h, q_[current_], u_[current_], q_[next], u_[next],
                                 settings_.contacts, integrator_->positionWeight(), false);
            contacts_->primeHeld();
        } else {
            // Nothing was held or solved: the step's first sub-step will be this one, and its
            // collide this collide (a pile started at one point spent 40 to 80 ms a second time
            // on it), unless the joints move the bodies first or the frame is cut otherwise.
            trialNextU_ = u_[next];
            trialSubsteps_ = substeps;
        }
    }
    ledger_ = ledger;
    forceEvaluations_ = evaluations;
    effectSeconds_ = seconds;
    integrator_->reset(layout_.dimension());  // an adaptive method's step history: not the trial's
}

void World::holdContactForces() {
    // The impulse model's contact forces belong to the method's step (CONTRACT §3): the forces
    // of the last solve (its accumulated impulses per inner sub-step, as Box2D warm-starts them)
    // act in every evaluation as a force held over the step, so a body at rest on its support
    // stays at rest in the method itself, whatever the method, and the method's books show no
    // error for it. A constant force has no Jacobian; its work (friction on a sliding body) is
    // the contacts' (bookHeldWork()).
    holding_ = false;
    if (!heldValid_ || !contacts_ || settings_.contactModel != ContactModel::Impulse) return;
    heldForce_.setZero();
    holding_ = contacts_->solver().addHeldForces(heldForce_);
}

void World::holdMotorTorques() {
    // A motor is a joint's force: a method that takes the joints' force at the step's end
    // (backward Euler) meets it there too (driveMotors() from nothing). Held in that method's
    // step, the torque pair turned bodies the joints did not hold within it, and a motor
    // pushing on its hinge's limit spun the free pair it joins (tst_joints).
    motorsHeld_ = false;
    if (joints_ && joints_->hasMotors() && !integrator_->info().constraintsAtEnd) {
        heldMotor_.setZero();
        motorsHeld_ = joints_->addHeldMotorTorques(heldMotor_);
    }
}

void World::bookHeldWork(double h, int next) {
    // A force held over the step changes every method's velocities by h·W·F, and so the kinetic
    // energy by exactly F·h·(u0 + u1)/2: that is its work on the method's path, whatever the
    // method. It is the contacts' work, booked with what the solver changes after it
    // (solveContacts()): a held force the solver takes back again (a body that left its
    // support) nets to nothing; a body at rest books nothing.
    heldWork_ = 0.0;
    const Vec& u0 = u_[current_];
    const Vec& u1 = u_[next];
    if (motorsHeld_) {
        // The motors' held torques push on the method's path: their work is the motors' (a
        // motor's push is work, in or out), booked at once; the rest of a motor's work is
        // driveMotors()' change of the kinetic energy (solveJoints()).
        double work = 0.0;
        for (int i = 0; i < static_cast<int>(heldMotor_.size()); ++i)
            if (heldMotor_[i] != 0.0) work += heldMotor_[i] * (u0[i] + u1[i]);
        ledger_.workNc += 0.5 * h * work;
        motorsHeld_ = false;
    }
    if (!holding_) return;
    double work = 0.0;
    for (int i = 0; i < static_cast<int>(heldForce_.size()); ++i)
        if (heldForce_[i] != 0.0) work += heldForce_[i] * (u0[i] + u1[i]);
    heldWork_ = 0.5 * h * work;
}

void World::releaseHeldForces(double h, int next, bool collided) {
    // The solver takes the held forces of the contacts it has (found again at the frame's start,
    // their impulses carried over) as the part of its warm start the method's step has applied
    // already. A force held for a contact that is gone (a body lifted off) is taken back here:
    // its share of the step, h·W·F on the velocities and positionWeight·h² on the positions
    // (the method's response to a constant force). A joint's answer to the held force stays: a
    // cart rests on its wheels in the method's step too.
    if (!holding_) return;
    // Every point that held a force was found again (a pile at rest, step after step): the
    // contacts account for all of it, and nothing is taken back.
    if (collided && contacts_->heldCarried()) return;
    Vec& q = q_[next];
    Vec& u = u_[next];
    heldForce_ *= -1.0;  // what the solver's contacts do not account for: held − accounted
    contacts_->solver().addHeldForces(heldForce_);
    const double weight = integrator_->positionWeight() * h;
    for (int i = 0; i < static_cast<int>(heldForce_.size()); ++i) {
        if (heldForce_[i] == 0.0) continue;
        const double dv = -h * invMass_[i] * heldForce_[i];
        u[i] -= dv;
        q[i] -= weight * dv;
    }
}

void World::solveConstraints(double h, int collideSubsteps, int next, StageTimer& timer) {
    // The held forces' share of the method's kinetic energy, read where the method's velocities
    // are its own: straight after it, or after the joints' projection for a method that takes
    // their force at the step's end (there it is the method's constraint force).
    const bool constraintsAtEnd = integrator_->info().constraintsAtEnd;
    if (!constraintsAtEnd) bookHeldWork(h, next);
    if (joints_) {
        // The joints complete the method's step before anything else moves the bodies (SHAKE,
        // the velocities onto the tangent, the motors): what they change is booked as the
        // joints' own, and SHAKE answers only the method's drift.
        timer.start(StepStage::SolveJoints);
        solveJoints(h, next);
    }
    if (constraintsAtEnd) bookHeldWork(h, next);
    if (!contacts_ || penalty_) {
        holding_ = false;
        return;
    }
    // The contacts' booking starts from the method's end: a held force that holds a body
    // where it is books nothing.
    const double before = mechanicalEnergy(q_[next], u_[next]);
    if (collideSubsteps > 0) {
        // Once per frame, after the first sub-step shows where the bodies are heading.
        timer.start(StepStage::Collide);
        collide(next, collideSubsteps);
    }
    timer.start(StepStage::SolveContacts);
    const bool held = holding_;
    releaseHeldForces(h, next, collideSubsteps > 0);
    holding_ = false;
    // Contacts move jointed bodies apart, and the joints answer (rejoin()): the two trade
    // energy back and forth, and what counts is their net change, booked once after both:
    // taken out, work_nc; put in, correction.
    const bool kinematic = settings_.contactModel == ContactModel::Kinematic;
    const bool both = joints_ && (kinematic || contacts_->touching());
    const EnergyLedger booked = ledger_;
    if (both) {
        beforeContactsQ_ = q_[next];  // same sizes after the first: no allocation
        beforeContactsU_ = u_[next];
    }
    if (kinematic)
        solveKinematic(next);
    else
        solveContacts(h, next, before, held);
    if (!both) return;
    timer.start(StepStage::SolveJoints);
    // Where the contacts moved nothing (every point speculative or already separating), the
    // joints' state stands as solveJoints() left it: a relax asks no more of a contact than
    // the solve did, so the rounds would change nothing either.
    if (!sameBits(beforeContactsQ_, q_[next]) || !sameBits(beforeContactsU_, u_[next]))
        rejoin(next);
    const double after = mechanicalEnergy(q_[next], u_[next]);
    if (std::isfinite(after)) {
        const double net = after - before + heldWork_;
        ledger_.workNc = booked.workNc + std::min(net, 0.0);
        ledger_.correction = booked.correction + std::max(net, 0.0);
    }
}

void World::solveContacts(double h, int next, double before, bool held) {
    // The impulses and a bounded position correction answer what the held forces did not. What
    // they change (with the motion they cause), and the held forces' work in the method's step,
    // is physical work only where it takes energy out
    // (friction, restitution losses, an inelastic normal impulse): a contact cannot do positive
    // work. Energy the stage puts in is the solver's own, booked in correction with the
    // push-out that removes overlap (CONTRACT §6): a pile solved short of convergence is never
    // work_nc.
    const auto start = ProfileClock::now();
    Vec& q = q_[next];
    Vec& u = u_[next];
    contacts_->solveStep(h, q_[current_], u_[current_], q, u, settings_.contacts,
                         integrator_->positionWeight(), held);
    const double after = mechanicalEnergy(q, u);
    withoutPushOut_ = q;
    contacts_->addPushOut(withoutPushOut_, -1.0);
    const double unpushed = mechanicalEnergy(withoutPushOut_, u);
    effectSeconds_.back() += secondsSince(start);
    if (!std::isfinite(after)) return;  // the guard reports it
    const double impulses = unpushed - before + heldWork_;
    ledger_.workNc += std::min(impulses, 0.0);
    ledger_.correction += (after - unpushed) + std::max(impulses, 0.0);
}

}  // namespace phasebox
