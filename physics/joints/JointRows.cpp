// The rows of each joint at a state (JointSolver.h): its constraints C, their Jacobian J and
// J̇·u in each mode, the violations SHAKE iterates on, and what the world reads from them
// (errors, points). The solver's factorization and its stages are in JointSolver.cpp.

#include "physics/joints/JointSolver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace phasebox {

namespace {
// A row of J for a point's motion along n: [n, arm × n], scaled.
Eigen::RowVector3d pointRow(const Vec2& n, const Vec2& arm, double scale) {
    return Eigen::RowVector3d(scale * n.x(), scale * n.y(), scale * cross(arm, n));
}
}  // namespace

// ---- rows ------------------------------------------------------------------------------------

void JointSolver::cacheRotations(const Vec& q) {
    for (std::size_t s = 0; s < turningDofs_.size(); ++s)
        rotations_[s] = rotation(q[turningDofs_[s] + 2]);
    rotationsNowAt(q);
}

void JointSolver::turnRotations(const Vec& delta) {
    rotationsKnown_ = false;  // shake() says where they end
    for (std::size_t s = 0; s < turningDofs_.size(); ++s) {
        const double d = delta[turningDofs_[s] + 2];
        if (d == 0.0) continue;
        // R(θ + δ) = R(θ)·R(δ); a SHAKE iteration's δ is small, and then the series to δ⁵ is
        // exact to 1e-21.
        const double d2 = d * d;
        Mat2 turn;
        if (std::abs(d) < 1e-3) {
            const double c = 1.0 - d2 * (0.5 - d2 / 24.0);
            const double sn = d * (1.0 - d2 * (1.0 / 6.0 - d2 / 120.0));
            turn << c, -sn, sn, c;
        } else {
            turn = rotation(d);
        }
        rotations_[s] = rotations_[s] * turn;
    }
}

