#pragma once
// The ODE view of Witkin & Baraff: what an integrator may know of the world.
//
// The state is second order: generalised positions q and velocities u of equal dimension,
// with q' = u (in 2D an angle's rate is the angular velocity, so this holds for boxes too)
// and u' = a(q, u, t) = M⁻¹·F(q, u, t). An integrator never knows what a spring is.

#include "physics/core/Types.h"

#include <vector>

namespace phasebox {

// Force Jacobians accumulated by the effects as triplets: K = ∂F/∂q, D = ∂F/∂u.
// The triplet buffers keep their capacity, so refilling them each step does not allocate
// once the largest pattern has been seen.
struct ForceJacobians {
    std::vector<Triplet> stiffness;  // K
    std::vector<Triplet> damping;    // D
    bool symmetric = true;           // false when some effect adds a non-symmetric term
    // Asked for by the implicit integrators: leave out the parts of K that can make
    // M − h·D − h²·K indefinite (a compressed spring's geometric stiffness, as Choi & Ko 2002
    // do for cloth), so that the matrix is symmetric positive definite and conjugate gradients
    // apply. Newton's residual stays exact, so iterating still converges to the true step.
    bool definite = false;

    // Empties the buffers (keeping their capacity) for the next evaluation.
    void clear() {
        stiffness.clear();
        damping.clear();
        symmetric = true;
    }
    void addStiffness(int row, int col, double value) { stiffness.emplace_back(row, col, value); }
    void addDamping(int row, int col, double value) { damping.emplace_back(row, col, value); }
    // Adds a 2×2 block at (row, col).
    void addStiffnessBlock(int row, int col, const Mat2& block) {
        for (int r = 0; r < 2; ++r)
            for (int c = 0; c < 2; ++c) addStiffness(row + r, col + c, block(r, c));
    }
    void addDampingBlock(int row, int col, const Mat2& block) {
        for (int r = 0; r < 2; ++r)
            for (int c = 0; c < 2; ++c) addDamping(row + r, col + c, block(r, c));
    }
};

class OdeSystem {
public:
    virtual ~OdeSystem() = default;

    virtual int dimension() const = 0;
    virtual const Vec& inverseMass() const = 0;
    virtual const Vec& mass() const = 0;

    // accel = M⁻¹·F(q, u, t). Returns the power of the non-conservative forces at (q, u, t),
    // which integrators accumulate into work_nc with their own quadrature weights.
    virtual double acceleration(double t, const Vec& q, const Vec& u, Vec& accel) = 0;

    // Power of the non-conservative forces alone (no accelerations), for methods whose last
    // force evaluation is not at the end point. Costs nothing when every effect is conservative.
    virtual double nonConservativePower(double t, const Vec& q, const Vec& u) = 0;

    // Forces F(q, u, t), for implicit methods' residuals. Returns the non-conservative power.
    virtual double forces(double t, const Vec& q, const Vec& u, Vec& force) = 0;

    // Forces and their Jacobians, for implicit methods. Returns the non-conservative power.
    virtual double forcesAndJacobians(double t, const Vec& q, const Vec& u, Vec& force,
                                      ForceJacobians& jacobians) = 0;
};

}  // namespace phasebox
