#pragma once
// What a step may cost, as a time estimate the scene's validation and the adaptive methods
// share. A particle, cloth node or spring is one unit of work an evaluation; a rigid body or a
// joint kCostlyWorkUnits (its rows, contacts and solves). A step's sub-steps times the
// scene's units, or an adaptive method's internal steps a frame times them, stay within
// kMaxStepWork: a few seconds of work, whatever the scene (docs/robustness.md has the
// figures this is calibrated on).

namespace phasebox {

inline constexpr long long kCostlyWorkUnits = 64;
inline constexpr long long kMaxStepWork = 64'000'000;
// An adaptive method's frame: its evaluations a frame times the units. An evaluation is the
// forces alone, about a tenth of a sub-step's cost (which adds the contacts, the projections
// and the bookkeeping), so the same seconds allow ten times the units.
inline constexpr double kMaxEvaluationWork = 10.0 * kMaxStepWork;

}  // namespace phasebox
