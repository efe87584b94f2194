// SHAKE, the joints' constraint force of the method after a step (JointSolver::shake(), whose
// comment in JointSolver.h says what it does): its iterations along the directions at the
// step's start, Anderson-mixed, its continuation along the directions at the iterate, and the
// implicit stiffness of the hinges and welds. The rest of the solver is in JointSolver.cpp.

#include "physics/joints/JointSolver.h"
#include "physics/joints/JointTuning.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace phasebox {

namespace {
// s: the time constant over which a body's scaled inertia lets go of a stiffness it no longer
// meets (stiffen()).
constexpr double kStiffnessHold = 2.0;
}  // namespace

bool JointSolver::shake(double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u, const Vec& invMass,
                        bool alongEnd) {
    // The equality rows in their directions at the step's start, factored once: each
    // iteration only evaluates C at q. With them the ropes that were taut and pulling at the
    // start: they pulled through the step as the derivative's equalities, and SHAKE keeps
    // them as it keeps a rod, so that a rope pendulum swings like a rod one. (Where the step
    // ends does not tell: symplectic Euler ends a swinging rope's step inside its length.)
    // Rows of the derivative's mode at q0 are these: a step's single derivative evaluation
    // (symplectic Euler's) has left them.
    stepLength_ = h;
    projectionFloor_ = joints::kProjectionTolerance * std::max(1.0, q.lpNorm<Eigen::Infinity>());
    if (!rowsAreAt(q0) || rowsMode_ != Mode::Dynamics)
        evaluateRows(Mode::Dynamics, q0, q0);  // (the velocities only enter J̇·u, unused here)
    dropInequalities();
    for (int k = 0; k < jointCount(); ++k)
        ropeShaken_[k] = joints_[k].type == Joint::Type::Rope && rows_[k].count > 0;
    const Vec& weights = stiffen(h, u0, q, u, invMass);
    cacheRotations(q);  // of q, not of rowsQ_ (q0)
    double worst = shakeViolation(q);
    shakeTolerance_ = std::clamp(joints::kShakeFraction * worst, projectionFloor_, shakeCeiling_);
    if (worst <= shakeTolerance_) return true;
    // Past the asymptotic regime (the step moved a joint a good part of its size): the
    // directions of the start are too far from the end's, and an impulse along them would pump
    // energy in. On along the end's directions instead.
    if (alongEnd || worst > shakeReach_) return shakeAlongEnd(h, q, u, weights);
    factor(weights);
    double previous = worst;
    for (int it = 0; it < joints::kProjectionIterations; ++it) {
        solve();
        accelerate(it > 0);
        applyShakeImpulse(h, weights, q, u);
        turnRotations(impulse_);
        worst = shakeViolation(q);
        if (worst <= shakeTolerance_) {
            // R(θ)·R(δ1)·R(δ2)·… are q's rotations to rounding: the rows at q take them.
            rotationsNowAt(q);
            return true;
        }
        // Not contracting: the directions of the start are too far from the end's. Back to
        // the state before this iteration, and on along the end's directions.
        if (worst > 0.5 * previous) {
            q -= impulse_;
            u -= impulse_ * (1.0 / h);
            return shakeAlongEnd(h, q, u, weights);
        }
        previous = worst;
    }
    return false;
}

const Vec& JointSolver::stiffen(double h, const Vec& u0, Vec& q, Vec& u, const Vec& invMass) {
    stiffened_ = false;
    if (!(implicitLimit_ > 0.0)) {
        // A method that meets no stiffness implicitly holds none: switched back to one that
        // does, the bodies start afresh.
        std::fill(heldStiffness_.begin(), heldStiffness_.end(), 0.0);
        return invMass;
    }
    if (!forcesKnown_) return invMass;
    // k = Σ arm·F over the body's hinges and welds, at the step's start (the rotations are
    // q0's: shake() has just evaluated the rows there, or the derivative did), from the
    // forces of the last derivative evaluation.
    stiffness_.assign(turningDofs_.size(), 0.0);  // no larger than before: no allocation
    for (int k = 0; k < jointCount(); ++k) {
        const Joint::Type type = joints_[k].type;
        if (type != Joint::Type::Hinge && type != Joint::Type::Weld) continue;
        for (int side = 0; side < 2; ++side) {
            const End& e = side == 0 ? endA_[k] : endB_[k];
            if (e.turns)
                stiffness_[e.slot] += (rotations_[e.slot] * e.local).dot(forceOn_[k][side]);
        }
    }
    bool stiff = false;
    const double decay = std::exp(-h / kStiffnessHold);
    for (std::size_t s = 0; s < turningDofs_.size(); ++s) {
        const int d = turningDofs_[s] + 2;
        // The stiffness held: the most of this step's and the last held one decayed (a NaN
        // force leaves the hold as it was).
        const double decayed = heldStiffness_[s] * decay;
        heldStiffness_[s] = stiffness_[s] > decayed ? stiffness_[s] : decayed;
        const double w = h * h * heldStiffness_[s] * invMass[d];
        if (!(w > implicitLimit_)) continue;
        if (!stiff) {
            stiffInvMass_ = invMass;  // same size: no allocation
            // Factors of stiffInvMass_'s last contents must not pass for this step's.
            if (factoredMass_ == &stiffInvMass_) factoredValid_ = false;
        }
        stiff = true;
        // The body turns as if its inertia were I·w/limit: its zig-zag then meets w = limit.
        const double inertia = w / implicitLimit_;
        const double omega = u0[d] + (u[d] - u0[d]) / inertia;
        q[d] -= h * (u[d] - omega);  // the step's own x' = x + h·v'
        u[d] = omega;
        stiffInvMass_[d] = invMass[d] / inertia;
    }
    stiffened_ = stiff;
    return stiff ? stiffInvMass_ : invMass;
}

