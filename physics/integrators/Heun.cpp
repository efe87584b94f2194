// heun: explicit trapezoid. k₁ = f(y), k₂ = f(y + h·k₁), y' = y + h/2·(k₁ + k₂).

#include "physics/integrators/Methods.h"

namespace phasebox::methods {

const IntegratorInfo kHeunInfo{
    "heun",
    "Heun (explicit trapezoid)",
    2,
    false,
    false,
    false,
    "2",
    "Average of the slopes at the start and at an Euler-predicted end point.",
    0.5,
    0.0,
    [](double wh) { return 1.0 + wh * wh * wh * wh / 4.0; },
    false,
    false};

namespace {
class Heun final : public Integrator {
public:
    const IntegratorInfo& info() const override { return kHeunInfo; }
    void reset(int n) override {
        a1_.setZero(n);
        a2_.setZero(n);
        q2_.setZero(n);
        u2_.setZero(n);
    }
    bool advance(OdeSystem& sys, double t, double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                 double& workNc) override {
        const double p1 = sys.acceleration(t, q0, u0, a1_);
        q2_ = q0 + h * u0;
        u2_ = u0 + h * a1_;
        const double p2 = sys.acceleration(t + h, q2_, u2_, a2_);
        q = q0 + (0.5 * h) * (u0 + u2_);
        u = u0 + (0.5 * h) * (a1_ + a2_);
        workNc += 0.5 * h * (p1 + p2);
        ++stats_.acceptedSteps;
        return true;
    }

private:
    Vec a1_, a2_, q2_, u2_;
};
}  // namespace

std::unique_ptr<Integrator> makeHeun() {
    return std::make_unique<Heun>();
}

}  // namespace phasebox::methods
