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
    penalty_->bind(EffectWorldView{&layout_, &mass_, &bodies_.particles, &bodies_.boxes});
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
    for (const Box& b : bodies_.boxes)
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
    for (const Box& b : bodies_.boxes) {
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

void World::findPenaltyPairs() {
    const auto start = ProfileClock::now();
    const Vec& u = u_[current_];
    // Bounds grow by how far each body can move in the frame: its speed now, or at the frame's
    // end extrapolated from the last frame's change.
    if (penaltyVelocity_.size() != u.size()) penaltyVelocity_ = u;
    penaltyVelocity_ = 2.0 * u - penaltyVelocity_;
    contacts_->findPairs(bodies_, q_[current_], u, penaltyVelocity_, 1.0, settings_.dt,
                         settings_.contacts);
    penaltyVelocity_ = u;
    effectSeconds_.back() += secondsSince(start);
}

void World::collide(int next, int substeps) {
    const auto start = ProfileClock::now();
    if (settings_.contactModel == ContactModel::Kinematic) {
        contacts_->findPairs(bodies_, q_[current_], u_[current_], u_[next], 1.0 / substeps,
                             settings_.dt, settings_.contacts);
        kinematicImpulse_.setZero(layout_.dimension());  // summed over the frame's sub-steps
    } else
        contacts_->collide(bodies_, invMass_, q_[current_], u_[current_], u_[next], 1.0 / substeps,
                           settings_.dt, settings_.contacts);
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

void World::solveContacts(double h, int next) {
    // Contacts act after the smooth step as impulses and a bounded position correction. What
    // the impulses change (with the motion they cause) is physical work only where it takes
    // energy out (friction, restitution losses, an inelastic normal impulse): a contact cannot
    // do positive work. Energy the stage puts in is the solver's own, booked in correction with
    // the push-out that removes overlap (CONTRACT §6): a pile solved short of convergence, or a
    // resting body given back what symplectic Euler's step took, is never work_nc.
    const auto start = ProfileClock::now();
    Vec& q = q_[next];
    Vec& u = u_[next];
    const double before = mechanicalEnergy(q, u);
    contacts_->solveStep(h, q_[current_], u_[current_], q, u, settings_.contacts,
                         integrator_->info().positionWeight);
    const double after = mechanicalEnergy(q, u);
    withoutPushOut_ = q;
    contacts_->addPushOut(withoutPushOut_, -1.0);
    const double unpushed = mechanicalEnergy(withoutPushOut_, u);
    effectSeconds_.back() += secondsSince(start);
    if (!std::isfinite(after)) return;  // the guard reports it
    const double impulses = unpushed - before;
    ledger_.workNc += std::min(impulses, 0.0);
    ledger_.correction += (after - unpushed) + std::max(impulses, 0.0);
}

}  // namespace phasebox
