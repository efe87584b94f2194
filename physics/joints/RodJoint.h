#pragma once
// A rod: one row holds the distance between its two points at its length.

#include "physics/joints/JointRows.h"

namespace phasebox::joints {

inline void rodRows(const RowsInput& in, Rows& r) {
    distanceRow(in, in.b.p, in.b.v, in.b.arm, in.centripetalB, in.joint.length, r);
}

inline Vec3 rodViolation(const ViolationInput& in) {
    return distanceViolation(in, in.joint.length);
}

}  // namespace phasebox::joints
