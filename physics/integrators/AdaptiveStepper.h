#pragma once
// Step-size bookkeeping shared by the adaptive methods: they take internal steps of their own
// size but land exactly on the caller's step boundary, and carry the suggested size from one
// call to the next.

#include <algorithm>
#include <cmath>

namespace phasebox {

class AdaptiveStepper {
public:
    // Forget the history: the next call starts with the caller's whole step.
    void reset() { suggested_ = 0.0; }
    // The size carried to the next call (0: none yet), for a snapshot of the world.
    double suggested() const { return suggested_; }
    void setSuggested(double h) { suggested_ = h; }

    // The size of the next internal step, given what remains of the caller's step. A
    // remainder that would leave a sliver of less than 1e-10 of the step is taken at once.
    double next(double remaining, double callerStep) const {
        double h = suggested_ > 0.0 ? std::min(suggested_, callerStep) : callerStep;
        if (h >= remaining || remaining - h < 1e-10 * callerStep) h = remaining;
        return h;
    }

    // Records a new suggestion from the error ratio (error / tolerance, ≤ 1 when accepted)
    // and the method's error exponent: h_next = 0.9·h·(1/ratio)^exponent, grown at most 5×
    // and shrunk at most 10× at a time.
    void adapt(double h, double ratio, double exponent) {
        double factor = ratio > 0.0 ? 0.9 * std::pow(1.0 / ratio, exponent) : 5.0;
        factor = std::clamp(factor, 0.1, 5.0);
        suggested_ = h * factor;
    }

    // True when the step has collapsed relative to the caller's step: the method gives up
    // rather than loop forever on a singular or diverging problem.
    static bool collapsed(double h, double callerStep) { return h < 1e-12 * callerStep; }

private:
    double suggested_ = 0.0;
};

}  // namespace phasebox