void JointSolver::rowsOf(int k, Mode mode, const Vec& q, const Vec& u, Rows& r, bool cached,
                         bool jacobian) const {
    const Joint& j = joints_[k];
    const End& ea = endA_[k];
    const End& eb = endB_[k];
    const EndState a = evaluate(ea, q, u, cached), b = evaluate(eb, q, u, cached);
    r.count = 0;
    if (jacobian) {
        r.ja.setZero();
        r.jb.setZero();
    }
    r.c.setZero();
    r.bias.setZero();
    r.target.setZero();
    // The centripetal part of each point's acceleration, −ω²·arm: J̇·u of a point row.
    const Vec2 centripetalA = -a.omega * a.omega * a.arm, centripetalB = -b.omega * b.omega * b.arm;
    // A row that keeps a distance: d = pa − pb, C = |d| − length.
    const auto distanceRow = [&](const Vec2& pb, const Vec2& vb, const Vec2& armB,
                                 const Vec2& centripetal, double length) {
        const Vec2 d = a.p - pb;
        const double len = d.norm();
        const Vec2 n = len > 0.0 ? Vec2(d / len) : Vec2(1.0, 0.0);
        const Vec2 dv = a.v - vb;
        if (jacobian) {
            r.ja.row(0) = pointRow(n, a.arm, 1.0);
            r.jb.row(0) = pointRow(n, armB, -1.0);
        }
        r.c[0] = len - length;
        const double along = n.dot(dv);
        r.bias[0] = n.dot(centripetalA - centripetal) +
                    (len > 0.0 ? (dv.squaredNorm() - along * along) / len : 0.0);
        r.count = 1;
        return along;
    };
    switch (j.type) {
        case Joint::Type::Hinge:
        case Joint::Type::Weld: {
            const Vec2 c = a.p - b.p - j.offset;
            for (int i = 0; i < 2; ++i) {
                if (jacobian) {
                    const Vec2 axis = i == 0 ? Vec2(1.0, 0.0) : Vec2(0.0, 1.0);
                    r.ja.row(i) = pointRow(axis, a.arm, 1.0);
                    r.jb.row(i) = pointRow(axis, b.arm, -1.0);
                }
                r.c[i] = c[i];
                r.bias[i] = (centripetalA - centripetalB)[i];
            }
            r.count = 2;
            const bool angular = ea.rigid && eb.rigid && (ea.turns || eb.turns);
            if (!angular) break;
            const double angle = b.angle - a.angle - j.referenceAngle;
            double target = 0.0;
            bool active = j.type == Joint::Type::Weld;
            if (!active && j.hasLimits && mode != Mode::Dynamics) {
                const double rate = b.omega - a.omega;
                const double slack = mode == Mode::Velocity ? 1e-9 : 0.0;
                if (angle < j.lower + slack && (mode == Mode::Position || rate < 0.0)) {
                    active = true;
                    target = j.lower;
                } else if (angle > j.upper - slack && (mode == Mode::Position || rate > 0.0)) {
                    active = true;
                    target = j.upper;
                }
            }
            if (!active) break;
            if (jacobian && ea.turns) r.ja(2, 2) = -1.0;
            if (jacobian && eb.turns) r.jb(2, 2) = 1.0;
            r.c[2] = angle - target;
            r.count = 3;
            break;
        }
        case Joint::Type::Rod:
            distanceRow(b.p, b.v, b.arm, centripetalB, j.length);
            break;
        case Joint::Type::Rope: {
            const double along = distanceRow(b.p, b.v, b.arm, centripetalB, j.length);
            const double taut = tautBand(j.length);
            const bool active = mode == Mode::Dynamics   ? r.c[0] > -taut
                                : mode == Mode::Position ? r.c[0] > 0.0
                                                         : r.c[0] > -taut && along > 0.0;
            if (!active) r.count = 0;
            break;
        }
        case Joint::Type::Pulley: {
            double c = -j.length;
            // Each side's length, direction and rate, for the stops below.
            std::array<double, 2> lengths{}, rates{}, curvatures{};
            std::array<Vec2, 2> directions;
            const auto side = [&](int which, const EndState& s, const Vec2& ground,
                                  const Vec2& centripetal, double scale, Mat3& jac) {
                const Vec2 d = s.p - ground;
                const double len = d.norm();
                const Vec2 n = len > 0.0 ? Vec2(d / len) : Vec2(0.0, -1.0);
                if (jacobian) jac.row(0) = pointRow(n, s.arm, scale);
                const double along = n.dot(s.v);
                // The side's length's J̇·u: the point's centripetal part and its turning.
                curvatures[which] = n.dot(centripetal) +
                                    (len > 0.0 ? (s.v.squaredNorm() - along * along) / len : 0.0);
                r.bias[0] += scale * curvatures[which];
                c += scale * len;
                lengths[which] = len;
                rates[which] = along;
                directions[which] = n;
            };
            side(0, a, j.groundA, centripetalA, 1.0, r.ja);
            side(1, b, j.groundB, centripetalB, j.ratio, r.jb);
            r.c[0] = c;
            r.count = 1;
            // A side whose rope has run up to its pulley stops there (pulleyStop()): an
            // inequality. After the step it catches the side (positions, then the speculative
            // velocities); a side resting at its stop is held there by a constraint force, as a
            // taut rope is, until that force would have to pull (solveDynamics()).
            const double stop = pulleyStop(j);
            for (int which = 0; which < 2; ++which) {
                const double left = lengths[which] - stop;  // to the stop
                const bool active =
                    mode == Mode::Dynamics ? left < kTautFraction * j.length
                    : mode == Mode::Position
                        ? left < 0.0
                        : rates[which] < 0.0 && left + stepLength_ * rates[which] < 1e-9;
                if (!active) continue;
                const EndState& s = which == 0 ? a : b;
                if (jacobian)
                    (which == 0 ? r.ja : r.jb).row(1) = pointRow(directions[which], s.arm, 1.0);
                r.c[1] = left;
                r.bias[1] = curvatures[which];
                if (mode == Mode::Velocity && stepLength_ > 0.0)
                    r.target[1] = std::min(0.0, -left / stepLength_);
                r.count = 2;
                break;
            }
            break;
        }
        case Joint::Type::Track:
            if (j.circle) {
                distanceRow(j.center, Vec2::Zero(), Vec2::Zero(), Vec2::Zero(), j.radius);
            } else {
                if (jacobian) r.ja.row(0) = pointRow(j.lineNormal, a.arm, 1.0);
                r.c[0] = j.lineNormal.dot(a.p - j.linePoint);
                r.bias[0] = j.lineNormal.dot(centripetalA);
                r.count = 1;
            }
            break;
    }
    if (!jacobian) return;
    // A row that is not active (a slack rope, a hinge inside its limits) must not couple
    // through the factors either: its Jacobian is zero.
    for (int i = r.count; i < 3; ++i) {
        r.ja.row(i).setZero();
        r.jb.row(i).setZero();
    }
    // A fixed end has no velocities to act on.
    if (ea.dof < 0) r.ja.setZero();
    if (eb.dof < 0) r.jb.setZero();
    if (!ea.turns) r.ja.col(2).setZero();
    if (!eb.turns) r.jb.col(2).setZero();
}

