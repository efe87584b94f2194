#include "app/accuracy/OrderAssessment.h"

#include "physics/integrators/Integrator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace phasebox {

namespace {

std::string formatOrder(double order) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", order);
    return text;
}

// "⁴" for 4: dt⁴ reads as the formula a student has seen.
std::string superscript(int n) {
    static const char* const digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    if (n >= 0 && n <= 9) return digits[n];
    char text[16];
    std::snprintf(text, sizeof text, "^%d", n);
    return text;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

enum class PairKind { InRange, Floor, Growing };

struct Pair {
    double coarseDt, fineDt, order;
    PairKind kind;
};

// The order over the runs of one method: sorted coarsest step first, each pair of neighbouring
// steps gives a slope; the slopes are sorted into unstable, round-off floor and in range, and
// the asymptotic range at the fine end gives the measured order.
void measureOrder(OrderAssessment& a, std::vector<const AccuracyRecord*>& runs,
                  const AccuracyResult& result) {
    // Coarsest step first; a diverged run is unstable at its step.
    std::sort(runs.begin(), runs.end(),
              [](const AccuracyRecord* x, const AccuracyRecord* y) { return x->dt > y->dt; });
    const double scale = std::max(result.positionScale, 1e-12);
    const double floor = (result.referenceExact ? kRoundOffFloor : kReferenceFloor) * scale;
    std::vector<Pair> pairs;
    const AccuracyRecord* previous = nullptr;
    for (const AccuracyRecord* r : runs) {
        if (r->diverged || std::isinf(r->positionError)) {
            ++a.diverged;
            a.unstableUpToDt = std::min(a.unstableUpToDt.value_or(r->dt), r->dt);
            previous = nullptr;
            continue;
        }
        const bool usable = std::isfinite(r->positionError) && r->positionError > 0.0;
        if (usable && previous && previous->dt != r->dt) {
            Pair p{previous->dt, r->dt,
                   std::log(previous->positionError / r->positionError) /
                       std::log(previous->dt / r->dt),
                   PairKind::InRange};
            if (r->positionError < floor && p.order < a.theory - kOrderTolerance)
                p.kind = PairKind::Floor;
            else if (p.order < kGrowingOrder)
                p.kind = PairKind::Growing;
            pairs.push_back(p);
        }
        previous = usable ? r : nullptr;
    }
    // The floor starts at the finer step of the first pair that reached it: round-off only
    // grows as the steps shrink, so whatever finer steps do there (their errors wander up and
    // down) is floor too. Unstable: every step down to the finest one that a finer step beat in
    // the wrong direction, above the floor.
    for (const Pair& p : pairs)
        if (p.kind == PairKind::Floor) {
            a.floorFromDt = p.fineDt;
            break;
        }
    for (const Pair& p : pairs)
        if (p.kind == PairKind::Growing && (!a.floorFromDt || p.fineDt > *a.floorFromDt))
            a.unstableUpToDt = std::min(a.unstableUpToDt.value_or(p.coarseDt), p.coarseDt);
    std::vector<const Pair*> between;  // coarse to fine
    for (const Pair& p : pairs) {
        const bool belowUnstable = !a.unstableUpToDt || p.coarseDt < *a.unstableUpToDt;
        const bool aboveFloor = !a.floorFromDt || p.fineDt > *a.floorFromDt;
        if (p.kind == PairKind::InRange && belowUnstable && aboveFloor) between.push_back(&p);
    }
    // The asymptotic range is at the fine end: from the finest pair, coarser pairs join while
    // their slope agrees with the range's so far. Coarser pairs that disagree are steps too
    // large for the leading error term to decide (RK4 on a stiff spring measures 0.9 and 0.1
    // there, then 3.8 and 4.1).
    std::vector<double> inRange;
    for (auto p = between.rbegin(); p != between.rend(); ++p) {
        if (!inRange.empty() && std::abs((*p)->order - median(inRange)) > kOrderTolerance) {
            a.preAsymptoticUpToDt = (*p)->coarseDt;
            break;
        }
        inRange.push_back((*p)->order);
    }
    a.pairsInRange = static_cast<int>(inRange.size());
    if (!inRange.empty()) a.measured = median(inRange);
}

// The notes: what the measured number is, then what was left out and why.
void explain(OrderAssessment& a, const AccuracyResult& result, std::size_t runCount) {
    std::ostringstream note, why;
    const std::string theory = std::to_string(a.theory);
    if (a.measured) {
        const double m = *a.measured;
        if (m > a.theory + kOrderTolerance) {
            a.kind = OrderAssessment::Kind::ErrorsCancel;
            note << "above its order " << theory << ": errors cancel at this end time";
            why << "Measured " << formatOrder(m) << ", more than the method's order " << theory
                << ": at this end time its errors partly cancel (a turning point or a whole "
                   "number of periods). A different duration shows the true order.";
        } else if (m < a.theory - kOrderTolerance) {
            a.kind = OrderAssessment::Kind::NotAsymptotic;
            note << "below its order " << theory << ": steps not yet small enough";
            why << "Measured " << formatOrder(m) << ", less than the method's order " << theory
                << ": the steps are still too large for the error to shrink like dt"
                << superscript(a.theory) << ". Add smaller steps to see the method's own order.";
        } else {
            a.kind = OrderAssessment::Kind::AsExpected;
            note << "as expected";
            why << "Measured " << formatOrder(m) << ", close to the method's order " << theory
                << ": halving dt divides the error by about 2" << superscript(a.theory) << " = "
                << (1 << a.theory) << ".";
        }
        if (a.pairsInRange == 1) {
            note << " (one pair of steps only)";
            why << " Only one pair of steps was usable: too few to be sure.";
        }
    } else if (a.floorFromDt && !a.unstableUpToDt) {
        a.kind = OrderAssessment::Kind::RoundOffFloor;
        note << "at the floor already: use larger steps";
        why << "Even the coarsest steps are as accurate as the computer can tell, so halving dt "
               "cannot help any more and no order can be measured. Larger steps would show it.";
    } else if (a.unstableUpToDt) {
        a.kind = OrderAssessment::Kind::Unstable;
        note << "unstable at every dt studied";
        why << "At every step studied the method is unstable: "
            << (a.diverged == static_cast<int>(runCount)
                    ? "every run blew up (diverged)"
                    : "the error does not shrink as dt shrinks, or the run blew up")
            << ", so no order can be measured. Try much smaller steps or an implicit method.";
    } else {
        a.kind = OrderAssessment::Kind::TooFewSteps;
        note << "too few steps to measure";
        why << "An order needs at least two runs with a finite error at different steps.";
    }
    const bool unstableNote = a.unstableUpToDt && a.kind != OrderAssessment::Kind::Unstable;
    if (unstableNote) {
        note << "; unstable at dt ≥ " << formatStep(*a.unstableUpToDt);
        why << " At dt ≥ " << formatStep(*a.unstableUpToDt) << " the method is unstable: "
            << (a.diverged ? "the run blew up (diverged)"
                           : "the error grew instead of shrinking as the step was halved")
            << ", so those steps are left out.";
    }
    if (a.preAsymptoticUpToDt) {
        note << "; dt ≥ " << formatStep(*a.preAsymptoticUpToDt) << " too large to count";
        why << " At dt ≥ " << formatStep(*a.preAsymptoticUpToDt)
            << " the steps are too large: the error does not yet shrink like dt"
            << superscript(a.theory) << " (not yet in the asymptotic range), so those steps are "
            << "left out.";
    }
    if (a.floorFromDt && a.kind != OrderAssessment::Kind::RoundOffFloor) {
        note << "; " << (result.referenceExact ? "round-off floor" : "reference's accuracy")
             << " reached at dt ≤ " << formatStep(*a.floorFromDt);
        why << " At dt ≤ " << formatStep(*a.floorFromDt) << " the error has reached "
            << (result.referenceExact ? "the round-off floor" : "the reference's own accuracy")
            << " and no longer improves: "
            << (result.referenceExact
                    ? "the computer's rounding errors, added up over many steps, are as large "
                      "as the method's own error"
                    : "the rk45 reference is not more accurate than that")
            << ", so those steps are left out of the measured order.";
    }
    a.note = note.str();
    a.explanation = why.str();
}

OrderAssessment assessOne(const AccuracyResult& result, const std::string& name) {
    OrderAssessment a;
    a.integrator = name;
    const IntegratorInfo* info = findIntegrator(name);
    a.theory = info ? info->order : 0;

    std::vector<const AccuracyRecord*> runs;
    for (const AccuracyRecord& r : result.records)
        if (r.integrator == name && !r.tolerance) runs.push_back(&r);
    if (info && info->adaptive) {
        a.note = "adaptive: order not measured";
        a.explanation =
            "This method chooses its own steps to meet a tolerance, so there is no "
            "single step size to measure an order against; compare its points in the "
            "diagram instead.";
        return a;
    }
    if (result.contacts) {
        a.note = "contacts: order not measured";
        a.explanation =
            "In a scene with contacts the moment of each impact is caught only to "
            "within a step, which makes every method about first order. Compare the "
            "errors and the cost, not orders.";
        return a;
    }
    if (!result.error.empty() || !std::any_of(runs.begin(), runs.end(), [](const auto* r) {
            return !std::isnan(r->positionError);
        })) {
        a.note = "no reference: order not measured";
        a.explanation = "Without a reference solution there is no error to measure.";
        return a;
    }

    measureOrder(a, runs, result);
    explain(a, result, runs.size());

    return a;
}

}  // namespace

std::string formatStep(double dt) {
    const double inverse = 1.0 / dt;
    char text[32];
    if (std::abs(inverse - std::round(inverse)) < 1e-9 * inverse)
        std::snprintf(text, sizeof text, "1/%lld", static_cast<long long>(std::llround(inverse)));
    else
        std::snprintf(text, sizeof text, "%.4g", dt);
    return text;
}

std::vector<OrderAssessment> assessOrders(const AccuracyResult& result) {
    std::vector<std::string> names;
    for (const AccuracyRecord& r : result.records)
        if (std::find(names.begin(), names.end(), r.integrator) == names.end())
            names.push_back(r.integrator);
    std::vector<OrderAssessment> out;
    out.reserve(names.size());
    for (const std::string& name : names) out.push_back(assessOne(result, name));
    return out;
}

}  // namespace phasebox
