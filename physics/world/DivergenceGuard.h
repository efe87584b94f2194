#pragma once
// The divergence guard (CONTRACT.md §2): after each step it judges the energy ledger, and when
// the simulation has blown up (|drift| or |correction| above 10³·E₀) it says which good state to
// go back to: the start of the last step at which both were still within E₀.

#include "physics/core/Types.h"
#include "physics/world/EnergyLedger.h"

#include <string>

namespace phasebox {

struct Divergence {
    double time = 0.0;          // when the bad value appeared
    std::string objectId;       // the first object where it appeared
    std::string what;           // "non-finite velocity", "energy growing without bound", …
    double restoredTime = 0.0;  // the state was restored to this time
    // Where hinges or rods hold a chain pulled straight between two fixed points (a sag or a
    // free end is what helps there): the ids of its first and last joints, else empty
    // (World::nameStraightChain).
    std::string straightFrom, straightTo;
    std::string message() const;
};

// The world's clock: time as base + n·dt rather than a running sum, so that step 600 of
// dt = 1/60 is t = 10.
struct SimulationClock {
    double time = 0.0;
    double timeBase = 0.0;
    long long stepsSinceTimeBase = 0;
    long long stepCount = 0;
};

class DivergenceGuard {
public:
    // A state to go back to. Its q and u are kept only when asked (copyState): with one
    // sub-step the world's second state buffer still holds the frame start for free.
    struct Checkpoint {
        Vec q, u;
        bool hasState = false;
        SimulationClock clock;
        EnergyLedger ledger;
    };
    enum class Verdict { Good, RestoreFrameStart, RestoreRunawayStart };

    // E₀ without the work put in since (set at the baseline); forgets any runaway.
    void setEnergyScale(double scale);
    double energyScale() const { return energyScale_; }
    // E₀ of CONTRACT §2: the scale plus the physical work put in since it was taken.
    double divergenceScale() const { return energyScale_ + workPutIn_; }

    void beginFrame(const SimulationClock& clock, const EnergyLedger& ledger, const Vec& q,
                    const Vec& u, bool copyState);
    const Checkpoint& frameStart() const { return frameStart_; }
    const Checkpoint& runawayStart() const { return runawayStart_; }

    // Judges the ledger at the end of the frame. frameStartQ/U are where the frame start lives
    // when it was not copied (the world's other buffer), kept should the runaway begin here.
    Verdict judge(const EnergyLedger& ledger, const Vec& frameStartQ, const Vec& frameStartU);
    // A non-finite value: back to where a runaway began if one is under way, else to the
    // frame start.
    Verdict onNonFinite() const {
        return beyondScale_ ? Verdict::RestoreRunawayStart : Verdict::RestoreFrameStart;
    }
    // After a restore or an edit: the runaway and the work put in are measured afresh.
    void forgetGrowth();

private:
    double energyScale_ = 0.0;
    double workPutIn_ = 0.0;    // positive work_nc since the scale was taken
    bool beyondScale_ = false;  // |drift| or |correction| above E₀ at the last judgement
    Checkpoint frameStart_, runawayStart_;
};

}  // namespace phasebox
