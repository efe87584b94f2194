// midpoint: explicit midpoint (RK2) on y' = f(y): a half Euler step to the midpoint, then a
// full step with the midpoint's slope.

#include "physics/integrators/Methods.h"

namespace phasebox::methods {

const IntegratorInfo kMidpointInfo{
    "midpoint",
    "Midpoint (RK2)",
    2,
    false,
    false,
    false,
    "2",
    "Explicit midpoint: a half step to estimate the slope, then a full step with it.",
    0.5,
    0.0,
    [](double wh) { return 1.0 + wh * wh * wh * wh / 4.0; },
    false,
    false};

namespace {
class Midpoint final : public Integrator {
public:
    const IntegratorInfo& info() const override { return kMidpointInfo; }
    void reset(int n) override {
        a_.setZero(n);
        qm_.setZero(n);
        um_.setZero(n);
    }
    bool advance(OdeSystem& sys, double t, double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                 double& workNc) override {
        sys.acceleration(t, q0, u0, a_);
        qm_ = q0 + (0.5 * h) * u0;
        um_ = u0 + (0.5 * h) * a_;
        workNc += h * sys.acceleration(t + 0.5 * h, qm_, um_, a_);
        q = q0 + h * um_;
        u = u0 + h * a_;
        ++stats_.acceptedSteps;
        return true;
    }

private:
    Vec a_, qm_, um_;
};
}  // namespace

std::unique_ptr<Integrator> makeMidpoint() {
    return std::make_unique<Midpoint>();
}

}  // namespace phasebox::methods
