#include "app/accuracy/AccuracyStudy.h"

#include "app/accuracy/ExactReference.h"
#include "app/io/NumberFormat.h"
#include "app/io/SceneIO.h"
#include "physics/integrators/Integrator.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneSchema.h"

#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <deque>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace phasebox {

namespace {

constexpr double kReferenceTolerance = 1e-12;
constexpr const char* kReferenceName = "rk45 tol 1e-12";
// How far above a method's order the median observed order may be before the study warns.
constexpr double kOrderWarning = 0.5;
// References are a state vector each; a few scenes' worth is plenty for an app session.
constexpr std::size_t kCacheEntries = 16;
// How often a run looks at the cancel flag: often enough that cancelling a large scene feels
// immediate, rarely enough that an atomic load per step never shows in the timing.
constexpr long long kCancelCheckEvery = 16;
constexpr double kNoUpperBound = std::numeric_limits<double>::infinity();

// CPU time of the calling thread. The study runs in a worker thread next to the GUI, and on a
// busy machine: wall time would charge the methods for whatever else runs, thread CPU time
// charges them for their own work only.
double threadCpuSeconds() {
#if defined(CLOCK_THREAD_CPUTIME_ID)
    timespec ts{};
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) == 0)
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
#endif
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

bool isCancelled(const std::atomic<bool>* cancel) {
    return cancel && cancel->load(std::memory_order_relaxed);
}

struct RunOutcome {
    bool cancelled = false;
    bool diverged = false;
    std::string divergence;
    double cpuSeconds = 0.0;
    long long steps = 0;
    long long forceEvals = 0;
    double maxAbsDrift = 0.0;
    Vec positions;
};

// Steps a freshly built world to endTime: whole frames of its dt and, when dt does not divide
// the end time, one shorter last frame, so that every run is compared with the reference at
// the same instant (comparing at different instants would add v·Δt to the error).
RunOutcome runToEnd(World& world, double endTime, const std::atomic<bool>* cancel) {
    RunOutcome out;
    const double dt = world.settings().dt;
    const double ratio = endTime / dt;
    long long frames = std::llround(ratio);
    double last = 0.0;
    if (std::abs(ratio - static_cast<double>(frames)) > 1e-9 * std::max(1.0, ratio)) {
        frames = static_cast<long long>(std::floor(ratio));
        last = endTime - static_cast<double>(frames) * dt;
    }
    const bool adaptive = world.integrator().info().adaptive;
    const long long steps0 =
        adaptive ? world.integrator().stats().acceptedSteps : world.stepCount();
    const long long evals0 = world.forceEvaluations();
    const auto step = [&] {
        if (world.step()) return true;
        out.diverged = true;
        out.divergence = world.divergence() ? world.divergence()->message() : "the step failed";
        return false;
    };

    const double start = threadCpuSeconds();
    for (long long i = 0; i < frames; ++i) {
        if (i % kCancelCheckEvery == 0 && isCancelled(cancel)) {
            out.cancelled = true;
            break;
        }
        if (!step()) break;
    }
    if (!out.cancelled && !out.diverged && last > 0.0) {
        SimulationSettings settings = world.settings();
        settings.dt = last;
        world.setSettings(settings);
        step();
    }
    out.cpuSeconds = threadCpuSeconds() - start;

    // Integrator counters are read after the run: the world never replaces its integrator
    // while the method's name stays the same.
    out.steps = (adaptive ? world.integrator().stats().acceptedSteps : world.stepCount()) - steps0;
    out.forceEvals = world.forceEvaluations() - evals0;
    out.maxAbsDrift = world.energy().maxAbsDrift;
    out.positions = world.positions();
    return out;
}

// ---- the rk45 reference and its cache ------------------------------------------------------

struct ReferenceCache {
    std::mutex mutex;
    std::deque<std::pair<QByteArray, Vec>> entries;  // oldest first
    std::atomic<long long> computations{0};
};

ReferenceCache& referenceCache() {
    static ReferenceCache cache;
    return cache;
}

