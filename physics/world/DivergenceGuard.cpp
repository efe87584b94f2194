#include "physics/world/DivergenceGuard.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace phasebox {

namespace {
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

void DivergenceGuard::setEnergyScale(double scale) {
    energyScale_ = scale;
    forgetGrowth();
}

void DivergenceGuard::forgetGrowth() {
    previousDrift_ = 0.0;
    growthStreak_ = 0;
}

void DivergenceGuard::beginFrame(const SimulationClock& clock, const EnergyLedger& ledger,
                                 const Vec& q, const Vec& u, bool copyState) {
    frameStart_.clock = clock;
    frameStart_.ledger = ledger;
    frameStart_.hasState = copyState;
    if (copyState) {  // into memory sized once
        frameStart_.q = q;
        frameStart_.u = u;
    }
}

DivergenceGuard::Verdict DivergenceGuard::judge(const EnergyLedger& ledger, const Vec& frameStartQ,
                                                const Vec& frameStartU) {
    // Energy a solver creates runs away like energy an integrator creates: both count.
    const double drift = std::max(ledger.drift, ledger.correction);
    if (!std::isfinite(drift)) return Verdict::RestoreFrameStart;
    // The growth rule measures against the scene's own energy, not against work_nc: in a
    // damped blow-up the damping's work explodes as fast as the drift and would hide it.
    const bool growing = drift > kRunawayFactor * energyScale_ && drift > kGrowth * previousDrift_;
    if (growing && growthStreak_ == 0) {
        // The growth may be a blow-up: remember where it started, the last good state.
        runawayStart_ = frameStart_;
        runawayStart_.hasState = true;
        if (!frameStart_.hasState) {
            runawayStart_.q = frameStartQ;
            runawayStart_.u = frameStartU;
        }
    }
    growthStreak_ = growing ? growthStreak_ + 1 : 0;
    previousDrift_ = drift;
    if (growthStreak_ >= kStreak) return Verdict::RestoreRunawayStart;
    if (drift > kAbsurd * (energyScale_ + std::abs(ledger.workNc)))
        return Verdict::RestoreFrameStart;
    return Verdict::Good;
}

}  // namespace phasebox
