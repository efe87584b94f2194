#pragma once
// A hinge: two rows hold its two points together (pinRows); with limits, a third row holds the
// angle at the limit it is past, an inequality that acts after the step only.

#include "physics/joints/JointRows.h"

namespace phasebox::joints {

inline void hingeRows(const RowsInput& in, Rows& r) {
    pinRows(in, r);
    const Joint& j = in.joint;
    if (!angular(in) || !j.hasLimits || in.mode == Mode::Dynamics) return;
    const double angle = relativeAngle(in);
    const double rate = in.b.omega - in.a.omega;
    // In the velocity projection, a hinge at its limit (within 1e-9 rad) moving further out.
    const double slack = in.mode == Mode::Velocity ? 1e-9 : 0.0;
    const bool position = in.mode == Mode::Position;
    if (angle < j.lower + slack && (position || rate < 0.0))
        angleRow(in, angle, j.lower, r);
    else if (angle > j.upper - slack && (position || rate > 0.0))
        angleRow(in, angle, j.upper, r);
}

inline Vec3 hingeViolation(const ViolationInput& in) {
    // The point rows: a limit's is not one of the equalities.
    return pinViolation(in);
}

}  // namespace phasebox::joints
