#pragma once
// A pulley: one row holds the rope's length, side a's from its pulley plus ratio times side
// b's; a second holds a side that has run up to its pulley at its stop (an inequality,
// JointSolver::pulleyStop()).

#include "physics/joints/JointRows.h"
#include "physics/joints/JointSolver.h"

#include <algorithm>
#include <array>

namespace phasebox::joints {

inline void pulleyRows(const RowsInput& in, Rows& r) {
    const Joint& j = in.joint;
    const Mode mode = in.mode;
    double c = -j.length;
    // Each side's length, direction and rate, for the stops below.
    std::array<double, 2> lengths{}, rates{}, curvatures{};
    std::array<Vec2, 2> directions;
    const auto side = [&](int which, const EndState& s, const Vec2& ground, const Vec2& centripetal,
                          double scale, Mat3& jac) {
        const Vec2 d = s.p - ground;
        const double len = d.norm();
        const Vec2 n = len > 0.0 ? Vec2(d / len) : Vec2(0.0, -1.0);
        if (in.jacobian) jac.row(0) = pointRow(n, s.arm, scale);
        const double along = n.dot(s.v);
        // The side's length's J̇·u: the point's centripetal part and its turning.
        curvatures[which] =
            n.dot(centripetal) + (len > 0.0 ? (s.v.squaredNorm() - along * along) / len : 0.0);
        r.bias[0] += scale * curvatures[which];
        c += scale * len;
        lengths[which] = len;
        rates[which] = along;
        directions[which] = n;
    };
    side(0, in.a, j.groundA, in.centripetalA, 1.0, r.ja);
    side(1, in.b, j.groundB, in.centripetalB, j.ratio, r.jb);
    r.c[0] = c;
    r.count = 1;
    // A side whose rope has run up to its pulley stops there (pulleyStop()): an
    // inequality. After the step it catches the side (positions, then the speculative
    // velocities); a side resting at its stop is held there by a constraint force, as a
    // taut rope is, until that force would have to pull (solveDynamics()).
    const double stop = JointSolver::pulleyStop(j);
    const double step = in.stepLength;
    for (int which = 0; which < 2; ++which) {
        const double left = lengths[which] - stop;  // to the stop
        const bool active = mode == Mode::Dynamics ? left < JointSolver::kTautFraction * j.length
                            : mode == Mode::Position
                                ? left < 0.0
                                : rates[which] < 0.0 && left + step * rates[which] < 1e-9;
        if (!active) continue;
        const EndState& s = which == 0 ? in.a : in.b;
        if (in.jacobian)
            (which == 0 ? r.ja : r.jb).row(1) = pointRow(directions[which], s.arm, 1.0);
        r.c[1] = left;
        r.bias[1] = curvatures[which];
        if (mode == Mode::Velocity && step > 0.0) r.target[1] = std::min(0.0, -left / step);
        r.count = 2;
        break;
    }
}

inline Vec3 pulleyViolation(const ViolationInput& in) {
    const Joint& j = in.joint;
    Vec3 c = Vec3::Zero();
    c[0] = -j.length + (in.pointOf(in.endA) - j.groundA).norm() +
           j.ratio * (in.pointOf(in.endB) - j.groundB).norm();
    return c;
}

}  // namespace phasebox::joints
