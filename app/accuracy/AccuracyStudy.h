#pragma once
// The accuracy study: what accuracy costs in time. For each integrator and each step size (or,
// for the adaptive methods, each tolerance) the scene runs to its end time on a fresh copy; the
// positions at the end are compared with a reference and the run is timed.
//
// The reference is the closed form where Phasebox knows one (ExactReference.h), else rk45 at
// tolerance 1e-12, computed once per scene and end time (with contacts: and finest dt, which
// sets its contact resolution) and cached for the process.
//
// runAccuracyStudy() is the synchronous core (phasebox-cli accuracy calls it directly);
// AccuracyStudy runs it in a worker thread for the app, with progress and cancel.

#include "physics/scene/SceneDesc.h"

#include <QFutureWatcher>
#include <QObject>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace phasebox {

// One run: one integrator at one dt (and tolerance, for the adaptive methods).
struct AccuracyRecord {
    std::string integrator;
    // Fixed-step methods: the step. Adaptive methods: the frame step at whose boundaries they
    // land; their own internal steps follow `tolerance`.
    double dt = 0.0;
    std::optional<double> tolerance;  // adaptive methods only
    // Steps taken: frames of dt for the fixed-step methods, accepted internal steps for the
    // adaptive ones (what their cost grows with).
    long long steps = 0;
    long long forceEvals = 0;
    double cpuSeconds = 0.0;  // this thread's CPU time, best of `repeats` runs
    int repeats = 1;
    // Largest |difference| over every position coordinate (x, y, box angle) of the dynamic
    // objects at the end time; +∞ when the run diverged, NaN when there is no reference.
    double positionError = 0.0;
    double energyDrift = 0.0;  // largest |drift| over the run (CONTRACT.md §2)
    // ln(e_prev/e) / ln(dt_prev/dt) against the previous record of the same integrator; empty
    // for the first, for adaptive methods (their dt does not change), when an error is 0 or not
    // finite, and for every record of a scene with contacts.
    std::optional<double> order;
    bool diverged = false;
    std::string divergence;  // what and where, when diverged
};

struct AccuracyOptions {
    std::vector<std::string> integrators;  // empty = all ten, in the registry's order
    std::vector<double> dts;               // empty = the scene's dt × 1, ½, … 1/32
    double duration = 0.0;                 // end time; 0 = the scene's duration
    // The duration is a default the user did not choose (the app's suggestion): the study may
    // move it off a turning point of the exact motion, as it does with duration 0.
    bool durationIsDefault = false;
    // Tolerances the adaptive methods sweep, at the frame step dts.front(); empty = each
    // method's default (defaultAccuracyTolerances).
    std::vector<double> tolerances;
    // Timing: a run shorter than repeatBelowSeconds is repeated (best of up to maxRepeats)
    // while its repeats together stay within repeatBudgetSeconds, so that clock granularity
    // and cache warm-up do not decide the cost of short runs, and long studies stay long only
    // where the runs themselves are.
    int maxRepeats = 5;
    double repeatBelowSeconds = 0.05;
    double repeatBudgetSeconds = 0.25;
};

struct AccuracyResult {
    std::string reference;  // "exact: harmonic oscillator", …, or "rk45 tol 1e-12"
    bool referenceExact = false;
    bool referenceFromCache = false;  // the rk45 reference was computed by an earlier study
    bool contacts = false;            // the scene has contacts (orders are then left empty)
    std::string note;  // kContactNote (kPenaltyContactNote) for scenes with contacts, else empty
    double endTime = 0.0;
    // The largest |coordinate| of the start and reference positions: round-off is relative to
    // it (assessOrders).
    double positionScale = 0.0;
    std::vector<AccuracyRecord> records;
    int plannedRuns = 0;  // records a complete study has
    bool cancelled = false;
    std::string error;  // the reference could not be computed (its run diverged)
    // Observed orders well above a method's own: its errors cancel at this end time (a turning
    // point of an oscillation, a whole number of periods), which a different duration shows.
    std::vector<std::string> warnings;
    // The study's end time was moved from the scene's duration to where the exact motion moves
    // fastest within the next half period (see runAccuracyStudy).
    bool endTimeMoved = false;
};

inline constexpr const char* kContactNote =
    "contact events make every method first-order; compare drift and distance from the "
    "reference, not orders";
// Penalty contacts are forces, but the force switches on where an overlap begins (its damping
// part jumps there): the same first-order ceiling, for another reason.
inline constexpr const char* kPenaltyContactNote =
    "penalty contacts switch on where an overlap begins (the damping force jumps there, the "
    "spring force kinks), which makes every method about first-order; compare drift and "
    "distance from the reference, not orders";

// Called after the reference and after each run: done of total work items (the reference
// counts as one). Called on the thread that runs the study.
using AccuracyProgress = std::function<void(int done, int total)>;

// Runs the study. A set cancel flag stops it at the next check (every few dozen steps); the
// result then holds the records finished so far and cancelled = true. Throws
// std::invalid_argument for bad options (unknown integrator, dt outside (0, 1], tolerance or
// duration ≤ 0) and SceneError for a scene that does not build. Diverging runs are data: they
// are recorded with positionError = +∞, never thrown.
AccuracyResult runAccuracyStudy(const SceneDesc& scene, const AccuracyOptions& options,
                                const AccuracyProgress& progress = {},
                                const std::atomic<bool>* cancel = nullptr);

std::vector<double> defaultAccuracyDts(double sceneDt);
// adaptive_euler: 1e-2 … 1e-7; rk45: 1e-5 … 1e-10 (looser ones do not bind within a frame).
std::vector<double> defaultAccuracyTolerances(std::string_view integrator);

// The rk45 reference cache: how many references were computed (not taken from the cache) in
// this process, and a way to forget them.
long long accuracyReferenceComputations();
void clearAccuracyReferenceCache();

// The study in a worker thread (QtConcurrent), for the app's Accuracy dialog.
class AccuracyStudy : public QObject {
    Q_OBJECT

public:
    explicit AccuracyStudy(QObject* parent = nullptr);
    // Cancels a running study and waits for its worker.
    ~AccuracyStudy() override;

    // Starts a study on a copy of the scene. Returns false (and starts nothing) while one runs.
    bool start(const SceneDesc& scene, const AccuracyOptions& options = {});
    bool isRunning() const;
    // Asks the worker to stop; finished() follows with result().cancelled set.
    void cancel();
    // Blocks until the worker is done (shutdown, tests); finished() is still emitted later,
    // from the event loop.
    void waitForFinished();

    // The last finished study. When it could not start (bad options, a scene that does not
    // build) the reason is in result().error and there are no records.
    const AccuracyResult& result() const { return result_; }

signals:
    void progress(int done, int total);
    void finished();

private:
    void collect();

    QFutureWatcher<AccuracyResult> watcher_;
    std::shared_ptr<std::atomic<bool>> cancel_;
    AccuracyResult result_;
};

}  // namespace phasebox
