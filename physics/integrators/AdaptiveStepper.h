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

    // The most internal steps a caller's step may take: within maxWork internal steps times
    // coordinates (a large scene), and within kMaxInternalPerFrame whatever the scene's size,
    // each shared by workShare (the caller's sub-steps split the frame's budget). Past it the
    // method gives up and the world reports the scene too stiff for it: its step had fallen
    // below about dt/1024 on average, and a chain of 100 particles on rods whipping under
    // adaptive_euler took 13,000 evaluations a frame, 76 s for 10 s (issue #38), where the
    // coordinates' budget alone allowed 500,000 internal steps a frame.
    static constexpr long long kMaxInternalPerFrame = 1024;
    static long long budget(double workShare, double maxWork, long long coordinates,
                            long long maxSteps) {
        const double byWork = workShare * maxWork / static_cast<double>(coordinates + 1);
        const double byFrame = std::max(1.0, workShare * kMaxInternalPerFrame);
        return static_cast<long long>(std::min({static_cast<double>(maxSteps), byWork, byFrame}));
    }

private:
    double suggested_ = 0.0;
};

}  // namespace phasebox
