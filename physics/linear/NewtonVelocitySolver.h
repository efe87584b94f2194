#pragma once
// The Newton solve shared by the implicit methods. Both look for a velocity v such that
//     M·(v − u₀) = c·F(q₀ + c·v, v)
// with c = h for backward Euler (v is the end velocity) and c = h/2 for the implicit midpoint
// rule (v is the midpoint velocity). The Jacobian of that residual is A = M − c·D − c²·K.
//
// The first iteration linearises F about the start (q₀, u₀), which is exactly the step of
// Baraff & Witkin 1998: (M − c·D − c²·K)·Δv = c·(F₀ + c·K·u₀). Later iterations are Newton
// steps on the residual at the current iterate.

#include "physics/core/OdeSystem.h"
#include "physics/linear/AggregationMultigrid.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <functional>

namespace phasebox {

class NewtonVelocitySolver {
public:
    void reset(int n);

    struct Result {
        bool ok = false;
        int iterations = 0;
        double lastCorrection = 0.0;  // ∞-norm of the last update
        double power = 0.0;           // non-conservative power at the last force evaluation
        int linearSolves = 0;
        int linearIterations = 0;     // conjugate-gradient iterations, summed (0 when direct)
        double linearResidual = 0.0;  // relative residual of the last iterative solve
    };

    // Systems with at least this many degrees of freedom are solved by preconditioned
    // conjugate gradients (warm-started from the last step's answer) rather than by a sparse
    // factorisation, whose fill-in grows faster than the cloth.
    static constexpr int kIterativeThreshold = 2000;
    static constexpr double kIterativeTolerance = 1e-4;
    static constexpr double kRefinementTolerance = 1e-12;
    // First solves that may reuse the multigrid's coarse factorisation before it is redone.
    static constexpr int kCoarseLag = 3;

    // Solves for v. maxIterations ≥ 1; with untilConverged the loop stops early once the
    // update is below the relative tolerance, and it keeps going (up to maxIterations) while
    // it is not.
    Result solve(OdeSystem& sys, double t, double c, const Vec& q0, const Vec& u0, Vec& v,
                 int maxIterations, bool untilConverged, double relativeTolerance);

private:
    // Where the assembled values go: a value array and, per contribution, its slots in it.
    struct Target {
        double* values = nullptr;
        std::size_t count = 0;
        std::vector<int> slots;
        bool rowMajor = false;  // the multigrid's blocks; matrix_ is column-major
    };
    template <typename Visit>
    void forEachContribution(double c, Visit&& visit) const;
    // Adds this step's M − c·D − c²·K into target's recorded slots; false if the
    // contributions are not the recorded ones (effects came or went).
    bool refill(const Vec& mass, double c, Target& target);
    void recordSlots(int n, double c, Target& target, const std::function<int(int, int)>& place);
    // Assembles A = M − c·D − c²·K into matrix_. The sparsity pattern is built once and only
    // refilled while the effects produce the same contributions (the usual case: springs do
    // not come and go between steps), so a step neither allocates nor re-analyses.
    void assemble(OdeSystem& sys, double c);
    // Assembles A straight into the multigrid's fine matrix and refreshes the hierarchy
    // (building both, and matrix_, when the pattern is new).
    bool assembleIterative(OdeSystem& sys, double c, bool refreshCoarse);
    // Solves A·x = rhs_ into delta_.
    bool solveLinear(OdeSystem& sys, double c, bool warmStart, Result& result);
    bool conjugateGradient(double tolerance, int maxIterations, int& iterations, double& residual);

    ForceJacobians jac_;
    Vec force_, rhs_, delta_, qe_, kU_;
    SparseMatrix matrix_;
    std::vector<Triplet> triplets_;
    std::vector<long long> keys_;  // (row, col) of each contribution, in assembly order
    Target direct_, iterative_;    // matrix_, and the multigrid's blocked copy
    bool ldltAnalyzed_ = false;
    bool luAnalyzed_ = false;
    Eigen::SimplicialLDLT<SparseMatrix> ldlt_;
    Vec guess_;  // the last step's first update, to warm-start the next one
    Vec residual_, z_, direction_, product_;  // conjugate-gradient scratch
    AggregationMultigrid multigrid_;          // conjugate gradients' preconditioner
    bool coarseFresh_ = false;                // its coarse level matches this matrix
    int solvesSinceCoarse_ = 0;               // first solves since its coarse refresh
    int iterationsAfterCoarse_ = 0;           // CG iterations of the first solve after it
    int lastIterations_ = 0;                  // CG iterations of the last first solve
    Eigen::SparseLU<SparseMatrix> lu_;
};

}  // namespace phasebox