bool JointSolver::shakeAlongEnd(double h, Vec& q, Vec& u, const Vec& weights) {
    // Newton's projection in the mass metric, the rows evaluated at each iterate (converging
    // quadratically wherever it starts near enough), the velocities moved with the positions
    // as SHAKE moves them. Ropes past their length are held with the equalities.
    double previous = std::numeric_limits<double>::infinity();
    struct Along {
        bool& flag;
        explicit Along(bool& f) : flag(f) { flag = true; }
        ~Along() { flag = false; }
    } along(shakingAlongEnd_);
    for (int it = 0; it < joints::kProjectionIterations; ++it) {
        evaluateRows(Mode::Position, q, u);
        dropInequalities();
        const double worst = worstViolation();
        if (worst <= projectionFloor_) return true;
        if (!(worst < previous)) return false;  // diverging (or NaN): the world's projection
        previous = worst;
        factor(weights);
        for (int k = 0; k < jointCount(); ++k) {
            rhs_[k] = -rows_[k].c;
            joints::zeroFrom(rhs_[k], rows_[k].count);
        }
        solve();
        applyShakeImpulse(h, weights, q, u);
    }
    return false;
}

void JointSolver::accelerate(bool withPrevious) {
    // The iteration is a fixed point, λ ← λ + f(λ) with f = (J0·W·J0ᵀ)⁻¹·(−C), contracting
    // linearly (by 3 to 10 an iteration on a whipping chain). Anderson mixing over the last
    // kAndersonDepth iterations: the step f − Σ γ_j·(Δλ_j + Δf_j), with γ the least-squares
    // fit of f by the Δf_j. Where a few modes contract by fixed ratios (the asymptotic regime)
    // that removes them: with one mode, f_k = ρ·f_(k−1), it is the step to the limit, f/(1 − ρ).
    const int m = jointCount();
    if (!withPrevious) {
        andersonCount_ = andersonNext_ = 0;
        previousStep_ = lastDelta_ = lambda_;  // same sizes: no allocation
        return;
    }
    // This iteration's differences into the ring: Δf = f − f_prev, Δλ = the last move.
    const int slot = andersonNext_;
    std::vector<Vec3>& df = andersonDf_[slot];
    std::vector<Vec3>& dl = andersonDl_[slot];
    for (int k = 0; k < m; ++k) {
        df[k] = lambda_[k] - previousStep_[k];
        dl[k] = lastDelta_[k];
        previousStep_[k] = lambda_[k];
    }
    andersonNext_ = (andersonNext_ + 1) % kAndersonDepth;
    andersonCount_ = std::min(andersonCount_ + 1, kAndersonDepth);
    const int n = andersonCount_;
    // Over the B rows a joint can have (a third row is zero where B = 2).
    const auto overRows = [&](auto&& pass) {
        if (blockRows_ == 2)
            pass(std::integral_constant<int, 2>{});
        else
            pass(std::integral_constant<int, 3>{});
    };
    // The Gram matrix of the Δf keeps its entries between iterations: only the new difference's
    // products are new, and with λ's they take one pass.
    std::array<double, kAndersonDepth> gram{}, fit{};
    overRows([&](auto rows) {
        constexpr int B = decltype(rows)::value;
        for (int k = 0; k < m; ++k)
            for (int i = 0; i < n; ++i) {
                const auto dfi = andersonDf_[i][k].template head<B>();
                gram[i] += dfi.dot(df[k].template head<B>());
                fit[i] += dfi.dot(lambda_[k].template head<B>());
            }
    });
    for (int i = 0; i < n; ++i) andersonGram_(i, slot) = andersonGram_(slot, i) = gram[i];
    Eigen::Matrix<double, kAndersonDepth, kAndersonDepth> g =
        Eigen::Matrix<double, kAndersonDepth, kAndersonDepth>::Identity();
    Eigen::Matrix<double, kAndersonDepth, 1> rhs = Eigen::Matrix<double, kAndersonDepth, 1>::Zero();
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) g(i, j) = andersonGram_(i, j);
        rhs[i] = fit[i];
    }
    // A relative 1e-10 on the diagonal keeps the fit defined where two differences align.
    double scale = 0.0;
    for (int i = 0; i < n; ++i) scale = std::max(scale, g(i, i));
    if (!(scale > 0.0)) {
        lastDelta_ = lambda_;
        return;
    }
    for (int i = 0; i < n; ++i) g(i, i) += 1e-10 * scale;
    const Eigen::Matrix<double, kAndersonDepth, 1> gamma = g.ldlt().solve(rhs);
    overRows([&](auto rows) {
        constexpr int B = decltype(rows)::value;
        for (int k = 0; k < m; ++k) {
            Eigen::Matrix<double, B, 1> step = lambda_[k].template head<B>();
            for (int i = 0; i < n; ++i)
                step -= gamma[i] * (andersonDl_[i][k].template head<B>() +
                                    andersonDf_[i][k].template head<B>());
            lambda_[k].template head<B>() = step;
        }
    });
    lastDelta_ = lambda_;
}

}  // namespace phasebox
