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
    false,
    false};

namespace {
class SymplecticEuler final : public Integrator {
public:
    const IntegratorInfo& info() const override { return kSymplecticEulerInfo; }
    void reset(int) override {}
    bool advance(OdeSystem& sys, double t, double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                 double& workNc) override {
        // The accelerations beyond the uniform fields are written into the output velocities,
        // which the update then overwrites lane by lane: no array of their own to write, read
        // back and keep in cache. The uniform part (gravity) is a constant of the loop.
        const OdeSystem::SplitAcceleration split = sys.accelerationSplit(t, q0, u0, u);
        workNc += h * split.power;
        if (split.hasRest)
            update<true>(sys, h, split.uniform, q0, u0, q, u);
        else
            update<false>(sys, h, split.uniform, q0, u0, q, u);
        ++stats_.acceptedSteps;
        return true;
    }

private:
    // One fused pass: the velocity update and the position update read the same lanes, and
    // when the caller wants the end state summed, the sum reads them from registers. With
    // `Rest` the non-uniform accelerations are read from u (where they were written).
    template <bool Rest>
    void update(OdeSystem& sys, double h, const Vec2& uniform, const Vec& q0, const Vec& u0, Vec& q,
                Vec& u) {
        const double* __restrict q0p = q0.data();
        const double* __restrict u0p = u0.data();
        const double* ap = u.data();
        double* __restrict qp = q.data();
        double* up = u.data();
        using A2 = Eigen::Array2d;
        const A2 g = uniform.array();
        const A2 hg = h * g;
        // A point: two lanes, handed to the sum in registers.
        auto point = [=](Eigen::Index i, A2& x, A2& v) {
            if constexpr (Rest)
                v = Eigen::Map<const A2>(u0p + i) + h * (g + Eigen::Map<const A2>(ap + i));
            else
                v = Eigen::Map<const A2>(u0p + i) + hg;
            x = Eigen::Map<const A2>(q0p + i) + h * v;
            Eigen::Map<A2>(up + i) = v;
            Eigen::Map<A2>(qp + i) = x;
        };
        // A rigid body: (x, y, θ); the uniform part acts on (x, y).
        auto body = [=](Eigen::Index k) {
            for (Eigen::Index i = k; i < k + 3; ++i) {
                const double a = i < k + 2 ? g[i - k] : 0.0;
                const double v = u0p[i] + h * (Rest ? a + ap[i] : a);
                up[i] = v;
                qp[i] = q0p[i] + h * v;
            }
        };
        const int paired = sys.pointDofs();
        if (StateSummary* summary = requestedSummary()) {
            *summary = sweepState(paired, sys.mass(), q, u, point, body);
            markSummarized();
        } else {
            A2 x, v;
            for (Eigen::Index i = 0; i < paired; i += 2) point(i, x, v);
            for (Eigen::Index k = paired; k < q.size(); k += 3) body(k);
        }
    }
};
}  // namespace

std::unique_ptr<Integrator> makeSymplecticEuler() {
    return std::make_unique<SymplecticEuler>();
}

}  // namespace phasebox::methods
