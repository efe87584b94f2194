#include "physics/linear/NewtonVelocitySolver.h"

#include <cmath>

namespace phasebox {

// Updates this small relative to the velocity are round-off when they stop shrinking.
constexpr double kRoundOffFloor = 1e-9;
// Newton iterations a step takes when a force switches on or off within it (activeSetChanged):
// a piecewise-linear force converges in a few once the switch is inside the iterate.
constexpr int kActiveSetIterations = 12;

void NewtonVelocitySolver::reset(int n) {
    force_.setZero(n);
    rhs_.setZero(n);
    delta_.setZero(n);
    qe_.setZero(n);
    kU_.setZero(n);
    guess_.setZero(n);
    for (Vec* v : {&residual_, &z_, &direction_, &product_}) v->setZero(n);
    matrix_.resize(n, n);
    keys_.clear();  // the next assembly builds the pattern anew
    solvesSinceCoarse_ = iterationsAfterCoarse_ = lastIterations_ = 0;
}

namespace {
long long key(int row, int col) {
    return (static_cast<long long>(row) << 32) | static_cast<unsigned>(col);
}
}  // namespace

// The contributions, in the order keys_ and the slot tables list them: the masses, K's and
// D's single entries, their blocks, and their pairs (each standing for up to four blocks).
// A block takes two slots: where its (r, c) entry goes and where its second row's (r + 1, c)
// entry goes, if the target keeps rows together (the multigrid's row-major blocks, whose
// (r, c + 1) follows (r, c)); or its (r, c) and its second column's (r, c + 1), if the target
// keeps columns together (matrix_, column-major, whose (r + 1, c) follows (r, c)).
template <typename Visit>
void NewtonVelocitySolver::forEachContribution(double c, Visit&& visit) const {
    const double kScale = -c * c, dScale = -c;
    for (const Triplet& t : jac_.stiffness) visit.single(t.row(), t.col(), kScale * t.value());
    for (const Triplet& t : jac_.damping) visit.single(t.row(), t.col(), dScale * t.value());
    for (const JacobianBlock& b : jac_.stiffnessBlocks)
        visit.block(key(b.row, b.col), b.row, b.col, b.v, kScale);
    for (const JacobianBlock& b : jac_.dampingBlocks)
        visit.block(key(b.row, b.col), b.row, b.col, b.v, dScale);
    for (const auto* pairs : {&jac_.stiffnessPairs, &jac_.dampingPairs}) {
        const double scale = pairs == &jac_.stiffnessPairs ? kScale : dScale;
        for (const JacobianPair& p : *pairs) {
            visit.pairKey(key(p.a + 1, p.b + 1));
            ForceJacobians::forEachPairBlock(p,
                                             [&](int row, int col, const double* v, double sign) {
                                                 visit.block(-1, row, col, v, sign * scale);
                                             });
        }
    }
}

bool NewtonVelocitySolver::refill(const Vec& mass, double c, Target& target) {
    const int n = static_cast<int>(mass.size());
    const std::size_t count = n + jac_.stiffness.size() + jac_.damping.size() +
                              jac_.stiffnessBlocks.size() + jac_.dampingBlocks.size() +
                              jac_.stiffnessPairs.size() + jac_.dampingPairs.size();
    if (count != keys_.size() || target.slots.empty()) return false;
    std::fill(target.values, target.values + target.count, 0.0);
    struct Filler {
        double* values;
        const long long* keys;
        const int* slot;
        bool rowMajor;
        bool ok = true;
        void single(int row, int col, double v) {
            ok = ok && *keys++ == key(row, col);
            values[*slot++] += v;
        }
        void block(long long k, int, int, const double* v, double scale) {
            if (k >= 0) ok = ok && *keys++ == k;
            double* first = values + *slot++;
            double* second = values + *slot++;
            first[0] += scale * v[0];
            second[0] += scale * v[rowMajor ? 2 : 1];
            first[1] += scale * v[rowMajor ? 1 : 2];
            second[1] += scale * v[3];
        }
        void pairKey(long long k) { ok = ok && *keys++ == k; }
    } filler{target.values, keys_.data() + n, target.slots.data(), target.rowMajor};
    for (int i = 0; i < n; ++i) target.values[*filler.slot++] += mass[i];
    // Pattern checks and sums run in one pass; a mismatch (effects came or went) is caught
    // before the values are used, and the caller then builds the pattern anew.
    forEachContribution(c, filler);
    return filler.ok;
}

void NewtonVelocitySolver::recordSlots(int n, double c, Target& target,
                                       const std::function<int(int, int)>& place) {
    target.slots.clear();
    for (int i = 0; i < n; ++i) target.slots.push_back(place(i, i));
    struct Recorder {
        std::vector<int>& slots;
        const std::function<int(int, int)>& place;
        bool rowMajor;
        void single(int row, int col, double) { slots.push_back(place(row, col)); }
        void block(long long, int row, int col, const double*, double) {
            slots.push_back(place(row, col));
            slots.push_back(rowMajor ? place(row + 1, col) : place(row, col + 1));
        }
        void pairKey(long long) {}
    } recorder{target.slots, place, target.rowMajor};
    forEachContribution(c, recorder);
}

void NewtonVelocitySolver::assemble(OdeSystem& sys, double c) {
    const Vec& mass = sys.mass();
    direct_.values = matrix_.valuePtr();
    direct_.count = static_cast<std::size_t>(matrix_.nonZeros());
    if (refill(mass, c, direct_)) return;
    // A new pattern (the first step, or effects that came or went): build it and record each
    // contribution's place in the matrix's values, so the next steps only add into them.
    const int n = static_cast<int>(mass.size());
    triplets_.clear();
    keys_.clear();
    for (int i = 0; i < n; ++i) {
        triplets_.emplace_back(i, i, mass[i]);
        keys_.push_back(key(i, i));
    }
    struct Collector {
        std::vector<Triplet>& triplets;
        std::vector<long long>& keys;
        void single(int row, int col, double v) {
            triplets.emplace_back(row, col, v);
            keys.push_back(key(row, col));
        }
        void block(long long k, int row, int col, const double* v, double scale) {
            for (int e = 0; e < 4; ++e)
                triplets.emplace_back(row + e / 2, col + e % 2, scale * v[e]);
            if (k >= 0) keys.push_back(k);
        }
        void pairKey(long long k) { keys.push_back(k); }
    } collector{triplets_, keys_};
    forEachContribution(c, collector);
    matrix_.resize(n, n);
    matrix_.setFromTriplets(triplets_.begin(), triplets_.end());
    matrix_.makeCompressed();
    recordSlots(n, c, direct_, [this](int row, int col) {
        return static_cast<int>(&matrix_.coeffRef(row, col) - matrix_.valuePtr());
    });
    direct_.values = matrix_.valuePtr();
    direct_.count = static_cast<std::size_t>(matrix_.nonZeros());
    iterative_.slots.clear();  // the multigrid is built anew for this pattern
    ldltAnalyzed_ = luAnalyzed_ = false;
}

bool NewtonVelocitySolver::assembleIterative(OdeSystem& sys, double c, bool refreshCoarse) {
    const Vec& mass = sys.mass();
    if (!iterative_.slots.empty()) {
        iterative_.values = multigrid_.fineValues();
        iterative_.count = multigrid_.fineValueCount();
        if (refill(mass, c, iterative_)) {
            multigrid_.refresh(refreshCoarse);
            coarseFresh_ = refreshCoarse;
            return true;
        }
    }
    // First step of a pattern: assemble matrix_ (whose values weigh the aggregation), build
    // the hierarchy on it, and record where each contribution goes in its blocked copy.
    assemble(sys, c);
    const int n = static_cast<int>(mass.size());
    multigrid_.build(matrix_, sys.pointDofs());
    iterative_.rowMajor = true;
    recordSlots(n, c, iterative_,
                [this](int row, int col) { return multigrid_.fineOffset(row, col); });
    iterative_.values = multigrid_.fineValues();
    iterative_.count = multigrid_.fineValueCount();
    if (!refill(mass, c, iterative_)) return false;
    multigrid_.refresh();
    coarseFresh_ = true;
    return true;
}

bool NewtonVelocitySolver::solveLinear(OdeSystem& sys, double c, bool warmStart, Result& result) {
    if (jac_.empty()) {
        // No effect has a Jacobian: A = M is diagonal.
        delta_ = rhs_.cwiseProduct(sys.inverseMass());
        return true;
    }
    const int n = static_cast<int>(sys.mass().size());
    if (jac_.symmetric && n >= kIterativeThreshold) {
        // Large symmetric systems: conjugate gradients preconditioned by aggregation
        // multigrid, on the multigrid's blocked copy of the matrix, assembled in place.
        // The first (Baraff & Witkin) solve is a linearisation anyway and tolerates a loose
        // residual; Newton refinements need a tight one or they could not converge.
        // The coarse level's factorisation (about a tenth of the work of a step) is kept for
        // up to kCoarseLag first solves while the cloth changes slowly. It is redone as soon as
        // a solve needs more iterations than the one after the last factorisation (plus 2),
        // and a solve that does not converge within that margin is repeated with a fresh one.
        // Newton refinements always take a fresh one.
        if (warmStart) ++solvesSinceCoarse_;
        const bool lag = warmStart && solvesSinceCoarse_ <= kCoarseLag &&
                         lastIterations_ <= iterationsAfterCoarse_ + 2;
        if (assembleIterative(sys, c, !lag)) {
            const double tolerance = warmStart ? kIterativeTolerance : kRefinementTolerance;
            const int maxIterations = std::max(200, n / 4);
            for (int attempt = 0; attempt < 2; ++attempt) {
                if (attempt == 1) {
                    if (coarseFresh_) break;
                    multigrid_.refresh(true);
                    coarseFresh_ = true;
                }
                const bool fresh = coarseFresh_;
                if (warmStart)
                    delta_ = guess_;
                else
                    delta_.setZero();
                int iterations = 0;
                double residual = 0.0;
                const int cap = fresh ? maxIterations
                                      : std::min(maxIterations, 2 * iterationsAfterCoarse_ + 10);
                const bool converged = conjugateGradient(tolerance, cap, iterations, residual);
                result.linearIterations += iterations;
                result.linearResidual = residual;
                if (warmStart) {
                    lastIterations_ = iterations;
                    if (fresh) {
                        iterationsAfterCoarse_ = iterations;
                        solvesSinceCoarse_ = 0;
                    }
                }
                if (converged && delta_.allFinite()) {
                    if (warmStart) guess_ = delta_;
                    return true;
                }
            }
        }
        // Not converged (an indefinite matrix despite the definite Jacobian): fall through to
        // the direct solvers below.
    }
    assemble(sys, c);
    if (jac_.symmetric) {
        if (!ldltAnalyzed_) {
            ldlt_.analyzePattern(matrix_);
            ldltAnalyzed_ = true;
        }
        ldlt_.factorize(matrix_);
        if (ldlt_.info() == Eigen::Success) {
            delta_ = ldlt_.solve(rhs_);
            if (ldlt_.info() == Eigen::Success && delta_.allFinite()) return true;
        }
    }
    // Non-symmetric Jacobians, or an indefinite matrix LDLᵀ could not factor: general LU.
    if (!luAnalyzed_) {
        lu_.analyzePattern(matrix_);
        luAnalyzed_ = true;
    }
    lu_.factorize(matrix_);
    if (lu_.info() != Eigen::Success) return false;
    delta_ = lu_.solve(rhs_);
    return lu_.info() == Eigen::Success && delta_.allFinite();
}

bool NewtonVelocitySolver::conjugateGradient(double tolerance, int maxIterations, int& iterations,
                                             double& residual) {
    // Conjugate gradients preconditioned by a multigrid V-cycle, solving matrix_·delta_ =
    // rhs_ from the guess already in delta_. Every vector is a member sized once, so a step
    // allocates nothing. Stops when ‖r‖ ≤ tolerance·‖rhs‖.
    const double rhsNorm = rhs_.norm();
    if (!(rhsNorm > 0.0)) {
        delta_.setZero();
        residual = 0.0;
        return true;
    }
    // The last step's answer is a good start while the motion is smooth; when the cloth
    // changes direction it is worse than no guess at all (measured: 231 iterations per step
    // warm against 72 cold for a 64 × 64 cloth, before the multigrid). So the guess g is scaled
    // by the α that minimises the error in A's norm along it, α = gᵀ·rhs / gᵀ·A·g: near 0 when
    // the cloth turns round, near 1 while it moves smoothly, and never worse than either
    // (measured on the 64 × 64 cloth: 9.2 iterations per step against 10.5 with the guess
    // taken whole or dropped). The product A·g is the one the residual needs anyway.
    multigrid_.multiply(delta_, product_);  // matrix_ in the multigrid's blocked form
    const double curvature0 = delta_.dot(product_);
    const double scale = curvature0 > 0.0 ? delta_.dot(rhs_) / curvature0 : 0.0;
    delta_ *= scale;
    residual_ = rhs_ - scale * product_;
    multigrid_.apply(residual_, z_);
    direction_ = z_;
    double rz = residual_.dot(z_);
    double residualSquared = residual_.squaredNorm();
    const int n = static_cast<int>(rhs_.size());
    for (iterations = 0; iterations < maxIterations; ++iterations) {
        residual = std::sqrt(residualSquared) / rhsNorm;
        if (residual <= tolerance) return true;
        multigrid_.multiply(direction_, product_);
        const double curvature = direction_.dot(product_);
        if (!(curvature > 0.0)) return false;  // not positive definite along this direction
        const double alpha = rz / curvature;
        // The two updates and the new residual's norm in one pass.
        double* x = delta_.data();
        double* r = residual_.data();
        const double* p = direction_.data();
        const double* ap = product_.data();
        residualSquared = 0.0;
        for (int i = 0; i < n; ++i) {
            x[i] += alpha * p[i];
            r[i] -= alpha * ap[i];
            residualSquared += r[i] * r[i];
        }
        multigrid_.apply(residual_, z_);
        const double rzNext = residual_.dot(z_);
        direction_ = z_ + (rzNext / rz) * direction_;
        rz = rzNext;
    }
    residual = residual_.norm() / rhsNorm;
    return residual <= tolerance;
}

NewtonVelocitySolver::Result NewtonVelocitySolver::solve(OdeSystem& sys, double t, double c,
                                                         const Vec& q0, const Vec& u0, Vec& v,
                                                         int maxIterations, bool untilConverged,
                                                         double relativeTolerance) {
    Result result;
    const Vec& mass = sys.mass();

    // Iteration 1: linearise about the start (Baraff & Witkin).
    jac_.clear();
    jac_.definite = true;
    result.power = sys.forcesAndJacobians(t, q0, u0, force_, jac_);
    rhs_ = c * force_;
    if (jac_.hasStiffness()) {
        kU_.setZero();  // K·u₀ straight from the entries (duplicates add up, as in K)
        for (const Triplet& t : jac_.stiffness) kU_[t.row()] += t.value() * u0[t.col()];
        for (const JacobianBlock& b : jac_.stiffnessBlocks) {
            kU_[b.row] += b.v[0] * u0[b.col] + b.v[1] * u0[b.col + 1];
            kU_[b.row + 1] += b.v[2] * u0[b.col] + b.v[3] * u0[b.col + 1];
        }
        for (const JacobianPair& p : jac_.stiffnessPairs) {
            // S·(u_a − u_b) at a, its negative at b (a fixed end has no velocity).
            const double ux = (p.a >= 0 ? u0[p.a] : 0.0) - (p.b >= 0 ? u0[p.b] : 0.0);
            const double uy = (p.a >= 0 ? u0[p.a + 1] : 0.0) - (p.b >= 0 ? u0[p.b + 1] : 0.0);
            const double fx = p.v[0] * ux + p.v[1] * uy, fy = p.v[2] * ux + p.v[3] * uy;
            if (p.a >= 0) {
                kU_[p.a] += fx;
                kU_[p.a + 1] += fy;
            }
            if (p.b >= 0) {
                kU_[p.b] -= fx;
                kU_[p.b + 1] -= fy;
            }
        }
        rhs_ += (c * c) * kU_;
    }
    if (!solveLinear(sys, c, true, result)) return result;
    ++result.linearSolves;
    v = u0 + delta_;
    result.iterations = 1;
    result.lastCorrection = delta_.lpNorm<Eigen::Infinity>();
    // A force that switches on or off within the step (a penalty contact beginning): the
    // linearisation about the start does not see it, and the step taken without it ends deep
    // in the overlap with the energy of a spring compressed from nothing. Newton then goes on
    // until it has converged with the switch in.
    if (maxIterations < kActiveSetIterations) {
        qe_ = q0 + c * v;
        if (sys.activeSetChanged(q0, qe_)) {
            maxIterations = kActiveSetIterations;
            untilConverged = true;
        }
    }

    // Further Newton iterations on R(v) = M·(v − u₀) − c·F(q₀ + c·v, v).
    while (result.iterations < maxIterations) {
        qe_ = q0 + c * v;
        jac_.clear();
        jac_.definite = true;
        result.power = sys.forcesAndJacobians(t, qe_, v, force_, jac_);
        rhs_ = c * force_ - mass.cwiseProduct(v - u0);  // −R
        if (!solveLinear(sys, c, false, result)) return result;
        ++result.linearSolves;
        v += delta_;
        ++result.iterations;
        const double previous = result.lastCorrection;
        result.lastCorrection = delta_.lpNorm<Eigen::Infinity>();
        if (!v.allFinite()) return result;
        if (!untilConverged) continue;
        const double scale = 1.0 + v.lpNorm<Eigen::Infinity>();
        if (result.lastCorrection <= relativeTolerance * scale) break;
        // At the round-off floor the update stops shrinking (quadratic convergence would cut it
        // by far more than half): further iterations cannot improve the answer.
        if (result.lastCorrection <= kRoundOffFloor * scale &&
            result.lastCorrection > 0.5 * previous)
            break;
    }
    result.ok = v.allFinite();
    return result;
}

}  // namespace phasebox
