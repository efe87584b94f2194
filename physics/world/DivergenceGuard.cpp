#include "physics/world/DivergenceGuard.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace phasebox {

namespace {
// CONTRACT §2: a step diverges when |drift| or |correction| exceeds kRunawayFactor times E₀ (the
// scene's energy scale plus the physical work put in since it was taken). The factor is high
// because a stable method near its limit swings far: symplectic Euler at ω·h = 1.99 is bounded
// but its energy error reaches 200 times the oscillator's energy.
constexpr double kRunawayFactor = 1e3;
}  // namespace

std::string Divergence::message() const {
    std::ostringstream out;
    out << "the simulation diverged at t = " << time << " s";
    if (!objectId.empty()) out << " in object \"" << objectId << "\"";
    out << " (" << what << "); the state was restored to t = " << restoredTime << " s.";
    if (!straightFrom.empty()) {
        out << " The joints from \"" << straightFrom << "\" to \"" << straightTo
            << "\" hold a chain pulled straight between two fixed points: it cannot sag without "
               "stretching, and the forces that keep it straight grow without bound as it moves. "
               "Start the chain with some sag or free one of its ends; else try";
    } else {
        out << " Try";
    }
    out << " a smaller dt, more sub-steps, or an implicit integrator (implicit_euler).";
    return out.str();
}

void DivergenceGuard::setEnergyScale(double scale) {
    energyScale_ = scale;
    forgetGrowth();
}

void DivergenceGuard::forgetGrowth() {
    beyondScale_ = false;
    workPutIn_ = 0.0;
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
    const double worst = std::max(std::abs(ledger.drift), std::abs(ledger.correction));
    if (!std::isfinite(worst)) return Verdict::RestoreFrameStart;
    // E₀ grows with the physical work put in (a motor, the wind): what it adds is not a
    // runaway of the method.
    workPutIn_ += std::max(0.0, ledger.workNc - frameStart_.ledger.workNc);
    const double scale = divergenceScale();
    if (worst > scale) {
        if (!beyondScale_) {
            // The frame start is the last state at which both were still within E₀: where a
            // runaway begins, and what a divergence restores.
            runawayStart_ = frameStart_;
            runawayStart_.hasState = true;
            if (!frameStart_.hasState) {
                runawayStart_.q = frameStartQ;
                runawayStart_.u = frameStartU;
            }
            beyondScale_ = true;
        }
    } else {
        beyondScale_ = false;
    }
    return worst > kRunawayFactor * scale ? Verdict::RestoreRunawayStart : Verdict::Good;
}

}  // namespace phasebox
