// implicit_midpoint: y' = y + h·f((y + y')/2), Newton-iterated to convergence. Symplectic and
// second order; it conserves every quadratic invariant, so a linear spring's energy is kept to
// round-off at any step size.

#include "physics/integrators/Methods.h"

#include "physics/linear/NewtonVelocitySolver.h"

namespace phasebox::methods {

const IntegratorInfo kImplicitMidpointInfo{
    "implicit_midpoint",
    "Implicit midpoint",
    2,
    true,
    true,
    false,
    "1 + Jacobian per Newton iteration (to convergence)",
    "Implicit midpoint rule: symplectic, second order, conserves a linear spring's energy.",
    0.5,
    kInfinity,
    nullptr,
    false,
    false};

namespace {
constexpr int kMaxNewtonIterations = 50;
constexpr double kNewtonTolerance = 1e-13;
// Round-off can stall the update above kNewtonTolerance; above this it has not converged.
constexpr double kNotConverged = 1e-8;

class ImplicitMidpoint final : public Integrator {
public:
    const IntegratorInfo& info() const override { return kImplicitMidpointInfo; }
    void reset(int n) override {
        newton_.reset(n);
        vm_.setZero(n);
        qm_.setZero(n);
    }
    bool advance(OdeSystem& sys, double t, double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                 double& workNc) override {
        // Unknown: the midpoint velocity vm, with the midpoint position q0 + h/2·vm.
        const double c = 0.5 * h;
        const auto r =
            newton_.solve(sys, t + c, c, q0, u0, vm_, kMaxNewtonIterations, true, kNewtonTolerance);
        stats_.linearSolves += r.linearSolves;
        stats_.lastNewtonIterations = r.iterations;
        stats_.lastNewtonCorrection = r.lastCorrection;
        stats_.lastLinearIterations = r.linearIterations;
        stats_.lastLinearResidual = r.linearResidual;
        stats_.linearIterations += r.linearIterations;
        // Not converged after kMaxNewtonIterations: the step is not the implicit midpoint rule's,
        // so it fails (the world reports it) rather than passing off a wrong answer.
        if (!r.ok || r.lastCorrection > kNotConverged * (1.0 + vm_.lpNorm<Eigen::Infinity>()))
            return false;
        qm_ = q0 + c * vm_;
        workNc += h * sys.nonConservativePower(t + c, qm_, vm_);
        q = q0 + h * vm_;
        u = 2.0 * vm_ - u0;
        ++stats_.acceptedSteps;
        return true;
    }

private:
    NewtonVelocitySolver newton_;
    Vec vm_, qm_;
};
}  // namespace

std::unique_ptr<Integrator> makeImplicitMidpoint() {
    return std::make_unique<ImplicitMidpoint>();
}

}  // namespace phasebox::methods