inline Vec2 JointSolver::pointOf(const End& e, const Vec& q) const {
    if (e.dof < 0) return e.fixed;
    if (!e.turns) return q.segment<2>(e.dof);
    return q.segment<2>(e.dof) + rotations_[e.slot] * e.local;
}

inline JointSolver::Vec3 JointSolver::violationOf(int k, const Vec& q) const {
    const Joint& j = joints_[k];
    const End& ea = endA_[k];
    const End& eb = endB_[k];
    const Vec2 pa = pointOf(ea, q);
    Vec3 c = Vec3::Zero();
    switch (j.type) {
        case Joint::Type::Hinge:
        case Joint::Type::Weld: {
            c.head<2>() = pa - pointOf(eb, q) - j.offset;
            // The angle row, where it is one of the equalities (a weld's; a hinge's limit is not).
            if (j.type == Joint::Type::Hinge) break;
            const double angleA = ea.dof < 0 ? ea.angle0 : ea.turns ? q[ea.dof + 2] : 0.0;
            const double angleB = eb.dof < 0 ? eb.angle0 : eb.turns ? q[eb.dof + 2] : 0.0;
            c[2] = angleB - angleA - j.referenceAngle;
            break;
        }
        case Joint::Type::Rod:
        case Joint::Type::Rope:
            c[0] = (pa - pointOf(eb, q)).norm() - j.length;
            break;
        case Joint::Type::Pulley:
            c[0] =
                -j.length + (pa - j.groundA).norm() + j.ratio * (pointOf(eb, q) - j.groundB).norm();
            break;
        case Joint::Type::Track:
            c[0] =
                j.circle ? (pa - j.center).norm() - j.radius : j.lineNormal.dot(pa - j.linePoint);
            break;
    }
    return c;
}

double JointSolver::shakeViolation(const Vec& q) {
    double worst = 0.0;
    for (int k = 0; k < jointCount(); ++k) {
        const Vec3 c = violationOf(k, q);
        rhs_[k].setZero();
        for (int i = 0; i < rows_[k].count; ++i) {
            rhs_[k][i] = -c[i];
            worst = std::max(worst, std::abs(c[i]));
        }
    }
    return worst;
}

void JointSolver::evaluateRows(Mode mode, const Vec& q, const Vec& u) {
    // The rotations stand where they are of this very q (a step's end is the next step's
    // start, and SHAKE's turned rotations are of where it ended).
    const bool sameQ = rowsAreAt(q);
    rowsQ_ = q;  // same size after the first: no allocation
    rowsMode_ = mode;
    if (!rotationsAreAt(q)) cacheRotations(q);
    // Equalities' Jacobians depend on q alone, whatever the mode: at the same q they stand,
    // and only J̇·u changes with the velocities.
    const bool sameRows = sameQ && !hasInequalities_;
    if (!sameRows) rowsChanged();
    for (int k = 0; k < jointCount(); ++k) rowsOf(k, mode, q, u, rows_[k], true, !sameRows);
}

JointErrors JointSolver::errors(const Vec& q) const {
    JointErrors e;
    Rows r;
    for (int k = 0; k < jointCount(); ++k) {
        // Position rows do not depend on the velocities: q stands in for u.
        rowsOf(k, Mode::Position, q, q, r);
        const int positional =
            joints_[k].type == Joint::Type::Hinge || joints_[k].type == Joint::Type::Weld
                ? std::min(r.count, 2)
                : r.count;
        if (joints_[k].type == Joint::Type::Pulley)  // the rope, and a stop it is past
            e.position = std::max(e.position, r.c.head(r.count).cwiseAbs().maxCoeff());
        else if (positional == 2)
            e.position = std::max(e.position, r.c.head<2>().norm());
        else if (positional == 1)
            e.position = std::max(e.position, std::abs(r.c[0]));
        if (r.count == 3) e.angle = std::max(e.angle, std::abs(r.c[2]));
    }
    return e;
}

Vec2 JointSolver::pointA(int joint, const Vec& q) const {
    return evaluate(endA_[joint], q, q).p;
}
Vec2 JointSolver::pointB(int joint, const Vec& q) const {
    return evaluate(endB_[joint], q, q).p;
}

}  // namespace phasebox
