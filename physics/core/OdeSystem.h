#pragma once
// The ODE view of Witkin & Baraff: what an integrator may know of the world.
//
// The state is second order: generalised positions q and velocities u of equal dimension,
// with q' = u (in 2D an angle's rate is the angular velocity, so this holds for boxes too)
// and u' = a(q, u, t) = M⁻¹·F(q, u, t). An integrator never knows what a spring is.

#include "physics/core/Types.h"

#include <vector>

namespace phasebox {

// A 2 × 2 block of a Jacobian at (row, col), row-major: the coupling of two points.
struct JacobianBlock {
    int row = 0, col = 0;
    double v[4] = {0.0, 0.0, 0.0, 0.0};
};

// A two-point coupling S between points a and b (first DOFs; −1 for a fixed end): adds S at
// (a, a) and (b, b) and −S at (a, b) and (b, a), the Jacobian of a force that depends on
// p_a − p_b only (springs, Coulomb and gravity pairs). One record instead of four blocks.
struct JacobianPair {
    int a = -1, b = -1;
    double v[4] = {0.0, 0.0, 0.0, 0.0};
};

// Force Jacobians accumulated by the effects: K = ∂F/∂q, D = ∂F/∂u, as two-point pairs (the
// bulk of a cloth's), 2 × 2 blocks and single entries (box angles and the like); duplicates
// add up. The buffers keep their capacity, so refilling them each step does not allocate
// once the largest pattern has been seen.
struct ForceJacobians {
    std::vector<Triplet> stiffness;  // K's single entries
    std::vector<Triplet> damping;    // D's single entries
    std::vector<JacobianBlock> stiffnessBlocks, dampingBlocks;
    std::vector<JacobianPair> stiffnessPairs, dampingPairs;
    bool symmetric = true;  // false when some effect adds a non-symmetric term
    // Asked for by the implicit integrators: leave out the parts of K that can make
    // M − h·D − h²·K indefinite (a compressed spring's geometric stiffness, as Choi & Ko 2002
    // do for cloth), so that the matrix is symmetric positive definite and conjugate gradients
    // apply. Newton's residual stays exact, so iterating still converges to the true step.
    bool definite = false;

    // Empties the buffers (keeping their capacity) for the next evaluation.
    void clear() {
        stiffness.clear();
        damping.clear();
        stiffnessBlocks.clear();
        dampingBlocks.clear();
        stiffnessPairs.clear();
        dampingPairs.clear();
        symmetric = true;
    }
    bool empty() const { return !hasStiffness() && !hasDamping(); }
    bool hasStiffness() const {
        return !stiffness.empty() || !stiffnessBlocks.empty() || !stiffnessPairs.empty();
    }
    bool hasDamping() const {
        return !damping.empty() || !dampingBlocks.empty() || !dampingPairs.empty();
    }
    void addStiffness(int row, int col, double value) { stiffness.emplace_back(row, col, value); }
    void addDamping(int row, int col, double value) { damping.emplace_back(row, col, value); }
    // Adds a 2×2 block at (row, col).
    void addStiffnessBlock(int row, int col, const Mat2& block) {
        stiffnessBlocks.push_back(make<JacobianBlock>(row, col, block));
    }
    void addDampingBlock(int row, int col, const Mat2& block) {
        dampingBlocks.push_back(make<JacobianBlock>(row, col, block));
    }
    void addStiffnessPair(int a, int b, const Mat2& coupling) {
        stiffnessPairs.push_back(make<JacobianPair>(a, b, coupling));
    }
    void addDampingPair(int a, int b, const Mat2& coupling) {
        dampingPairs.push_back(make<JacobianPair>(a, b, coupling));
    }
    // All of K (or D) as triplets, blocks and pairs spelled out: for analysis and tests.
    std::vector<Triplet> stiffnessTriplets() const {
        return spelledOut(stiffness, stiffnessBlocks, stiffnessPairs);
    }
    std::vector<Triplet> dampingTriplets() const {
        return spelledOut(damping, dampingBlocks, dampingPairs);
    }
    // Calls block(row, col, v, sign) for each 2 × 2 block a pair stands for.
    template <typename Block>
    static void forEachPairBlock(const JacobianPair& p, Block&& block) {
        if (p.a >= 0) block(p.a, p.a, p.v, 1.0);
        if (p.a >= 0 && p.b >= 0) {
            block(p.a, p.b, p.v, -1.0);
            block(p.b, p.a, p.v, -1.0);
        }
        if (p.b >= 0) block(p.b, p.b, p.v, 1.0);
    }

private:
    template <typename Record>
    static Record make(int first, int second, const Mat2& m) {
        return {first, second, {m(0, 0), m(0, 1), m(1, 0), m(1, 1)}};
    }
    static std::vector<Triplet> spelledOut(const std::vector<Triplet>& single,
                                           const std::vector<JacobianBlock>& blocks,
                                           const std::vector<JacobianPair>& pairs) {
        std::vector<Triplet> all = single;
        auto add = [&all](int row, int col, const double* v, double sign) {
            for (int e = 0; e < 4; ++e) all.emplace_back(row + e / 2, col + e % 2, sign * v[e]);
        };
        for (const JacobianBlock& b : blocks) add(b.row, b.col, b.v, 1.0);
        for (const JacobianPair& p : pairs) forEachPairBlock(p, add);
        return all;
    }
};

class OdeSystem {
public:
    virtual ~OdeSystem() = default;

