#include "physics/world/EnergyLedger.h"

#include <cmath>

namespace phasebox {

void EnergyLedger::close(const StateSummary& state, double potentialEnergy) {
    kinetic = state.kinetic;
    potential = potentialEnergy;
    drift = kinetic + potential - workNc - correction - initial;
    if (std::abs(drift) > maxAbsDrift) maxAbsDrift = std::abs(drift);
}

void EnergyLedger::rebase(double kineticEnergy, double potentialEnergy) {
    *this = EnergyLedger{};
    kinetic = kineticEnergy;
    potential = potentialEnergy;
    initial = kinetic + potential;
}

void EnergyLedger::carryOver(double kineticEnergy, double potentialEnergy) {
    kinetic = kineticEnergy;
    potential = potentialEnergy;
    initial = kinetic + potential - workNc - correction - drift;
}

double potentialEnergy(const std::vector<std::unique_ptr<Effect>>& effects, const Vec& q,
                       const Vec2& massMoment) {
    double energy = 0.0;
    for (const auto& e : effects) {
        double fromMoment = 0.0;
        energy +=
            e->potentialFromMassMoment(massMoment, fromMoment) ? fromMoment : e->potentialEnergy(q);
    }
    return energy;
}

}  // namespace phasebox
