#pragma once
// A weld: a hinge's two point rows and a third that holds the bodies' relative angle, all
// equalities (where one end is a particle, or both are fixed in angle, the point rows alone).

#include "physics/joints/JointRows.h"

namespace phasebox::joints {

inline void weldRows(const RowsInput& in, Rows& r) {
    pinRows(in, r);
    if (angular(in)) angleRow(in, relativeAngle(in), 0.0, r);
}

inline Vec3 weldViolation(const ViolationInput& in) {
    Vec3 c = pinViolation(in);
    const End& ea = in.endA;
    const End& eb = in.endB;
    const double angleA = ea.dof < 0 ? ea.angle0 : ea.turns ? in.q[ea.dof + 2] : 0.0;
    const double angleB = eb.dof < 0 ? eb.angle0 : eb.turns ? in.q[eb.dof + 2] : 0.0;
    c[2] = angleB - angleA - in.joint.referenceAngle;
    return c;
}

}  // namespace phasebox::joints
