#pragma once
// The tolerances and limits of JointSolver's projections, shared by its stages: JointSolver.cpp
// (binding, the position projection) and JointShake.cpp (SHAKE). Internal to physics/joints.

namespace phasebox::joints {

// Newton steps of the position projection, and the error below which it stops (m, rad), per
// metre of the largest coordinate (projectionFloor_): about 45 units in the last place, so that
// what a fourth-order method leaves of a joint's length (h^5 a step, added up over a run)
// neither drifts to a floor nor changes a pendulum's period there (RK4 on a 10° rod pendulum at
// 1/960 keeps its order 4 only below 1e-12 m, tst_constrained_methods), and it is still
// reachable in double precision far from the origin.
inline constexpr int kProjectionIterations = 12;
inline constexpr double kProjectionTolerance = 1e-14;  // per metre
// SHAKE stops once the violation is below this fraction of the one it started from (or below
// projectionFloor_), and never leaves more than kShakeCeiling (m, rad). What it starts from is
// the step's own error (symplectic Euler's ½·r·(ω·h)² where a link turns, a method of order p its
// h^(p+1) term), so what it leaves is a ten-thousandth of the method's own error at any step and
// shrinks with it: the Accuracy Lab's curves are not floored. A fixed floor instead made every
// step of a whip iterate to it (docs/architecture.md, Joints).
inline constexpr double kShakeFraction = 1e-4;
inline constexpr double kShakeCeiling = 1e-7;
// SHAKE acts while the step's violation is below this fraction of the smallest joint size.
inline constexpr double kShakeReach = 0.1;
// rad: a hinge this close to a limit, or past it, is at the limit in the derivative (the
// position projection leaves it within shakeTolerance_, at most kShakeCeiling, of the limit).
inline constexpr double kLimitBand = 1e-6;
// What the step's derivative takes as resting on a limit: within kLimitHoldBand of it (rad) and
// moving out past it no faster than kLimitHoldRate (rad/s); faster, it is meeting the limit (an
// impact, caught after the step). The contacts lift a resting limb off its stop by a fraction of
// a milliradian (a ragdoll's neck by 0.3 mrad, a knee by 0.26 mrad, moving at a hundredth of a
// radian a second); held only within kLimitBand (and below 1e-9 rad/s), such a limb swung back
// onto the stop inside every step under its held contact forces and was caught after it,
// booking 0.6 J of work_nc and as much correction a step (docs/robustness.md). An approach at
// kLimitHoldRate carries a limb of 0.05 kg·m² 6e-5 J into its stop.
inline constexpr double kLimitHoldBand = 1e-3;
inline constexpr double kLimitHoldRate = 5e-2;
// A limit that held through the last step holds on while the hinge is within this of it (rad).
// The contacts and their joined relax after the step lift a limb off its stop by a few
// milliradians at times (a ragdoll's neck by 2.2 mrad, its head lying on the floor); with the
// one band the limit then let go in the next step, the head fell onto its stop inside it at
// 57 rad/s² and was caught after it, and the next step held it again: a two-step cycle that
// under symplectic Euler booked 1.65 J of correction a second, lying still (docs/robustness.md).
// Held on, the limb stays where the contacts left it, at most this far off its stop.
inline constexpr double kLimitKeepBand = 5e-3;

}  // namespace phasebox::joints
