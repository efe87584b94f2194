#pragma once
// The live local error estimate: step doubling at the current state. One sub-step of h against
// two of h/2 with the running method, smooth forces only (contacts are events, not a smooth
// error). It runs its own instance of the method on scratch state, so that estimating never
// changes the run (its adaptive step, its solver's warm start).

#include "physics/integrators/Integrator.h"

#include <memory>

namespace phasebox {

class LocalErrorEstimator {
public:
    // The estimated local error of one step h from (q, u) at t, max over position coordinates
    // (m, or rad for an angle): the difference of the two answers divided by (1 − 2^−p) for a
    // method of order p; ∞ when the method fails. The system's counters are the caller's to keep.
    double estimate(OdeSystem& system, const Integrator& running, double t, double h, const Vec& q,
                    const Vec& u);

private:
    std::unique_ptr<Integrator> method_;
    Vec q_[3], u_[3];
};

}  // namespace phasebox
