#include "physics/integrators/NewtonVelocitySolver.h"

namespace phasebox {

void NewtonVelocitySolver::reset(int n) {
    force_.setZero(n);
    rhs_.setZero(n);
    delta_.setZero(n);
    qe_.setZero(n);
    kU_.setZero(n);
    stiffness_.resize(n, n);
    damping_.resize(n, n);
    matrix_.resize(n, n);
}

bool NewtonVelocitySolver::solveLinear(OdeSystem& sys, double c) {
    const Vec& mass = sys.mass();
    const int n = static_cast<int>(mass.size());
    if (jac_.stiffness.empty() && jac_.damping.empty()) {
        // No effect has a Jacobian: A = M is diagonal.
        delta_ = rhs_.cwiseProduct(sys.inverseMass());
        return true;
    }
    triplets_.clear();
    triplets_.reserve(jac_.stiffness.size() + jac_.damping.size() + n);
    for (int i = 0; i < n; ++i) triplets_.emplace_back(i, i, mass[i]);
    for (const Triplet& k : jac_.stiffness) triplets_.emplace_back(k.row(), k.col(), -c * c * k.value());
    for (const Triplet& d : jac_.damping) triplets_.emplace_back(d.row(), d.col(), -c * d.value());
    matrix_.setFromTriplets(triplets_.begin(), triplets_.end());

    if (jac_.symmetric) {
        ldlt_.compute(matrix_);
        if (ldlt_.info() == Eigen::Success) {
            delta_ = ldlt_.solve(rhs_);
            if (ldlt_.info() == Eigen::Success && delta_.allFinite()) return true;
        }
    }
    // Non-symmetric Jacobians, or an indefinite matrix LDLᵀ could not factor: general LU.
    lu_.analyzePattern(matrix_);
    lu_.factorize(matrix_);
    if (lu_.info() != Eigen::Success) return false;
    delta_ = lu_.solve(rhs_);
    return lu_.info() == Eigen::Success && delta_.allFinite();
}

NewtonVelocitySolver::Result NewtonVelocitySolver::solve(OdeSystem& sys, double t, double c,
                                                         const Vec& q0, const Vec& u0, Vec& v,
                                                         int maxIterations, bool untilConverged,
                                                         double relativeTolerance) {
    Result result;
    const Vec& mass = sys.mass();

    // Iteration 1: linearise about the start (Baraff & Witkin).
    jac_.clear();
    result.power = sys.forcesAndJacobians(t, q0, u0, force_, jac_);
    rhs_ = c * force_;
    if (!jac_.stiffness.empty()) {
        stiffness_.setFromTriplets(jac_.stiffness.begin(), jac_.stiffness.end());
        kU_.noalias() = stiffness_ * u0;
        rhs_ += (c * c) * kU_;
    }
    if (!solveLinear(sys, c)) return result;
    ++result.linearSolves;
    v = u0 + delta_;
    result.iterations = 1;
    result.lastCorrection = delta_.lpNorm<Eigen::Infinity>();

    // Further Newton iterations on R(v) = M·(v − u₀) − c·F(q₀ + c·v, v).
    while (result.iterations < maxIterations) {
        qe_ = q0 + c * v;
        jac_.clear();
        result.power = sys.forcesAndJacobians(t, qe_, v, force_, jac_);
        rhs_ = c * force_ - mass.cwiseProduct(v - u0);  // −R
        if (!solveLinear(sys, c)) return result;
        ++result.linearSolves;
        v += delta_;
        ++result.iterations;
        result.lastCorrection = delta_.lpNorm<Eigen::Infinity>();
        if (!v.allFinite()) return result;
        if (untilConverged &&
            result.lastCorrection <= relativeTolerance * (1.0 + v.lpNorm<Eigen::Infinity>()))
            break;
    }
    result.ok = v.allFinite();
    return result;
}

}  // namespace phasebox
