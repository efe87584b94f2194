#pragma once
// A hinge: two rows hold its two points together (pinRows); with limits, a third row holds the
// angle at a limit, an inequality: in the derivative while the hinge rests at the limit and the
// limit pushes, after the step where the hinge is past it or moving out.

#include "physics/joints/JointRows.h"
#include "physics/joints/JointTuning.h"

namespace phasebox::joints {

inline void hingeRows(const RowsInput& in, Rows& r) {
    pinRows(in, r);
    const Joint& j = in.joint;
    if (!angular(in) || !j.hasLimits) return;
    const double angle = relativeAngle(in);
    if (in.mode == Mode::Dynamics) {
        // A limit the hinge rests on holds the angle's acceleration at zero through the step,
        // like an equality, as a floor holds a box: after the step only, a limb resting on its
        // stop under its weight sank past it every step and was lifted back by the projection,
        // its energy booked as correction. Which limits hold is found at the step's start (at a
        // limit within kLimitHoldBand, or past it) and kept for the step's every evaluation, so
        // that the derivative is smooth within a step (an implicit method's Newton solve). Written
        // so that it pushes with λ ≥ 0 (solveDynamics() lets go of one that would pull); target
        // marks the side.
        // A hinge still moving out of its limit is an impact: the step does not hold it (the
        // velocity projection after the step catches it, booked as work). A limit that held
        // through the last step holds on within kLimitKeepBand (JointTuning.h).
        const double rate = in.b.omega - in.a.omega;
        const double lowerBand = in.previousLimit == kLowerLimit ? kLimitKeepBand : kLimitHoldBand;
        const double upperBand = in.previousLimit == kUpperLimit ? kLimitKeepBand : kLimitHoldBand;
        const int side = in.limit != kFindLimit                                  ? in.limit
                         : angle < j.lower + lowerBand && rate > -kLimitHoldRate ? kLowerLimit
                         : angle > j.upper - upperBand && rate < kLimitHoldRate  ? kUpperLimit
                                                                                 : kNoLimit;
        if (side == kLowerLimit) {
            angleRow(in, angle, j.lower, r);
        } else if (side == kUpperLimit) {
            angleRow(in, angle, j.upper, r);
            r.c[2] = -r.c[2];
            if (in.jacobian) {
                r.ja(2, 2) = -r.ja(2, 2);
                r.jb(2, 2) = -r.jb(2, 2);
            }
        }
        r.target[2] = side;
        return;
    }
    // In the velocity projection, a hinge at its limit (within kLimitBand: the position
    // projection leaves it at most kShakeCeiling past) moving further out.
    const double rate = in.b.omega - in.a.omega;
    const double slack = in.mode == Mode::Velocity ? kLimitBand : 0.0;
    const bool position = in.mode == Mode::Position;
    // In positions, a hinge past a limit, and in SHAKE along the end's directions one at the
    // limit the step holds (in.limit): a pin's projection alone turned a resting limb past its
    // stop (backward Euler then left every other step to the position projection). Not in the
    // projections after the step or the contacts: there a limb the contacts lift off its stop
    // would be pulled back onto it (the ragdoll booked 2 J of correction a step lying still).
    const bool lowerHeld = position && in.limit == kLowerLimit;
    const bool upperHeld = position && in.limit == kUpperLimit;
    if ((angle < j.lower + slack || lowerHeld) && (position || rate < 0.0))
        angleRow(in, angle, j.lower, r);
    else if ((angle > j.upper - slack || upperHeld) && (position || rate > 0.0))
        angleRow(in, angle, j.upper, r);
}

inline Vec3 hingeViolation(const ViolationInput& in) {
    // The point rows, and the limit the step holds (its row's sign: see hingeRows()).
    Vec3 c = pinViolation(in);
    if (in.limit == kLowerLimit || in.limit == kUpperLimit) {
        const Joint& j = in.joint;
        const double angle = in.angleOf(in.endB) - in.angleOf(in.endA) - j.referenceAngle;
        c[2] = in.limit == kLowerLimit ? angle - j.lower : j.upper - angle;
    }
    return c;
}

}  // namespace phasebox::joints
