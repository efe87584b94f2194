// The world's diagnostics: the local error estimate the Accuracy Lab and the status bar show,
// the energy baseline, which object went non-finite or holds the most energy when the guard
// trips, the effects' costs and the step profile, and the expensive invariant checks.
#include "physics/contacts/ContactStage.h"
#include "physics/world/World.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace phasebox {

namespace {
using Clock = ProfileClock;
}  // namespace

// ---- diagnostics --------------------------------------------------------------------------

template <class Fn>
auto World::outsideTheRun(Fn&& fn) {
    // A diagnostic is not part of the run: its force evaluations and time are not booked, and
    // the joints keep what the run's evaluations left: their forces (the error estimate's trial
    // steps have no contacts: a car's axles pulled nothing there, and the free-body view and
    // force(JOINT) showed that), their cached rotations (tst_determinism: a chain stepped with
    // the estimate after every step, as the app does, ended elsewhere than one stepped without)
    // and the limits the step holds. The stability advisor's one evaluation between steps was
    // left out of this until tst_determinism's chain and bridge with the advisor after every
    // step, and the ragdoll in tst_window_run, ended elsewhere than runs without it.
    const long long evaluations = forceEvaluations_;
    const std::vector<double> seconds = effectSeconds_;
    if (joints_) joints_->keepEvaluation(keptJointEvaluation_);
    auto result = fn();
    forceEvaluations_ = evaluations;
    effectSeconds_ = seconds;
    if (joints_) joints_->restoreEvaluation(keptJointEvaluation_);
    return result;
}

double World::estimateLocalError() {
    ensureLayout();
    return outsideTheRun([&] {
        // Of the sub-step the run takes: with the joints' own sub-steps of the last frame (a
        // step of the user's dt alone can be beyond the method's stability on a chain that
        // needs them).
        const int jointSubsteps = joints_ ? std::max(jointSubsteps_, pulledSubsteps_) : 1;
        return errorEstimator_.estimate(*this, *integrator_, clock_.time,
                                        settings_.dt / (settings_.substeps * jointSubsteps),
                                        q_[current_], u_[current_]);
    });
}

void World::diagnosticForcesAndJacobians(Vec& force, ForceJacobians& jacobians) {
    ensureLayout();
    outsideTheRun([&] {
        return forcesAndJacobians(clock_.time, q_[current_], u_[current_], force, jacobians);
    });
}

void World::resetEnergyBaseline() {
    ensureLayout();
    ledger_.rebase(kineticEnergy(), potentialEnergy());
    // The scale against which drift is judged: every energy in the scene, and a floor of each
    // body moving at 1 m/s so that a scene at rest at the origin still has a scale.
    double bodyMass = 0.0;  // Σm over bodies: each point's mass sits on two DOFs, a box's too
    for (int i = 0; i < layout_.dimension(); i += i < pointDofs() ? 2 : 3) bodyMass += mass_[i];
    double scale = ledger_.kinetic + 0.5 * bodyMass;
    for (const auto& e : effects_) scale += std::abs(e->potentialEnergy(q_[current_]));
    guard_.setEnergyScale(scale);
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
    if (contacts_ && effectSeconds_.size() > effects_.size())
        costs.push_back({"contacts", effectSeconds_.back()});
    return costs;
}

void World::resetProfile() {
    std::fill(effectSeconds_.begin(), effectSeconds_.end(), 0.0);
    profile_.reset();
}

// Expensive invariants (PHASEBOX_EXPENSIVE_CHECKS): after the stages that end a step, the
// layout is consistent with the objects, the state kept is finite, and the ledger balances
// when recomputed from scratch (which checks the summary the integrator fused into its pass).
void World::checkInvariants([[maybe_unused]] StepStage after) const {
#if PHASEBOX_EXPENSIVE_CHECKS
    auto fail = [](const char* what) {
        std::fprintf(stderr, "phasebox: invariant violated: %s\n", what);
        std::abort();
    };
    const int n = layout_.dimension();
    if (q_[current_].size() != n || u_[current_].size() != n || mass_.size() != n ||
        invMass_.size() != n)
        fail("state vectors do not match the layout");
    if (layout_.dynamicParticles != static_cast<int>(dynamicParticles_.size()) ||
        layout_.dynamicRigidBodies != static_cast<int>(dynamicRigidBodies_.size()))
        fail("layout counts do not match the objects");
    for (int k = 0; k < layout_.dynamicParticles; ++k)
        if (bodies_.particles[dynamicParticles_[k]].dof != layout_.particleDof(k))
            fail("a particle's dof does not match the layout");
    for (int k = 0; k < layout_.dynamicRigidBodies; ++k)
        if (bodies_.rigidBodies[dynamicRigidBodies_[k]].dof != layout_.rigidDof(k))
            fail("a box's dof does not match the layout");
    if (!(mass_.array() > 0.0).all() || !mass_.allFinite())
        fail("a mass is not positive and finite");
    if (after == StepStage::Guard) {
        // Whatever the verdict, the state the world keeps is a good one.
        if (!q_[current_].allFinite() || !u_[current_].allFinite())
            fail("the kept state is not finite");
    }
    if (after == StepStage::Ledger && std::isfinite(ledger_.drift)) {
        // Recomputed term by term, without the mass-moment shortcut.
        const Vec& q = q_[current_];
        const Vec& u = u_[current_];
        double kinetic = sleepingKinetic_;  // the bodies asleep hold theirs
        for (int i = 0; i < n; ++i) kinetic += 0.5 * mass_[i] * u[i] * u[i];
        double potential = sleepingPotential_;
        for (const auto& e : effects_) potential += e->potentialEnergy(q);
        potential += contactPotential(q);
        const double drift =
            kinetic + potential - ledger_.workNc - ledger_.correction - ledger_.initial;
        const double scale = 1.0 + std::abs(kinetic) + std::abs(potential) +
                             std::abs(ledger_.workNc) + std::abs(ledger_.correction) +
                             std::abs(ledger_.initial);
        if (std::abs(kinetic - ledger_.kinetic) > 1e-9 * scale ||
            std::abs(drift - ledger_.drift) > 1e-9 * scale)
            fail("the energy ledger does not balance");
    }
#endif
}

}  // namespace phasebox