// The scene as the reference runs it. Everything that can change the reference trajectory is
// in the key (objects, effects, frame step, sub-steps, contact solver, end time); what cannot
// (name, description, the scene's own integrator and tolerance) is normalised away, so that
// renaming a scene or switching its integrator in the app still finds the cached reference.
//
// Smooth scenes keep the scene's own frame step: rk45 lands on every frame boundary but its
// accuracy follows the tolerance alone. With contacts the frame step matters, because impulses
// act once per sub-step whatever the integrator: a reference stepped as coarsely as one of
// the runs would agree with that run's contact timing exactly and call it error-free. So the
// reference's sub-step is four times finer than the finest run (at least).
SceneDesc referenceScene(const SceneDesc& scene, double endTime, bool contacts, double finestDt) {
    SceneDesc s = scene;
    s.name.clear();
    s.description.clear();
    s.simulation.integrator = "rk45";
    s.simulation.tolerance = kReferenceTolerance;
    s.simulation.newtonIterations = 1;
    s.simulation.duration = endTime;
    if (contacts) {
        const double target =
            std::min(scene.simulation.dt / scene.simulation.substeps, finestDt) / 4.0;
        const double substeps = std::ceil(scene.simulation.dt / target - 1e-9);
        // Within the format's limits, so that the reference costs what a scene may ask for.
        const double most =
            std::min<double>(SceneLimits::kMaxSubsteps,
                             SceneLimits::kMaxSubstepWork / std::max(1LL, stepWorkUnits(scene)));
        s.simulation.substeps =
            static_cast<int>(std::clamp(substeps, double(scene.simulation.substeps),
                                        std::max(most, double(scene.simulation.substeps))));
    }
    return s;
}

QByteArray referenceKey(const SceneDesc& referenceScene, double endTime) {
    return SceneIO::serialize(referenceScene) + "\nend time " + formatNumber(endTime).toUtf8();
}

struct ReferenceOutcome {
    std::optional<Vec> positions;
    bool fromCache = false;
    bool cancelled = false;
    std::string error;
};

ReferenceOutcome rk45Reference(const SceneDesc& scene, double endTime, bool contacts,
                               double finestDt, const std::atomic<bool>* cancel) {
    ReferenceOutcome out;
    const SceneDesc s = referenceScene(scene, endTime, contacts, finestDt);
    const QByteArray key = referenceKey(s, endTime);
    ReferenceCache& cache = referenceCache();
    {
        const std::lock_guard lock(cache.mutex);
        for (const auto& [k, q] : cache.entries) {
            if (k != key) continue;
            out.positions = q;
            out.fromCache = true;
            return out;
        }
    }
    // Computed outside the lock: a long reference must not stall another study (two studies
    // of the same scene at the same moment may both compute it; the second insert is dropped).
    auto world = buildWorld(s).world;
    const RunOutcome run = runToEnd(*world, endTime, cancel);
    if (run.cancelled) {
        out.cancelled = true;
        return out;
    }
    if (run.diverged) {
        out.error = "the rk45 reference run failed: " + run.divergence;
        return out;
    }
    cache.computations.fetch_add(1);
    const std::lock_guard lock(cache.mutex);
    const bool present = std::any_of(cache.entries.begin(), cache.entries.end(),
                                     [&](const auto& e) { return e.first == key; });
    if (!present) {
        cache.entries.emplace_back(key, run.positions);
        if (cache.entries.size() > kCacheEntries) cache.entries.pop_front();
    }
    out.positions = run.positions;
    return out;
}

// ---- one record ---------------------------------------------------------------------------

