// rk45: Dormand–Prince 5(4) with local error control (Hairer, Nørsett & Wanner, Solving ODEs I,
// II.5). The fifth-order solution is propagated; the embedded fourth-order one estimates the
// error, measured in the RMS norm scaled by tolerance·(1 + max(|y|, |y'|)), i.e. the tolerance
// is both the absolute and the relative tolerance. The last stage is evaluated at the new
// point, so it is the next internal step's first stage (first same as last).

#include "physics/core/WorkUnits.h"
#include "physics/integrators/AdaptiveStepper.h"
#include "physics/integrators/Methods.h"

#include <array>

namespace phasebox::methods {

const IntegratorInfo kDormandPrinceInfo{
    "rk45",
    "Dormand–Prince 5(4)",
    5,
    false,
    false,
    true,
    "6 per attempt (+1 per call)",
    "Embedded Runge–Kutta pair with error control; the reference for the accuracy lab.",
    0.5,
    kInfinity,
    nullptr,
    false,
    false};

namespace {
constexpr long long kMaxInternalSteps = 10'000'000;
// Evaluations a frame times the scene's work units (core/WorkUnits.h), each sub-step its share:
// a scene too stiff for the method gives up in seconds, whatever its size and kind.
constexpr double kEvaluationsPerStep = 6;
constexpr int kStages = 7;

// Butcher tableau.
constexpr double kC[kStages] = {0.0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1.0, 1.0};
constexpr double kA[kStages][kStages - 1] = {
    {},
    {1.0 / 5},
    {3.0 / 40, 9.0 / 40},
    {44.0 / 45, -56.0 / 15, 32.0 / 9},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
    {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};
// Fifth-order weights (= the last row of A) and the difference fifth − fourth order.
constexpr double kB[kStages] = {35.0 / 384,     0.0,       500.0 / 1113, 125.0 / 192,
                                -2187.0 / 6784, 11.0 / 84, 0.0};
constexpr double kE[kStages] = {71.0 / 57600,      0.0,        -71.0 / 16695, 71.0 / 1920,
                                -17253.0 / 339200, 22.0 / 525, -1.0 / 40};

class DormandPrince final : public Integrator {
public:
    const IntegratorInfo& info() const override { return kDormandPrinceInfo; }
    void reset(int n) override {
        for (int s = 0; s < kStages; ++s) {
            kq_[s].setZero(n);
            ku_[s].setZero(n);
        }
        for (Vec* v : {&qs_, &us_, &qNew_, &uNew_}) v->setZero(n);
        stepper_.reset();
    }

    bool advance(OdeSystem& sys, double t, double H, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                 double& workNc) override {
        q = q0;
        u = u0;
        const double tol = settings_.tolerance;
        const double end = t + H;
        const Eigen::Index n = q.size();
        double time = t;
        long long internal = 0;
        const long long maxInternal = std::min<long long>(
            kMaxInternalSteps,
            static_cast<long long>(settings_.workShare * kMaxEvaluationWork /
                                   (kEvaluationsPerStep * std::max(1.0, sys.workUnits()))));
        // First stage at the start of this call; later ones reuse the last stage.
        power_[0] = sys.acceleration(time, q, u, ku_[0]);
        kq_[0] = u;
        while (time < end) {
            const double h = stepper_.next(end - time, H);
            if (AdaptiveStepper::collapsed(h, H) || ++internal > maxInternal) return false;
            for (int s = 1; s < kStages; ++s) {
                qs_ = q;
                us_ = u;
                for (int j = 0; j < s; ++j) {
                    if (kA[s][j] == 0.0) continue;
                    qs_ += (h * kA[s][j]) * kq_[j];
                    us_ += (h * kA[s][j]) * ku_[j];
                }
                power_[s] = sys.acceleration(time + kC[s] * h, qs_, us_, ku_[s]);
                kq_[s] = us_;
                if (s == kStages - 1) {
                    qNew_ = qs_;  // the last stage point is the fifth-order solution
                    uNew_ = us_;
                }
            }
            // Error estimate in the scaled RMS norm.
            double sum = 0.0;
            for (Eigen::Index i = 0; i < n; ++i) {
                double eq = 0.0, eu = 0.0;
                for (int s = 0; s < kStages; ++s) {
                    eq += kE[s] * kq_[s][i];
                    eu += kE[s] * ku_[s][i];
                }
                const double sq = tol * (1.0 + std::max(std::abs(q[i]), std::abs(qNew_[i])));
                const double su = tol * (1.0 + std::max(std::abs(u[i]), std::abs(uNew_[i])));
                sum += (h * eq / sq) * (h * eq / sq) + (h * eu / su) * (h * eu / su);
            }
            const double ratio = n > 0 ? std::sqrt(sum / (2.0 * static_cast<double>(n))) : 0.0;
            if (!std::isfinite(ratio) || !qNew_.allFinite() || !uNew_.allFinite()) {
                // A non-finite trial point: shrink hard and retry.
                stepper_.adapt(h, 1e10, 0.2);
                ++stats_.rejectedSteps;
                continue;
            }
            stepper_.adapt(h, ratio, 0.2);
            if (ratio > 1.0) {
                ++stats_.rejectedSteps;
                continue;
            }
            double work = 0.0;
            for (int s = 0; s < kStages; ++s) work += kB[s] * power_[s];
            workNc += h * work;
            q = qNew_;
            u = uNew_;
            time = (end - time == h) ? end : time + h;
            ++stats_.acceptedSteps;
            // First same as last.
            std::swap(kq_[0], kq_[kStages - 1]);
            std::swap(ku_[0], ku_[kStages - 1]);
            power_[0] = power_[kStages - 1];
        }
        return true;
    }

    std::vector<double> carriedState() const override { return {stepper_.suggested()}; }
    void restoreCarriedState(const std::vector<double>& carried) override {
        stepper_.setSuggested(carried.empty() ? 0.0 : carried.front());
    }

private:
    AdaptiveStepper stepper_;
    std::array<Vec, kStages> kq_, ku_;
    std::array<double, kStages> power_{};
    Vec qs_, us_, qNew_, uNew_;
};
}  // namespace

std::unique_ptr<Integrator> makeDormandPrince() {
    return std::make_unique<DormandPrince>();
}

}  // namespace phasebox::methods
