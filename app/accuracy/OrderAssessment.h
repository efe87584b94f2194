#pragma once
// What a method's measured order means. The slope of log error against log dt is the method's
// own order only in its asymptotic range: steps small enough that the leading error term
// decides, errors large enough to stand above round-off (or above the accuracy of an rk45
// reference). Outside that range the bare number misleads a student (RK4 "3.17" where its finest
// steps reach round-off, explicit Euler "-1.72" where its coarse steps are unstable). So each
// method's neighbouring pairs of steps are sorted into unstable, in range and at the floor, the
// order is measured on the pairs in range only, and the others are explained in words.

#include "app/accuracy/AccuracyStudy.h"

#include <optional>
#include <string>
#include <vector>

namespace phasebox {

// A pair of neighbouring steps is at the floor when its finer error is below this fraction of
// the positions' size and its slope is more than kOrderTolerance below the method's order.
// Round-off in a step is about 1e-16 of the coordinates and it accumulates over the run's thousands
// of steps, to 1e-13 or 1e-12; a truncation error still falling at the method's own rate is never
// called a floor, however small.
inline constexpr double kRoundOffFloor = 1e-9;
// With an rk45 reference (tolerance 1e-12) the errors cannot fall below the reference's own.
inline constexpr double kReferenceFloor = 1e-8;
// A slope below this means the error grew as the step shrank: the coarser step was unstable.
inline constexpr double kGrowingOrder = -0.3;
// How far a measured order may stray from the method's before it is called out.
inline constexpr double kOrderTolerance = 0.5;

struct OrderAssessment {
    enum class Kind {
        AsExpected,     // measured within kOrderTolerance of the method's order
        RoundOffFloor,  // no pair above the floor is left to measure
        Unstable,       // every run diverged or grew as the step shrank
        TooFewSteps,    // fewer than two usable runs
        NotAsymptotic,  // measured well below theory on pairs that are neither: steps too large
        ErrorsCancel,   // measured well above theory: errors cancel at this end time
        NotMeasured,    // adaptive methods, scenes with contacts, no reference
    };
    std::string integrator;
    int theory = 0;                  // the method's own order
    std::optional<double> measured;  // median slope over the pairs in range
    int pairsInRange = 0;
    Kind kind = Kind::NotMeasured;
    // The coarsest step whose error is already at the floor (round-off, or the rk45
    // reference's accuracy): it and every finer step are left out of the measured order.
    std::optional<double> floorFromDt;
    // The finest step that was unstable (it diverged, or a finer step had a larger error): it
    // and every coarser step are left out.
    std::optional<double> unstableUpToDt;
    // The finest step that was still too large for the error to follow the method's law (its
    // slope to the next step disagrees with the range's): it and every coarser step are left out.
    std::optional<double> preAsymptoticUpToDt;
    int diverged = 0;
    std::string note;         // a short phrase for the table: "round-off floor reached at …"
    std::string explanation;  // the whole story in sentences a student can follow
};

// One assessment per integrator of result, in the order of the records.
std::vector<OrderAssessment> assessOrders(const AccuracyResult& result);

// "1/120" when dt is the inverse of a whole number, else dt in up to 4 significant digits.
std::string formatStep(double dt);

}  // namespace phasebox
