#pragma once
// The integrator interface and registry (CONTRACT.md §3). An integrator advances the state
// (q, u) of an OdeSystem by one step h; it owns its scratch vectors, sized once by reset().

#include "physics/core/OdeSystem.h"
#include "physics/core/StateSummary.h"

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace phasebox {

struct IntegratorInfo {
    std::string_view name;   // the fixed name of CONTRACT.md §3
    std::string_view label;  // for people: "Symplectic Euler"
    int order;               // global order of accuracy on smooth problems
    bool implicit;
    bool symplectic;
    bool adaptive;
    std::string_view evaluations;  // force evaluations per step, as a phrase
    std::string_view summary;      // one sentence for tooltips and docs
    // How far a constant acceleration a moves a body in one step, in units of a·h²: 1 for
    // symplectic and implicit Euler (x' = x + h·v'), ½ for the second-order methods, 0 for
    // explicit Euler (x' = x + h·v). Contacts move positions as this method would have under
    // the contact force, so that a body resting on the ground stays put whatever the method.
    double positionWeight;
    // Stability on the undamped oscillator x'' = −ω²·x (what the stability advisor reads):
    // the method is stable while ω·h < stabilityBound; ∞ for the A-stable and the adaptive
    // ones, 0 for those that gain energy at every step. For the latter, energyGrowth(ω·h) is
    // the factor by which the oscillator's energy grows per step, |R(iωh)|².
    double stabilityBound;
    double (*energyGrowth)(double omegaH);
    // The step takes newton_iterations Newton iterations (the setting matters to it).
    bool usesNewtonIterations;
    // Where the method's step takes the joints' constraint force: false at the step's start
    // (SHAKE's directions, as symplectic Euler and the explicit methods step their forces),
    // true at its end (backward Euler: the positions are projected onto C = 0 along J at the
    // end point, the velocities onto its tangent, so a rod pendulum is damped as backward Euler
    // damps the pendulum in its angle).
    bool constraintsAtEnd;
};

struct IntegratorSettings {
    double tolerance = 1e-6;   // adaptive methods' local error tolerance
    int newtonIterations = 1;  // implicit_euler: 1 = the linearised step of Baraff & Witkin
    // The share of a frame's work budget (adaptive methods) one call may use: 1 / the
    // sub-steps a frame, so that sub-steps do not multiply what a frame may cost.
    double workShare = 1.0;
};

// Counters since the integrator was made or reset; the world reports them.
struct IntegratorStats {
    long long acceptedSteps = 0;  // internal steps (adaptive methods take several per call)
    long long rejectedSteps = 0;
    long long linearSolves = 0;
    int lastNewtonIterations = 0;
    double lastNewtonCorrection = 0.0;  // ∞-norm of the last Newton update (velocity units)
    int lastLinearIterations = 0;       // conjugate-gradient iterations in the last step
    double lastLinearResidual = 0.0;    // its relative residual
    long long linearIterations = 0;     // summed
};

class Integrator {
public:
    virtual ~Integrator() = default;

    virtual const IntegratorInfo& info() const = 0;
    // How far a constant acceleration a moved a body in the last step, in units of a·h²: the
    // info's positionWeight, but for a method whose weight depends on the internal steps it took
    // (adaptive Euler's explicit half steps s_j move it by ½·(1 − Σ s_j²/h²)). The contacts read
    // it after the step (World::solveContacts).
    virtual double positionWeight() const { return info().positionWeight; }

    // Sizes scratch memory for a state of this dimension and forgets any step-size history.
    virtual void reset(int dimension) = 0;

    // Advances the state (q0, u0) at time t to (q, u) at t + h and adds the work of the
    // non-conservative forces over the step to workNc. The output vectors are distinct from
    // the input ones and already sized, so the caller keeps the start state for free (the
    // world double-buffers its state). Returns false when the method fails (a singular linear
    // system, an adaptive step size that collapsed); q and u are then unspecified.
    // With a summary, it is filled for the end state (q, u) (core/StateSummary.h): fused into
    // the method's last pass where that pass writes the whole state, else summed after it.
    bool step(OdeSystem& system, double t, double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
              double& workNc, StateSummary* summary = nullptr) {
        summary_ = summary;
        summarized_ = false;
        const bool ok = advance(system, t, h, q0, u0, q, u, workNc);
        if (ok && summary && !summarized_)
            *summary = summarizeState(system.pointDofs(), system.mass(), q, u);
        summary_ = nullptr;
        return ok;
    }

    // What the method carries from one step to the next besides the state (an adaptive
    // method's suggested step size), as numbers: a snapshot of the world saves it so that a
    // restored run goes on with the same bits. Scratch memory is not carried.
    virtual std::vector<double> carriedState() const { return {}; }
    virtual void restoreCarriedState(const std::vector<double>& carried) { (void)carried; }
    void restoreStats(const IntegratorStats& stats) { stats_ = stats; }

    void setSettings(const IntegratorSettings& settings) { settings_ = settings; }
    const IntegratorSettings& settings() const { return settings_; }
    const IntegratorStats& stats() const { return stats_; }

protected:
    // One step of the method, as step() describes it.
    virtual bool advance(OdeSystem& system, double t, double h, const Vec& q0, const Vec& u0,
                         Vec& q, Vec& u, double& workNc) = 0;
    // The summary step() was asked for, or nullptr. A method that fills it in its last pass
    // (with sweepState) calls markSummarized() so that step() does not sum the state again.
    StateSummary* requestedSummary() const { return summary_; }
    void markSummarized() { summarized_ = true; }

    IntegratorSettings settings_;
    IntegratorStats stats_;

private:
    StateSummary* summary_ = nullptr;
    bool summarized_ = false;
};

// Every method, in the contract's order.
std::span<const IntegratorInfo> integratorRegistry();
const IntegratorInfo* findIntegrator(std::string_view name);
// The names joined by ", ", for error messages.
std::string knownIntegratorNames();

// nullptr for an unknown name.
std::unique_ptr<Integrator> makeIntegrator(std::string_view name,
                                           const IntegratorSettings& settings = {});

}  // namespace phasebox
