#pragma once
// The energy ledger of CONTRACT.md §2 and §6: kinetic and potential energy, the physical work
// of the non-conservative forces (work_nc), the energy that position correction of contacts
// and joints put in or took out (correction), and drift = total − initial − work_nc −
// correction, the integrator's own error. Nothing a solver does is hidden in work_nc.

#include "physics/core/StateSummary.h"
#include "physics/effects/Effect.h"

#include <memory>
#include <vector>

namespace phasebox {

struct EnergyLedger {
    double kinetic = 0.0;
    double potential = 0.0;
    double workNc = 0.0;
    double correction = 0.0;
    double drift = 0.0;
    double maxAbsDrift = 0.0;
    double initial = 0.0;  // kinetic + potential at the baseline (t = 0)

    // Books the end state of a step: its summary and its potential energy.
    void close(const StateSummary& state, double potentialEnergy);
    // Makes (kinetic, potential) the baseline: drift 0, work_nc 0, correction 0.
    void rebase(double kineticEnergy, double potentialEnergy);
    // Keeps the drift continuous across an edit (the edit itself is not integration error).
    void carryOver(double kineticEnergy, double potentialEnergy);
};

// The potential energy of every effect in state q; mass moment Σm·x lets uniform fields answer
// without a pass over the state.
double potentialEnergy(const std::vector<std::unique_ptr<Effect>>& effects, const Vec& q,
                       const Vec2& massMoment);

}  // namespace phasebox
