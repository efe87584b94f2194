#pragma once
// The stability advisor: how stiff is this scene, and which step each explicit method can
// take without blowing up. The stiffest mode's angular frequency ω comes from the force
// Jacobian: ω² is the largest eigenvalue of −M⁻¹·K, found by power iteration on the symmetric
// M^{-1/2}·(−K)·M^{-1/2}. For an undamped mode e^{iωt} the methods' limits are the classic
// ones: symplectic Euler and velocity Verlet need ω·h < 2, RK4 ω·h < 2√2 ≈ 2.83, while
// explicit Euler and the two-stage methods gain energy at every step size.

#include "physics/world/World.h"

#include <string>
#include <string_view>
#include <vector>

namespace phasebox {

struct StepLimit {
    std::string_view integrator;
    // The largest stable dt for an undamped oscillation of the stiffest mode: +∞ for a method
    // stable at any step, 0 for one that gains energy at every step.
    double maxDt = 0.0;
    std::string note;
};

struct StabilityAdvice {
    double omegaMax = 0.0;          // rad/s; 0 when nothing in the scene oscillates
    double dt = 0.0;                // the scene's sub-step length, dt/substeps
    std::vector<StepLimit> limits;  // one per fixed-step method, in registry order
    // Of those, the ones stable at the current step with a margin (largest stable step at least
    // 1.25 times it): the only methods the message names.
    std::vector<StepLimit> recommended;
    // The current integrator at the current sub-step: stable, and if not, what to do.
    bool currentStable = true;
    std::string message;
    // A warning about the contact model in plain words (contactModelWarning()), or empty.
    std::string contactWarning;
};

// Reads the world's force Jacobian at its current state (the world is not changed).
StabilityAdvice adviseStability(World& world, int powerIterations = 2000);

// What the contact model cannot do for this scene, in a classroom's words, or empty: kinematic
// contacts under a stack (a dynamic rigid body resting on another along gravity). They only
// remove the approach velocity and push overlaps apart, so nothing carries the weight of the bodies
// above: a tower telescopes into the floor.
std::string contactModelWarning(const World& world);

// ω·h bound of a method for undamped oscillation: +∞, a finite bound, or 0 (unstable).
double stabilityBound(std::string_view integrator);

}  // namespace phasebox
