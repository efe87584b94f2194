// implicit_euler: backward Euler y' = y + h·f(y'), solved by Newton on the force Jacobians.
// One iteration (the default) is the linearised step of Baraff & Witkin 1998, which is what
// makes stiff springs and cloth stable at large steps; it damps every mode, the stiffest most.

#include "physics/integrators/Methods.h"

#include "physics/linear/NewtonVelocitySolver.h"

#include <algorithm>

namespace phasebox::methods {

const IntegratorInfo kImplicitEulerInfo{
    "implicit_euler",
    "Implicit Euler",
    1,
    true,
    false,
    false,
    "1 + Jacobian per Newton iteration",
    "Backward Euler, Newton-linearised (Baraff & Witkin): unconditionally stable, dissipative.",
    1.0,
    kInfinity,
    nullptr,
    true,
    true};

namespace {
class ImplicitEuler final : public Integrator {
public:
    const IntegratorInfo& info() const override { return kImplicitEulerInfo; }
    void reset(int n) override { newton_.reset(n); }
    bool advance(OdeSystem& sys, double t, double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                 double& workNc) override {
        const int iterations = std::max(1, settings_.newtonIterations);
        // The unknown is the end velocity, solved straight into u.
        const auto r = newton_.solve(sys, t + h, h, q0, u0, u, iterations, true, 1e-12);
        stats_.linearSolves += r.linearSolves;
        stats_.lastNewtonIterations = r.iterations;
        stats_.lastNewtonCorrection = r.lastCorrection;
        stats_.lastLinearIterations = r.linearIterations;
        stats_.lastLinearResidual = r.linearResidual;
        stats_.linearIterations += r.linearIterations;
        if (!r.ok) return false;
        q = q0 + h * u;
        workNc += h * sys.nonConservativePower(t + h, q, u);
        ++stats_.acceptedSteps;
        return true;
    }

private:
    NewtonVelocitySolver newton_;
};
}  // namespace

std::unique_ptr<Integrator> makeImplicitEuler() {
    return std::make_unique<ImplicitEuler>();
}

}  // namespace phasebox::methods
