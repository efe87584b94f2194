#pragma once
// A track: one row holds end a's point on a line (along its normal) or on a circle (at the
// circle's radius from its centre).

#include "physics/joints/JointRows.h"

namespace phasebox::joints {

inline void trackRows(const RowsInput& in, Rows& r) {
    const Joint& j = in.joint;
    if (j.circle) {
        distanceRow(in, j.center, Vec2::Zero(), Vec2::Zero(), Vec2::Zero(), j.radius, r);
        return;
    }
    if (in.jacobian) r.ja.row(0) = pointRow(j.lineNormal, in.a.arm, 1.0);
    r.c[0] = j.lineNormal.dot(in.a.p - j.linePoint);
    r.bias[0] = j.lineNormal.dot(in.centripetalA);
    r.count = 1;
}

inline Vec3 trackViolation(const ViolationInput& in) {
    const Joint& j = in.joint;
    const Vec2 pa = in.pointOf(in.endA);
    Vec3 c = Vec3::Zero();
    c[0] = j.circle ? (pa - j.center).norm() - j.radius : j.lineNormal.dot(pa - j.linePoint);
    return c;
}

}  // namespace phasebox::joints
