// symplectic_euler: v' = v + h·a(x, v); x' = x + h·v'. First order but symplectic: the
// oscillator's energy oscillates within O(h) of its true value forever instead of drifting.
// With contacts this is exactly the classic "integrate velocities → solve contacts →
// integrate positions" loop of game engines.

#include "physics/integrators/Methods.h"

namespace phasebox::methods {

const IntegratorInfo kSymplecticEulerInfo{
    "symplectic_euler", "Symplectic Euler", 1, false, true, false, "1",
    "Semi-implicit Euler: velocity first, then position with the new velocity; bounded energy.", 1.0};

namespace {
class SymplecticEuler final : public Integrator {
public:
    const IntegratorInfo& info() const override { return kSymplecticEulerInfo; }
    void reset(int n) override { a_.setZero(n); }
    bool step(OdeSystem& sys, double t, double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
              double& workNc) override {
        workNc += h * sys.acceleration(t, q0, u0, a_);
        // One fused pass: the velocity update and the position update read the same lanes.
        const Eigen::Index n = q.size();
        const double* __restrict q0p = q0.data();
        const double* __restrict u0p = u0.data();
        const double* __restrict ap = a_.data();
        double* __restrict qp = q.data();
        double* __restrict up = u.data();
        for (Eigen::Index i = 0; i < n; ++i) {
            const double v = u0p[i] + h * ap[i];
            up[i] = v;
            qp[i] = q0p[i] + h * v;
        }
        ++stats_.acceptedSteps;
        return true;
    }

private:
    Vec a_;
};
}  // namespace

std::unique_ptr<Integrator> makeSymplecticEuler() { return std::make_unique<SymplecticEuler>(); }

}  // namespace phasebox::methods