// Runs one integrator at one dt (and tolerance), repeating short runs for a steadier time.
// nullopt when cancelled before the first run finished.
std::optional<AccuracyRecord> measure(const SceneDesc& base, const IntegratorInfo& method,
                                      double dt, std::optional<double> tolerance, double endTime,
                                      const std::optional<Vec>& reference,
                                      const AccuracyOptions& options,
                                      const std::atomic<bool>* cancel) {
    SceneDesc scene = base;
    scene.simulation.integrator = std::string(method.name);
    scene.simulation.dt = dt;
    if (tolerance) scene.simulation.tolerance = *tolerance;

    AccuracyRecord record;
    record.integrator = scene.simulation.integrator;
    record.dt = dt;
    record.tolerance = tolerance;
    double spent = 0.0;
    for (int repeat = 0; repeat < std::max(1, options.maxRepeats); ++repeat) {
        auto world = buildWorld(scene).world;  // building is not part of the cost
        // The cost is this thread's CPU time: the method's work all on it.
        world->setWorkers(1);
        const RunOutcome run = runToEnd(*world, endTime, cancel);
        if (run.cancelled) {
            if (repeat == 0) return std::nullopt;
            break;
        }
        spent += run.cpuSeconds;
        if (repeat == 0) {
            record.cpuSeconds = run.cpuSeconds;
            record.steps = run.steps;
            record.forceEvals = run.forceEvals;
            record.energyDrift = run.maxAbsDrift;
            record.diverged = run.diverged;
            record.divergence = run.divergence;
            if (run.diverged)
                record.positionError = std::numeric_limits<double>::infinity();
            else if (!reference)
                record.positionError = std::numeric_limits<double>::quiet_NaN();
            else if (run.positions.size() == 0)
                record.positionError = 0.0;
            else
                record.positionError = (run.positions - *reference).lpNorm<Eigen::Infinity>();
        } else {
            record.cpuSeconds = std::min(record.cpuSeconds, run.cpuSeconds);
        }
        record.repeats = repeat + 1;
        if (run.diverged || run.cpuSeconds >= options.repeatBelowSeconds ||
            spent >= options.repeatBudgetSeconds)
            break;
    }
    return record;
}

void computeOrders(AccuracyResult& result) {
    // With contacts the error is dominated by when each impact is detected, an O(h) event
    // error for every method: a computed "order" would only mislead.
    if (result.contacts) return;
    std::map<std::string, std::size_t> previous;
    for (std::size_t i = 0; i < result.records.size(); ++i) {
        AccuracyRecord& r = result.records[i];
        const auto it = previous.find(r.integrator);
        const std::optional<std::size_t> before =
            it == previous.end() ? std::nullopt : std::optional<std::size_t>(it->second);
        previous[r.integrator] = i;
        if (!before || r.tolerance) continue;
        const AccuracyRecord& p = result.records[*before];
        const bool usable = std::isfinite(p.positionError) && std::isfinite(r.positionError) &&
                            p.positionError > 0.0 && r.positionError > 0.0 && p.dt != r.dt;
        if (usable) r.order = std::log(p.positionError / r.positionError) / std::log(p.dt / r.dt);
    }
}

// The end time in [t, t + P/2] where the exact positions move fastest, when at t they move at
// less than half that speed; t otherwise. Candidates lie on the grid of the coarsest step, so
// that every run of the study still ends on a whole number of its steps.
double endTimeAwayFromTurningPoints(const ExactReference& exact, double t, double period,
                                    double grid) {
    const double h = 1e-4 * period;
    const auto speed = [&](double at) {
        return (exact.positions(at + h) - exact.positions(std::max(0.0, at - h))).norm();
    };
    double best = t, fastest = speed(t);
    const double atStart = fastest;
    const long long base = std::llround(t / grid);
    const int samples = static_cast<int>(std::min(4096.0, std::ceil(0.5 * period / grid)));
    for (int j = 1; j <= samples; ++j) {
        const double at = static_cast<double>(base + j) * grid;
        if (const double v = speed(at); v > fastest) {
            fastest = v;
            best = at;
        }
    }
    return atStart < 0.5 * fastest ? best : t;
}

// Observed orders well above each fixed-step method's own, as warnings.
void warnAboutDistortedOrders(AccuracyResult& result) {
    std::map<std::string, std::vector<double>> observed;
    for (const AccuracyRecord& r : result.records)
        if (r.order && !r.tolerance) observed[r.integrator].push_back(*r.order);
    for (auto& [name, orders] : observed) {
        const IntegratorInfo* info = findIntegrator(name);
        if (!info || orders.empty()) continue;
        std::nth_element(orders.begin(), orders.begin() + orders.size() / 2, orders.end());
        const double median = orders[orders.size() / 2];
        if (median <= info->order + kOrderWarning) continue;
        std::ostringstream out;
        out.precision(3);
        out << name << "'s observed order " << median << " is above its order " << info->order
            << ": its errors cancel at t = " << result.endTime
            << " s (a turning point or a whole number of periods); study another duration";
        result.warnings.push_back(out.str());
    }
}

