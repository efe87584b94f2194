// symplectic_euler: v' = v + h·a(x, v); x' = x + h·v'. First order but symplectic: the
// oscillator's energy oscillates within O(h) of its true value forever instead of drifting.
// With contacts this is exactly the classic "integrate velocities → solve contacts →
// integrate positions" loop of game engines.

#include "physics/integrators/Methods.h"

namespace phasebox::methods {

const IntegratorInfo kSymplecticEulerInfo{
    "symplectic_euler",
    "Symplectic Euler",
    1,
    false,
    true,
    false,
    "1",
    "Semi-implicit Euler: velocity first, then position with the new velocity; bounded energy.",
    1.0,
    2.0,
    nullptr,
    false};

namespace {
class SymplecticEuler final : public Integrator {
public:
    const IntegratorInfo& info() const override { return kSymplecticEulerInfo; }
    void reset(int n) override { a_.setZero(n); }
    bool advance(OdeSystem& sys, double t, double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                 double& workNc) override {
        workNc += h * sys.acceleration(t, q0, u0, a_);
        // One fused pass: the velocity update and the position update read the same lanes,
        // and when the caller wants the end state summed, the sum reads them from registers.
        const double* __restrict q0p = q0.data();
        const double* __restrict u0p = u0.data();
        const double* __restrict ap = a_.data();
        double* __restrict qp = q.data();
        double* __restrict up = u.data();
        // Two lanes at a time, so that the sum's 2-lane loads read what these stores wrote
        // (scalar stores under a vector load stall the store-to-load forwarding).
        using A2 = Eigen::Array2d;
        auto update = [=](Eigen::Index first, Eigen::Index count) {
            Eigen::Index i = first;
            for (; i + 2 <= first + count; i += 2) {
                const A2 v = Eigen::Map<const A2>(u0p + i) + h * Eigen::Map<const A2>(ap + i);
                Eigen::Map<A2>(up + i) = v;
                Eigen::Map<A2>(qp + i) = Eigen::Map<const A2>(q0p + i) + h * v;
            }
            if (i < first + count) {  // a rigid body's angle
                const double v = u0p[i] + h * ap[i];
                up[i] = v;
                qp[i] = q0p[i] + h * v;
            }
        };
        if (StateSummary* summary = requestedSummary()) {
            *summary = sweepState(sys.pairedDofs(), sys.mass(), q, u, update);
            markSummarized();
        } else {
            update(0, q.size());
        }
        ++stats_.acceptedSteps;
        return true;
    }

private:
    Vec a_;
};
}  // namespace

std::unique_ptr<Integrator> makeSymplecticEuler() {
    return std::make_unique<SymplecticEuler>();
}

}  // namespace phasebox::methods
