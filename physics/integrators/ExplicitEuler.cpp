// explicit_euler: x' = x + h·v; v' = v + h·a(x, v). First order; the oscillator's energy grows
// by (1 + h²ω²) every step, which is why it is here: to be watched failing.

#include "physics/integrators/Methods.h"

namespace phasebox::methods {

const IntegratorInfo kExplicitEulerInfo{
    "explicit_euler",
    "Explicit Euler",
    1,
    false,
    false,
    false,
    "1",
    "Forward Euler on (x, v): first order, gains energy on every oscillation.",
    0.0,
    0.0,
    [](double wh) { return 1.0 + wh * wh; },
    false,
    false};

namespace {
class ExplicitEuler final : public Integrator {
public:
    const IntegratorInfo& info() const override { return kExplicitEulerInfo; }
    void reset(int n) override { a_.setZero(n); }
    bool advance(OdeSystem& sys, double t, double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                 double& workNc) override {
        workNc += h * sys.acceleration(t, q0, u0, a_);
        q = q0 + h * u0;
        u = u0 + h * a_;
        ++stats_.acceptedSteps;
        return true;
    }

private:
    Vec a_;
};
}  // namespace

std::unique_ptr<Integrator> makeExplicitEuler() {
    return std::make_unique<ExplicitEuler>();
}

}  // namespace phasebox::methods
