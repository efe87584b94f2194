#pragma once
// The rows of one joint at a state: its constraints C, their Jacobian J for each end (x, y, θ)
// and J̇·u, in each mode, and the violation C of its equality rows that SHAKE iterates on. Each
// joint type writes its own, in its own file: xRows(in, rows) and xViolation(in) in
// HingeJoint.h, WeldJoint.h, RodJoint.h, RopeJoint.h, PulleyJoint.h and TrackJoint.h.
// JointSolver::rowsOf and violationOf (JointRows.cpp, the one file that includes those)
// dispatch on the type. They are inline: as calls into a file per type, a joint's rows and
// violation took the 100-hinge chain's step (bench_box2d_chain) from 0.067 to 0.070 ms. Here:
// what the types share.

#include "physics/core/Bodies.h"
#include "physics/core/Types.h"

#include <Eigen/Dense>

#include <vector>

namespace phasebox::joints {

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

// One end of a joint as the solver sees it.
struct End {
    int dof = -1;         // first state index of a dynamic body; −1 when fixed
    int slot = -1;        // a turning body's index in the solver's rotations
    bool turns = false;   // a dynamic rigid body: its third DOF is the angle
    bool rigid = false;   // a rigid body (dynamic or static): it has an angle
    Vec2 local{0, 0};     // the point in the body's frame (dynamic rigid body)
    Vec2 fixed{0, 0};     // the point in the world (a fixed end)
    double angle0 = 0.0;  // a fixed end's angle
    int hub = -1;         // a body kept as a node of the system: its hub (JointSolver.h)
};
// An end's point and motion at (q, u).
struct EndState {
    Vec2 p{0, 0}, v{0, 0}, arm{0, 0};
    double angle = 0.0, omega = 0.0;
};
// The rows of one joint at a state: C, J (for each end: x, y, θ), and J̇·u.
struct Rows {
    int count = 0;
    Mat3 ja = Mat3::Zero(), jb = Mat3::Zero();
    Vec3 c = Vec3::Zero(), bias = Vec3::Zero();
    // Velocity mode: the rate J·u the projection sets each row to (0 but for a pulley's
    // stop, which lets a side close in at most what it has left to its stop in a step).
    // Dynamics mode: target[2] is the side of a hinge limit the row holds (kLowerLimit,
    // kUpperLimit; HingeJoint.h), which solveDynamics() keeps as the step's.
    Vec3 target = Vec3::Zero();
};
enum class Mode { Dynamics, Position, Velocity };

// A joint at a state, as its type's rows read it. The rows come in zeroed (count 0); a type
// writes J only where jacobian is set (otherwise the rows' J of this q stand).
struct RowsInput {
    const Joint& joint;
    const End &endA, &endB;
    // Copies, not references: so the chain's rows took 2% fewer instructions (callgrind).
    EndState a, b;
    // The centripetal part of each point's acceleration, −ω²·arm: J̇·u of a point row.
    Vec2 centripetalA, centripetalB;
    Mode mode;
    bool jacobian;
    double stepLength;  // s: the last shake()'s h (a pulley's stops)
    // Dynamics mode: the hinge limit the step holds (kNoLimit, kLowerLimit, kUpperLimit), or
    // kFindLimit: the one the hinge is at now, if any (JointSolver::holdLimitsFromNextEvaluation).
    int limit = 0;
    // The limit the last step held (kNoLimit, kLowerLimit, kUpperLimit): with kFindLimit, one
    // that held is found within the wider kLimitKeepBand.
    int previousLimit = 0;
};
inline constexpr int kNoLimit = 0, kLowerLimit = 1, kUpperLimit = 2, kFindLimit = 3;

// A joint's ends at q, the rotations of q cached (per turning body's slot): what its violation
// reads.
struct ViolationInput {
    const Joint& joint;
    const End &endA, &endB;
    const Vec& q;
    const std::vector<Mat2>& rotations;
    int limit = 0;  // a hinge: the limit the step holds (RowsInput::limit)
    // An end's point at q.
    Vec2 pointOf(const End& e) const {
        if (e.dof < 0) return e.fixed;
        if (!e.turns) return q.segment<2>(e.dof);
        return q.segment<2>(e.dof) + rotations[e.slot] * e.local;
    }
    // An end's angle at q (as JointSolver::evaluate() reads it).
    double angleOf(const End& e) const {
        if (e.dof < 0) return e.angle0;
        return e.turns ? q[e.dof + 2] : 0.0;
    }
};

// v's entries from row count on set to zero (the rows a joint does not use). Branches, not a
// loop: a loop from count became a call to memset for one or two doubles.
inline void zeroFrom(Vec3& v, int count) {
    if (count <= 0) v[0] = 0.0;
    if (count <= 1) v[1] = 0.0;
    if (count <= 2) v[2] = 0.0;
}

// A row of J for a point's motion along n: [n, arm × n], scaled.
inline Eigen::RowVector3d pointRow(const Vec2& n, const Vec2& arm, double scale) {
    return Eigen::RowVector3d(scale * n.x(), scale * n.y(), scale * cross(arm, n));
}

// A row that keeps a distance from end a's point to pb (moving with vb, at the arm armB of
// its body, with that centripetal part): d = a.p − pb, C = |d| − length (a rod's, a taut
// rope's, a circular track's). Returns the rate of d's length.
inline double distanceRow(const RowsInput& in, const Vec2& pb, const Vec2& vb, const Vec2& armB,
                          const Vec2& centripetal, double length, Rows& r) {
    const EndState& a = in.a;
    const Vec2 d = a.p - pb;
    const double len = d.norm();
    const Vec2 n = len > 0.0 ? Vec2(d / len) : Vec2(1.0, 0.0);
    const Vec2 dv = a.v - vb;
    if (in.jacobian) {
        r.ja.row(0) = pointRow(n, a.arm, 1.0);
        r.jb.row(0) = pointRow(n, armB, -1.0);
    }
    r.c[0] = len - length;
    const double along = n.dot(dv);
    r.bias[0] = n.dot(in.centripetalA - centripetal) +
                (len > 0.0 ? (dv.squaredNorm() - along * along) / len : 0.0);
    r.count = 1;
    return along;
}
// Its violation at q: the distance between the two ends' points less length.
inline Vec3 distanceViolation(const ViolationInput& in, double length) {
    Vec3 c = Vec3::Zero();
    c[0] = (in.pointOf(in.endA) - in.pointOf(in.endB)).norm() - length;
    return c;
}

// The two rows that hold a's point at b's point plus the joint's offset (a hinge's, a weld's).
inline void pinRows(const RowsInput& in, Rows& r) {
    const Vec2 c = in.a.p - in.b.p - in.joint.offset;
    for (int i = 0; i < 2; ++i) {
        if (in.jacobian) {
            const Vec2 axis = i == 0 ? Vec2(1.0, 0.0) : Vec2(0.0, 1.0);
            r.ja.row(i) = pointRow(axis, in.a.arm, 1.0);
            r.jb.row(i) = pointRow(axis, in.b.arm, -1.0);
        }
        r.c[i] = c[i];
        r.bias[i] = (in.centripetalA - in.centripetalB)[i];
    }
    r.count = 2;
}
// Their violation at q, in the first two rows.
inline Vec3 pinViolation(const ViolationInput& in) {
    Vec3 c = Vec3::Zero();
    c.head<2>() = in.pointOf(in.endA) - in.pointOf(in.endB) - in.joint.offset;
    return c;
}
// Whether the ends have an angle between them that a row can hold (both rigid, one turning).
inline bool angular(const RowsInput& in) {
    return in.endA.rigid && in.endB.rigid && (in.endA.turns || in.endB.turns);
}
// The angle of b relative to a, less the joint's reference angle.
inline double relativeAngle(const RowsInput& in) {
    return in.b.angle - in.a.angle - in.joint.referenceAngle;
}
// The third row: that angle held at target.
inline void angleRow(const RowsInput& in, double angle, double target, Rows& r) {
    if (in.jacobian && in.endA.turns) r.ja(2, 2) = -1.0;
    if (in.jacobian && in.endB.turns) r.jb(2, 2) = 1.0;
    r.c[2] = angle - target;
    r.count = 3;
}

}  // namespace phasebox::joints
