#pragma once
// What the energy ledger and the divergence guard need of a state, summed in one pass:
// kinetic energy, the mass moment Σm·(x, y) (which gives uniform gravity's potential without
// a pass of its own) and finiteness (a sum is finite exactly when every term is).
//
// sweepState() is the one loop that computes it. An integrator whose last pass writes the
// whole state hands it its own update, so that the state is summed while it is still in
// registers instead of being read again (for gravity-only scenes that pass was a third of the
// step). The layout is the world's: (x, y) pairs of points first, then (x, y, θ) triples.

#include "physics/core/Types.h"

#include <cassert>
#include <cmath>

namespace phasebox {

struct StateSummary {
    double kinetic = 0.0;
    Vec2 massMoment = Vec2::Zero();  // Σ m·(x, y) over particles and rigid bodies
    bool finite = true;              // every coordinate and velocity is finite
};

// Sums the whole state: points [0, pointDofs) in pairs, rigid bodies after them in triples.
// point(i, x, v) yields the (x, y) position and velocity of the point at DOF i (an integrator's
// fused pass computes and stores them there, and hands them over in registers); body(k) is
// called before the rigid body at DOF k is read from (q, u).
template <typename Point, typename Body>
StateSummary sweepState(int pointDofs, const Vec& mass, const Vec& q, const Vec& u, Point&& point,
                        Body&& body) {
    using A2 = Eigen::Array2d;
    const double* m = mass.data();
    const double* qp = q.data();
    const double* up = u.data();
    const int n = static_cast<int>(q.size());
    assert(pointDofs % 2 == 0 && (n - pointDofs) % 3 == 0);
    // The point range is [x y x y …], so 2-lane accumulators keep x and y apart, and two of
    // each let the adds overlap.
    A2 ke0 = A2::Zero(), ke1 = A2::Zero(), mom0 = A2::Zero(), mom1 = A2::Zero();
    int i = 0;
    for (; i + 4 <= pointDofs; i += 4) {
        A2 x0, v0, x1, v1;
        point(i, x0, v0);
        point(i + 2, x1, v1);
        const A2 m0 = Eigen::Map<const A2>(m + i), m1 = Eigen::Map<const A2>(m + i + 2);
        ke0 += m0 * v0 * v0;
        ke1 += m1 * v1 * v1;
        mom0 += m0 * x0;
        mom1 += m1 * x1;
    }
    for (; i < pointDofs; i += 2) {
        A2 x0, v0;
        point(i, x0, v0);
        const A2 m0 = Eigen::Map<const A2>(m + i);
        ke0 += m0 * v0 * v0;
        mom0 += m0 * x0;
    }
    double angularKinetic = 0.0, angles = 0.0;
    for (int k = pointDofs; k < n; k += 3) {
        body(k);
        const A2 mb = Eigen::Map<const A2>(m + k), ub = Eigen::Map<const A2>(up + k);
        ke0 += mb * ub * ub;
        mom0 += mb * Eigen::Map<const A2>(qp + k);
        angularKinetic += m[k + 2] * up[k + 2] * up[k + 2];
        angles += qp[k + 2];
    }
    StateSummary summary;
    summary.kinetic = 0.5 * ((ke0 + ke1).sum() + angularKinetic);
    const A2 moment = mom0 + mom1;
    summary.massMoment = Vec2(moment[0], moment[1]);
    summary.finite =
        std::isfinite(summary.kinetic) && moment.isFinite().all() && std::isfinite(angles);
    return summary;
}

inline StateSummary summarizeState(int pointDofs, const Vec& mass, const Vec& q, const Vec& u) {
    const double* qp = q.data();
    const double* up = u.data();
    return sweepState(
        pointDofs, mass, q, u,
        [=](int i, Eigen::Array2d& x, Eigen::Array2d& v) {
            x = Eigen::Map<const Eigen::Array2d>(qp + i);
            v = Eigen::Map<const Eigen::Array2d>(up + i);
        },
        [](int) {});
}

}  // namespace phasebox
