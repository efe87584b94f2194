// adaptive_euler: explicit Euler with step doubling. One step of h is compared with two steps
// of h/2; the error is their largest difference. The step is accepted when error ≤ tolerance
// (keeping the more accurate two half steps), and the next step is 0.9·h·√(tolerance/error).

#include "physics/core/WorkUnits.h"
#include "physics/integrators/AdaptiveStepper.h"
#include "physics/integrators/Methods.h"

namespace phasebox::methods {

// Position weight ¼ for a frame taken in one accepted step: it keeps two explicit Euler half
// steps, which move a body by h·v + h²/4·a under a constant acceleration. A frame taken in several
// moves it further (positionWeight()): ½·(1 − Σ s_j²/H²) over its half steps s_j, towards ½.
const IntegratorInfo kAdaptiveEulerInfo{
    "adaptive_euler",
    "Adaptive Euler (step doubling)",
    1,
    false,
    false,
    true,
    "2 per attempt",
    "Explicit Euler whose step size follows the error of one step against two half steps.",
    0.25,
    kInfinity,
    nullptr,
    false,
    false};

namespace {
constexpr long long kMaxInternalSteps = 10'000'000;
// Evaluations a frame times the scene's work units (core/WorkUnits.h), each sub-step its share:
// a scene too stiff for the method gives up in seconds, whatever its size and kind.
constexpr double kEvaluationsPerStep = 2;

class AdaptiveEuler final : public Integrator {
public:
    const IntegratorInfo& info() const override { return kAdaptiveEulerInfo; }
    void reset(int n) override {
        for (Vec* v : {&a0_, &ah_, &qFull_, &uFull_, &qHalf_, &uHalf_}) v->setZero(n);
        stepper_.reset();
    }
    bool advance(OdeSystem& sys, double t, double H, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                 double& workNc) override {
        q = q0;
        u = u0;
        const double tol = settings_.tolerance;
        const double end = t + H;
        double time = t;
        long long internal = 0;
        double squares = 0.0;  // Σ s_j² over the accepted half steps
        const long long maxInternal = std::min<long long>(
            kMaxInternalSteps,
            static_cast<long long>(settings_.workShare * kMaxEvaluationWork /
                                   (kEvaluationsPerStep * std::max(1.0, sys.workUnits()))));
        while (time < end) {
            const double h = stepper_.next(end - time, H);
            if (AdaptiveStepper::collapsed(h, H) || ++internal > maxInternal) return false;
            const double p0 = sys.acceleration(time, q, u, a0_);
            // One full step.
            qFull_ = q + h * u;
            uFull_ = u + h * a0_;
            // Two half steps (the first shares a0).
            qHalf_ = q + (0.5 * h) * u;
            uHalf_ = u + (0.5 * h) * a0_;
            const double ph = sys.acceleration(time + 0.5 * h, qHalf_, uHalf_, ah_);
            qHalf_ += (0.5 * h) * uHalf_;
            uHalf_ += (0.5 * h) * ah_;
            const double error = std::max((qFull_ - qHalf_).lpNorm<Eigen::Infinity>(),
                                          (uFull_ - uHalf_).lpNorm<Eigen::Infinity>());
            if (!std::isfinite(error)) return false;
            stepper_.adapt(h, error / tol, 0.5);
            if (error > tol) {
                ++stats_.rejectedSteps;
                continue;
            }
            q = qHalf_;
            u = uHalf_;
            workNc += 0.5 * h * (p0 + ph);
            time = (end - time == h) ? end : time + h;
            squares += 0.5 * h * h;
            ++stats_.acceptedSteps;
        }
        weight_ = 0.5 * (1.0 - squares / (H * H));
        return true;
    }

    double positionWeight() const override { return weight_; }
    std::vector<double> carriedState() const override { return {stepper_.suggested()}; }
    void restoreCarriedState(const std::vector<double>& carried) override {
        stepper_.setSuggested(carried.empty() ? 0.0 : carried.front());
    }

private:
    AdaptiveStepper stepper_;
    double weight_ = 0.25;  // the last frame's positionWeight()
    Vec a0_, ah_, qFull_, uFull_, qHalf_, uHalf_;
};
}  // namespace

std::unique_ptr<Integrator> makeAdaptiveEuler() {
    return std::make_unique<AdaptiveEuler>();
}

}  // namespace phasebox::methods