    virtual int dimension() const = 0;
    virtual const Vec& inverseMass() const = 0;
    virtual const Vec& mass() const = 0;
    // DOFs [0, pointDofs()) are the (x, y) pairs of points, which a multigrid solver
    // aggregates together; 0 when the system does not say.
    virtual int pointDofs() const { return 0; }
    // One evaluation's cost in the units of core/WorkUnits.h; by default one a coordinate.
    virtual double workUnits() const { return dimension(); }

    // accel = M⁻¹·F(q, u, t). Returns the power of the non-conservative forces at (q, u, t),
    // which integrators accumulate into work_nc with their own quadrature weights.
    virtual double acceleration(double t, const Vec& q, const Vec& u, Vec& accel) = 0;

    // The same acceleration split as a = ā + a_rest(q, u, t): ā one vector added to the (x, y)
    // of every point and body (uniform fields such as gravity, which a velocity update folds in
    // as a constant, the way Box2D applies gravity in its integrate-velocities loop), and
    // a_rest written into rest only when `hasRest` (some effect is not uniform). Systems that
    // do not split report everything as the rest.
    struct SplitAcceleration {
        Vec2 uniform = Vec2::Zero();
        bool hasRest = true;
        double power = 0.0;  // as acceleration() returns
    };
    virtual SplitAcceleration accelerationSplit(double t, const Vec& q, const Vec& u, Vec& rest) {
        return {Vec2::Zero(), true, acceleration(t, q, u, rest)};
    }

    // Power of the non-conservative forces alone (no accelerations), for methods whose last
    // force evaluation is not at the end point. Costs nothing when every effect is conservative.
    virtual double nonConservativePower(double t, const Vec& q, const Vec& u) = 0;

    // Forces F(q, u, t), for implicit methods' residuals. Returns the non-conservative power.
    virtual double forces(double t, const Vec& q, const Vec& u, Vec& force) = 0;

    // Forces and their Jacobians, for implicit methods. Returns the non-conservative power.
    virtual double forcesAndJacobians(double t, const Vec& q, const Vec& u, Vec& force,
                                      ForceJacobians& jacobians) = 0;

    // Whether some force that acts at one of the two states does not act at the other (a
    // penalty contact beginning or ending between them): a Jacobian taken at q0 does not see it.
    virtual bool activeSetChanged(const Vec& q0, const Vec& q1) {
        (void)q0, (void)q1;
        return false;
    }
};

}  // namespace phasebox
