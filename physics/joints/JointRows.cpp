// The rows of each joint at a state (JointSolver.h): its constraints C, their Jacobian J and
// J̇·u in each mode, the violations SHAKE iterates on, and what the world reads from them
// (errors, points). Each type's rows are in its own file (JointRows.h); here the dispatch on
// the type. The solver's factorization and its stages are in JointSolver.cpp.

#include "physics/joints/JointRows.h"

#include "physics/joints/HingeJoint.h"
#include "physics/joints/JointSolver.h"
#include "physics/joints/PulleyJoint.h"
#include "physics/joints/RodJoint.h"
#include "physics/joints/RopeJoint.h"
#include "physics/joints/TrackJoint.h"
#include "physics/joints/WeldJoint.h"

#include <algorithm>
#include <cmath>

namespace phasebox {

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
    // The centripetal part of each point's acceleration, −ω²·arm: J̇·u of a point row.
    const Vec2 centripetalA = -a.omega * a.omega * a.arm, centripetalB = -b.omega * b.omega * b.arm;
    if (!jacobian && (j.type == Joint::Type::Hinge || j.type == Joint::Type::Weld)) {
        // Rows at the q of their J (evaluateRows: equalities only, so no hinge has limits): a
        // hinge's and a weld's C and J stand, and of the rest only the point rows' J̇·u changes
        // with the velocities (the angle row's is 0). The same arithmetic as pinRows.
        for (int i = 0; i < 2; ++i) r.bias[i] = (centripetalA - centripetalB)[i];
        return;
    }
    const bool limited = j.type == Joint::Type::Hinge && j.hasLimits && ea.rigid && eb.rigid &&
                         (ea.turns || eb.turns);
    if (jacobian && j.type == Joint::Type::Hinge && !limited) {
        pointRowsOf(j, ea, eb, a, b, centripetalA - centripetalB, r);
        return;
    }
    r.count = 0;
    if (jacobian) {
        r.ja.setZero();
        r.jb.setZero();
    }
    r.c.setZero();
    r.bias.setZero();
    r.target.setZero();
    const joints::RowsInput in{.joint = j,
                               .endA = ea,
                               .endB = eb,
                               .a = a,
                               .b = b,
                               .centripetalA = centripetalA,
                               .centripetalB = centripetalB,
                               .mode = mode,
                               .jacobian = jacobian,
                               .stepLength = stepLength_,
                               .limit = findLimits_ ? joints::kFindLimit
                                        : mode == Mode::Position && !shakingAlongEnd_
                                            ? joints::kNoLimit
                                            : heldLimit_[k],
                               .previousLimit = heldLimit_[k]};
    switch (j.type) {
        case Joint::Type::Hinge:
            joints::hingeRows(in, r);
            break;
        case Joint::Type::Weld:
            joints::weldRows(in, r);
            break;
        case Joint::Type::Rod:
            joints::rodRows(in, r);
            break;
        case Joint::Type::Rope:
            joints::ropeRows(in, r);
            break;
        case Joint::Type::Pulley:
            joints::pulleyRows(in, r);
            break;
        case Joint::Type::Track:
            joints::trackRows(in, r);
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

void JointSolver::pointRowsOf(const Joint& j, const End& ea, const End& eb, const EndState& a,
                              const EndState& b, const Vec2& centripetal, Rows& r) {
    // What rowsOf() makes of pinRows() alone, entry for entry (the rows of an end that is fixed
    // or does not turn zeroed as there), written once instead of zeroed and overwritten.
    const Vec2 c = a.p - b.p - j.offset;
    for (int i = 0; i < 2; ++i) {
        const Vec2 axis = i == 0 ? Vec2(1.0, 0.0) : Vec2(0.0, 1.0);
        if (ea.dof < 0) {
            r.ja.row(i).setZero();
        } else {
            r.ja.row(i) = joints::pointRow(axis, a.arm, 1.0);
            if (!ea.turns) r.ja(i, 2) = 0.0;
        }
        if (eb.dof < 0) {
            r.jb.row(i).setZero();
        } else {
            r.jb.row(i) = joints::pointRow(axis, b.arm, -1.0);
            if (!eb.turns) r.jb(i, 2) = 0.0;
        }
        r.c[i] = c[i];
        r.bias[i] = centripetal[i];
    }
    r.ja.row(2).setZero();
    r.jb.row(2).setZero();
    r.c[2] = r.bias[2] = 0.0;
    r.target.setZero();
    r.count = 2;
}

inline JointSolver::Vec3 JointSolver::violationOf(int k, const Vec& q) const {
    const Joint& j = joints_[k];
    const joints::ViolationInput in{j, endA_[k], endB_[k], q, rotations_, heldLimit_[k]};
    switch (j.type) {
        case Joint::Type::Hinge:
            return joints::hingeViolation(in);
        case Joint::Type::Weld:
            return joints::weldViolation(in);
        case Joint::Type::Rod:
            return joints::rodViolation(in);
        case Joint::Type::Rope:
            return joints::ropeViolation(in);
        case Joint::Type::Pulley:
            return joints::pulleyViolation(in);
        case Joint::Type::Track:
            return joints::trackViolation(in);
    }
    return Vec3::Zero();
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
    const int k = active_[joint];
    return evaluate(k >= 0 ? endA_[k] : idle_[joint].a, q, q).p;
}
Vec2 JointSolver::pointB(int joint, const Vec& q) const {
    const int k = active_[joint];
    return evaluate(k >= 0 ? endB_[k] : idle_[joint].b, q, q).p;
}

}  // namespace phasebox
