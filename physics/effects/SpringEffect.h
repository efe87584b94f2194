#pragma once
// Damped springs between two points, each a dynamic particle, a point fixed in a dynamic box,
// or a fixed world point: F_a = −(k·(L − L₀) + c·L̇)·û, F_b = −F_a, with û = (p_a − p_b)/L.
// Elastic potential ½·k·(L − L₀)²; the damping along the axis does work −c·L̇² (to work_nc).
// The world creates this effect when the first spring appears and drops it with the last.

#include "physics/effects/Effect.h"

#include <vector>

namespace phasebox {

struct SpringTerm {
    BodyPoint a, b;
    double stiffness = 0.0;
    double damping = 0.0;
    double restLength = 0.0;
};

class SpringEffect final : public Effect {
public:
    SpringEffect() : Effect(effectName::springs) {}

    void setTerms(std::vector<SpringTerm> terms);
    const std::vector<SpringTerm>& terms() const { return terms_; }

    double addForces(double t, const Vec& q, const Vec& u, Vec& force) override;
    double nonConservativePower(double t, const Vec& q, const Vec& u) override;
    void addJacobians(double t, const Vec& q, const Vec& u, ForceJacobians& jacobians) override;
    double addForcesAndJacobians(double t, const Vec& q, const Vec& u, Vec& force,
                                 ForceJacobians& jacobians) override;
    double potentialEnergy(const Vec& q) const override;
    bool hasNonConservativePart() const override { return anyDamping_; }

    // Signed tension k·(L − L₀) + c·L̇ of spring i in state (q, u) (positive = stretched),
    // for drawing springs coloured by tension.
    double tension(std::size_t i, const Vec& q, const Vec& u) const;

private:
    // A spring between two points without rotation (particles or fixed points), read without
    // BodyPoint's dispatch: a cloth's springs, when every spring is one.
    struct PointSpring {
        int a = -1, b = -1;   // first DOFs; −1 for a fixed end
        Vec2 fixedA, fixedB;  // a fixed end's position
        double stiffness = 0.0, damping = 0.0, restLength = 0.0;
        // p_a − p_b for positions q.
        void separation(const double* q, double& dx, double& dy) const {
            dx = (a >= 0 ? q[a] : fixedA.x()) - (b >= 0 ? q[b] : fixedB.x());
            dy = (a >= 0 ? q[a + 1] : fixedA.y()) - (b >= 0 ? q[b + 1] : fixedB.y());
        }
    };
    template <bool WithJacobians>
    double pointForces(const Vec& q, const Vec& u, Vec& force, ForceJacobians* jacobians) const;

    std::vector<SpringTerm> terms_;
    std::vector<PointSpring> points_;  // terms_ again, when every one is point to point
    bool anyDamping_ = false;
};

}  // namespace phasebox
