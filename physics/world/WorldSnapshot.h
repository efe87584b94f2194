#pragma once
// The whole state of a World at one moment, saved and restored: what a recording keeps as a
// keyframe (CONTRACT §8). Restoring it and stepping on gives the same bits as the run that was
// never interrupted, so the snapshot holds everything a step reads from the steps before it:
// both state buffers, the clock, the energy ledger, the divergence guard's checkpoints, the
// contact stage (its warm-start impulses and broad-phase order), the joints' solver (its
// factorisation and held stiffness), the sub-step choices the world holds, and what the
// integrator carries (an adaptive method's step size).
//
// A snapshot belongs to the world it was taken from and to that world's objects: it is not a
// scene description. The settings (method, dt, contact model) are part of the state and come
// back with it; an edit that adds or removes objects makes the earlier snapshots of that world
// meaningless, and restoring one refuses (returns false). With simulation.sleep on the
// snapshot holds the sleep state too: which bodies sleep and what their records keep, the
// islands they sleep in and every body's time at rest; restoring rebuilds the state's layout
// around the bodies asleep then (a sleeping body has no degrees of freedom).

#include "physics/contacts/ContactStage.h"
#include "physics/joints/JointSolver.h"
#include "physics/world/World.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace phasebox {

// What a recording keeps of every frame: enough to draw the world and to show every readout of
// it (the state, the clock, the ledger, and the contact and joint forces the step left, which
// the state does not give back), not enough to step on from it.
struct FrameState {
    Vec q, u;
    double time = 0.0;
    long long stepCount = 0;
    EnergyLedger ledger;
    FrameForces forces;
    // The bodies asleep (nullptr when none): q and u are of the layout without them. Shared by
    // the frames of a stretch in which the same islands sleep, so not counted in bytes().
    std::shared_ptr<const Sleepers> sleepers;

    static FrameState of(const World& world);
    std::size_t bytes() const {
        return sizeof(FrameState) + static_cast<std::size_t>(q.size() + u.size()) * sizeof(double) +
               forces.bytes();
    }
};

class WorldSnapshot {
public:
    WorldSnapshot();
    ~WorldSnapshot();
    WorldSnapshot(WorldSnapshot&&) noexcept;
    WorldSnapshot& operator=(WorldSnapshot&&) noexcept;

    // Copies the world's whole state (allocates: take it between steps, not inside one).
    static WorldSnapshot take(const World& world);
    // Puts the world back into the saved state, its settings included. False (and the world
    // untouched) when the world's objects are not the ones the snapshot was taken with.
    bool restoreInto(World& world) const;

    // Shows a recorded frame: the world's state, clock, ledger and forces (contactForce,
    // jointForce) become the frame's, so that drawing and every probe read that moment. What else
    // the world carries (warm starts, the method's step size) stays as it was: restore a snapshot
    // before stepping on. False when the frame is of other objects.
    static bool show(World& world, const FrameState& frame);

    // Whether the world runs with the settings the snapshot holds (a recording takes a new
    // keyframe where they change, so that re-simulation never crosses a switch of method).
    bool hasSettingsOf(const World& world) const;

    // The settings the world ran with when the snapshot was taken (method, dt, contact model).
    const SimulationSettings& settings() const { return settings_; }
    double time() const { return clock_.time; }
    long long stepCount() const { return clock_.stepCount; }
    // Bytes held, for a recording's memory budget (an estimate: vectors by their sizes).
    std::size_t bytes() const { return bytes_; }

private:
    int dimension_ = 0;
    SimulationSettings settings_;
    Vec q_[2], u_[2];
    int current_ = 0;
    Vec force_;
    SimulationClock clock_;
    long long forceEvaluations_ = 0;
    EnergyLedger ledger_;
    DivergenceGuard guard_;
    std::optional<Divergence> divergence_;
    std::unique_ptr<ContactStage> contacts_;
    std::unique_ptr<JointSolver> joints_;
    Vec penaltyVelocity_, kinematicImpulse_, heldForce_, unappliedJointForce_;
    double heldWork_ = 0.0;
    bool holding_ = false, heldValid_ = false, penaltyPairsStale_ = true;
    int jointSubsteps_ = 1;
    double jointSubstepsSince_ = 0.0;
    int pulledSubsteps_ = 1, pulledPeak_ = 1;
    double pulledSince_ = 0.0;
    std::vector<double> integratorCarried_;
    IntegratorStats integratorStats_;
    // The objects' counts, and the sleep state (World's sleeping section).
    std::size_t particles_ = 0, rigidBodies_ = 0;
    std::shared_ptr<const Sleepers> sleepers_;
    std::vector<double> restingSeconds_;
    std::vector<int> sleepingIsland_;
    int nextIsland_ = 0;
    std::size_t bytes_ = 0;
};

}  // namespace phasebox
