// rk4: the classic fourth-order Runge–Kutta method on y = (x, v).

#include "physics/integrators/Methods.h"

#include <numbers>

namespace phasebox::methods {

const IntegratorInfo kRungeKutta4Info{
    "rk4",   "Runge–Kutta 4",
    4,       false,
    false,   false,
    "4",     "Classic fourth-order Runge–Kutta: four slopes weighted 1/6, 1/3, 1/3, 1/6.",
    0.5,     2.0 * std::numbers::sqrt2,
    nullptr, false,
    false};

namespace {
class RungeKutta4 final : public Integrator {
public:
    const IntegratorInfo& info() const override { return kRungeKutta4Info; }
    void reset(int n) override {
        for (Vec* v : {&a1_, &a2_, &a3_, &a4_, &u2_, &u3_, &u4_, &qs_}) v->setZero(n);
    }
    bool advance(OdeSystem& sys, double t, double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                 double& workNc) override {
        // Stage slopes of x are the stage velocities (u0, u2, u3, u4), of v the accelerations.
        const double p1 = sys.acceleration(t, q0, u0, a1_);
        qs_ = q0 + (0.5 * h) * u0;
        u2_ = u0 + (0.5 * h) * a1_;
        const double p2 = sys.acceleration(t + 0.5 * h, qs_, u2_, a2_);
        qs_ = q0 + (0.5 * h) * u2_;
        u3_ = u0 + (0.5 * h) * a2_;
        const double p3 = sys.acceleration(t + 0.5 * h, qs_, u3_, a3_);
        qs_ = q0 + h * u3_;
        u4_ = u0 + h * a3_;
        const double p4 = sys.acceleration(t + h, qs_, u4_, a4_);
        q = q0 + (h / 6.0) * (u0 + 2.0 * u2_ + 2.0 * u3_ + u4_);
        u = u0 + (h / 6.0) * (a1_ + 2.0 * a2_ + 2.0 * a3_ + a4_);
        workNc += (h / 6.0) * (p1 + 2.0 * p2 + 2.0 * p3 + p4);
        ++stats_.acceptedSteps;
        return true;
    }

private:
    Vec a1_, a2_, a3_, a4_, u2_, u3_, u4_, qs_;
};
}  // namespace

std::unique_ptr<Integrator> makeRungeKutta4() {
    return std::make_unique<RungeKutta4>();
}

}  // namespace phasebox::methods
