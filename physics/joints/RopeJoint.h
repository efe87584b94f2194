#pragma once
// A rope: a rod's row while it is taut and pulling, none while it is slack.

#include "physics/joints/JointRows.h"
#include "physics/joints/JointSolver.h"

namespace phasebox::joints {

inline void ropeRows(const RowsInput& in, Rows& r) {
    const double along =
        distanceRow(in, in.b.p, in.b.v, in.b.arm, in.centripetalB, in.joint.length, r);
    // Taut: in the derivative within the taut band (the rope pulls while solveDynamics() finds
    // it pulling), in the position projection past its length, in the velocity projection
    // within the band and lengthening.
    const double taut = JointSolver::tautBand(in.joint.length);
    const bool active = in.mode == Mode::Dynamics   ? r.c[0] > -taut
                        : in.mode == Mode::Position ? r.c[0] > 0.0
                                                    : r.c[0] > -taut && along > 0.0;
    if (!active) r.count = 0;
}

inline Vec3 ropeViolation(const ViolationInput& in) {
    return distanceViolation(in, in.joint.length);
}

}  // namespace phasebox::joints