// Throws unless 0 < value <= upper (and finite).
void checkRange(const char* what, double value, double upper) {
    if (std::isfinite(value) && value > 0.0 && value <= upper) return;
    std::string range = " must be > 0";
    if (std::isfinite(upper)) range += " and <= " + formatNumber(upper).toStdString();
    throw std::invalid_argument(what + range + " (got " + formatNumber(value).toStdString() + ")");
}

}  // namespace

std::vector<double> defaultAccuracyDts(double sceneDt) {
    std::vector<double> dts;
    for (int k = 0; k <= 5; ++k) dts.push_back(sceneDt / static_cast<double>(1 << k));
    return dts;
}

std::vector<double> defaultAccuracyTolerances(std::string_view integrator) {
    // Adaptive methods land on every frame boundary, and a high-order one (rk45) meets a loose
    // tolerance with steps far longer than a frame: from 1e-2 to 1e-5 it would just take one
    // step per frame and the six points would coincide. Its sweep starts where the tolerance
    // binds, and stays well above the reference's 1e-12, so that it is never measured against
    // itself.
    const IntegratorInfo* info = findIntegrator(integrator);
    if (info && info->adaptive && info->order >= 4) return {1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
    return {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7};
}

long long accuracyReferenceComputations() {
    return referenceCache().computations.load();
}

void clearAccuracyReferenceCache() {
    ReferenceCache& cache = referenceCache();
    const std::lock_guard lock(cache.mutex);
    cache.entries.clear();
}

AccuracyResult runAccuracyStudy(const SceneDesc& scene, const AccuracyOptions& options,
                                const AccuracyProgress& progress, const std::atomic<bool>* cancel) {
    std::vector<const IntegratorInfo*> methods;
    if (options.integrators.empty()) {
        for (const IntegratorInfo& info : integratorRegistry()) methods.push_back(&info);
    } else {
        for (const std::string& name : options.integrators) {
            const IntegratorInfo* info = findIntegrator(name);
            if (!info)
                throw std::invalid_argument("unknown integrator \"" + name +
                                            "\"; known: " + knownIntegratorNames());
            methods.push_back(info);
        }
    }
    const std::vector<double> dts =
        options.dts.empty() ? defaultAccuracyDts(scene.simulation.dt) : options.dts;
    const double maxDt = schema::simulationField(schema::key::dt).range.max;  // World's too
    for (double dt : dts) checkRange("dt", dt, maxDt);
    for (double tol : options.tolerances) checkRange("tolerance", tol, kNoUpperBound);
    const auto tolerancesOf = [&](const IntegratorInfo& method) {
        return options.tolerances.empty() ? defaultAccuracyTolerances(method.name)
                                          : options.tolerances;
    };
    double endTime = options.duration != 0.0 ? options.duration : scene.simulation.duration;
    checkRange("duration", endTime, kNoUpperBound);

    AccuracyResult result;
    result.endTime = endTime;
    // Every run uses one sub-step, so that dt is the integrator's step (a scene stepped with
    // n sub-steps at dt corresponds to the row at dt/n). The reference keeps the scene's own.
    SceneDesc base = scene;
    base.simulation.substeps = 1;
    const BuildResult probe = buildWorld(scene);  // throws SceneError
    result.contacts = probe.world->contacts() != nullptr;
    if (result.contacts)
        result.note = scene.simulation.contactModel == ContactModel::Penalty ? kPenaltyContactNote
                                                                             : kContactNote;
    for (const IntegratorInfo* m : methods)
        result.plannedRuns += static_cast<int>(m->adaptive ? tolerancesOf(*m).size() : dts.size());
    const int total = result.plannedRuns + 1;
    const auto report = [&](int done) {
        if (progress) progress(done, total);
    };
    report(0);

    std::optional<Vec> reference;
    if (const auto exact = findExactReference(scene, *probe.world, endTime)) {
        // At a turning point (a whole or half number of periods of an oscillation) a phase
        // error hardly moves the position, and every method looks more accurate and of a higher
        // order than it is (symplectic Euler 3.02, RK4 5.00 on the oscillator at 10 s). Unless
        // the user chose the end time, the study ends where the exact motion is fastest within
        // the next half period, when the scene's duration is near a turning point.
        if (options.duration == 0.0 || options.durationIsDefault) {
            const std::vector<double> periods = exact->periods();
            if (!periods.empty()) {
                const double shortest = *std::min_element(periods.begin(), periods.end());
                endTime = endTimeAwayFromTurningPoints(*exact, endTime, shortest,
                                                       *std::max_element(dts.begin(), dts.end()));
                result.endTimeMoved = endTime != result.endTime;
                result.endTime = endTime;
            }
        }
        result.reference = "exact: " + exact->kind();
        result.referenceExact = true;
        reference = exact->positions(endTime);
    } else {
        result.reference = kReferenceName;
        const double finestDt = *std::min_element(dts.begin(), dts.end());
        ReferenceOutcome outcome = rk45Reference(scene, endTime, result.contacts, finestDt, cancel);
        if (outcome.cancelled) {
            result.cancelled = true;
            return result;
        }
        result.referenceFromCache = outcome.fromCache;
        result.error = outcome.error;
        reference = std::move(outcome.positions);
    }
    result.positionScale = probe.world->positions().lpNorm<Eigen::Infinity>();
    if (reference && reference->size() > 0)
        result.positionScale = std::max(result.positionScale, reference->lpNorm<Eigen::Infinity>());
    int done = 1;
    report(done);

    for (const IntegratorInfo* method : methods) {
        // Adaptive methods choose their own steps: they sweep the tolerance at one frame step.
        std::vector<std::pair<double, std::optional<double>>> items;
        if (method->adaptive)
            for (double tol : tolerancesOf(*method)) items.emplace_back(dts.front(), tol);
        else
            for (double dt : dts) items.emplace_back(dt, std::nullopt);
        for (const auto& [dt, tol] : items) {
            if (isCancelled(cancel)) break;
            std::optional<AccuracyRecord> record =
                measure(base, *method, dt, tol, endTime, reference, options, cancel);
            if (!record) break;
            result.records.push_back(std::move(*record));
            report(++done);
        }
        if (isCancelled(cancel)) break;
    }
    // Only a cancel stops the study early (a diverging run is a record like any other).
    result.cancelled = static_cast<int>(result.records.size()) < result.plannedRuns;
    computeOrders(result);
    warnAboutDistortedOrders(result);
    return result;
}

// ---- the worker-thread wrapper ------------------------------------------------------------

AccuracyStudy::AccuracyStudy(QObject* parent) : QObject(parent) {
    connect(&watcher_, &QFutureWatcherBase::finished, this, &AccuracyStudy::collect);
}

AccuracyStudy::~AccuracyStudy() {
    cancel();
    watcher_.waitForFinished();
}

bool AccuracyStudy::start(const SceneDesc& scene, const AccuracyOptions& options) {
    if (isRunning()) return false;
    cancel_ = std::make_shared<std::atomic<bool>>(false);
    // The worker owns copies of the scene and the options, and shares the flag: the document
    // may change while the study runs. Progress reaches the signal through this object's
    // thread (a queued call), and the destructor waits for the worker, so `this` outlives it.
    watcher_.setFuture(QtConcurrent::run([this, scene, options, flag = cancel_] {
        AccuracyResult result;
        try {
            result = runAccuracyStudy(
                scene, options,
                [this](int done, int total) {
                    QMetaObject::invokeMethod(
                        this, [this, done, total] { emit progress(done, total); },
                        Qt::QueuedConnection);
                },
                flag.get());
        } catch (const std::exception& e) {
            result.error = e.what();
        }
        return result;
    }));
    return true;
}

bool AccuracyStudy::isRunning() const {
    return watcher_.isRunning();
}

void AccuracyStudy::cancel() {
    if (cancel_) cancel_->store(true);
}

void AccuracyStudy::waitForFinished() {
    watcher_.waitForFinished();
}

void AccuracyStudy::collect() {
    result_ = watcher_.result();
    emit finished();
}

}  // namespace phasebox
