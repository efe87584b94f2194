// velocity_verlet: x' = x + h·v + h²/2·a; a' = a(x', v + h·a); v' = v + h/2·(a + a').
// Second order and symplectic for velocity-independent forces. The end-of-step acceleration is
// not reused as the next step's start value: with velocity-dependent forces (drag, damping)
// a' is evaluated at v + h·a, not at v', and contacts may change the state in between.

#include "physics/integrators/Methods.h"

namespace phasebox::methods {

const IntegratorInfo kVelocityVerletInfo{
    "velocity_verlet",
    "Velocity Verlet",
    2,
    false,
    true,
    false,
    "2",
    "Position from the current acceleration, velocity from the average of old and new ones.",
    0.5,
    2.0,
    nullptr,
    false,
    false};

namespace {
class VelocityVerlet final : public Integrator {
public:
    const IntegratorInfo& info() const override { return kVelocityVerletInfo; }
    void reset(int n) override {
        a_.setZero(n);
        a2_.setZero(n);
        up_.setZero(n);
    }
    bool advance(OdeSystem& sys, double t, double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                 double& workNc) override {
        const double p1 = sys.acceleration(t, q0, u0, a_);
        q = q0 + h * u0 + (0.5 * h * h) * a_;
        up_ = u0 + h * a_;
        const double p2 = sys.acceleration(t + h, q, up_, a2_);
        u = u0 + (0.5 * h) * (a_ + a2_);
        workNc += 0.5 * h * (p1 + p2);
        ++stats_.acceptedSteps;
        return true;
    }

private:
    Vec a_, a2_, up_;
};
}  // namespace

std::unique_ptr<Integrator> makeVelocityVerlet() {
    return std::make_unique<VelocityVerlet>();
}

}  // namespace phasebox::methods
