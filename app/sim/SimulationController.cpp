#include "app/sim/SimulationController.h"

#include "app/document/Document.h"
#include "app/sim/DivergenceReport.h"
#include "app/sim/ProbeRecorder.h"
#include "app/sim/Recorder.h"
#include "app/sim/RewindCommand.h"
#include "app/sim/RunRecording.h"
#include "physics/world/World.h"
#include "physics/world/WorldSnapshot.h"

#include <algorithm>
#include <cmath>

namespace phasebox {

namespace {
// A longer gap between ticks (a debugger stop, a suspended laptop, a modal dialog) is not owed
// to the simulation: catching up on it would only burn the next ticks' budgets.
constexpr double kMaxTickGapSeconds = 0.25;
// Steps whose clock lands this close below a whole dt still count as whole (rounding).
constexpr double kDtSlack = 1e-9;
constexpr qint64 kStatsIntervalNs = 250'000'000;
constexpr qint64 kRateWindowNs = 1'000'000'000;
// The weight of the newest step in the moving average of msPerStep().
constexpr double kAverageWeight = 0.05;
}  // namespace

SimulationController::SimulationController(Document& document, QObject* parent)
    : QObject(parent), document_(document) {
    timer_.setTimerType(Qt::PreciseTimer);
    timer_.setInterval(kTickMs);
    connect(&timer_, &QTimer::timeout, this, &SimulationController::tick);
    // A new scene (load, new, reset) starts paused, with none of the last scene's figures.
    connect(&document_, &Document::sceneReset, this, &SimulationController::forgetScene);
    // An edit makes another run: the recording starts over from the edited state.
    connect(&document_, &Document::sceneEdited, this, &SimulationController::forgetRecording);
    clock_.start();
}

void SimulationController::setSpeed(double speed) {
    // std::clamp passes a NaN through, and a NaN speed never fills the backlog: Play would
    // run no step at all.
    if (!std::isfinite(speed)) return;
    speed_ = std::clamp(speed, kMinSpeed, kMaxSpeed);
}

void SimulationController::play() {
    if (isRunning()) return;
    resumeFromShownFrame();
    backlog_ = 0.0;
    recentTicks_.clear();
    sinceTick_.start();
    timer_.start();
    emit runningChanged(true);
}

void SimulationController::pause() {
    if (!isRunning()) return;
    timer_.stop();
    backlog_ = 0.0;
    recentTicks_.clear();
    realTimeFactor_ = 0.0;
    emit runningChanged(false);
    emit statsChanged();
}

void SimulationController::forgetScene() {
    pause();
    forgetRecording();
    lastError_ = std::numeric_limits<double>::quiet_NaN();
    msPerStep_ = 0.0;
    realTimeFactor_ = 0.0;
    emit statsChanged();
}

void SimulationController::togglePlay() {
    isRunning() ? pause() : play();
}

void SimulationController::singleStep() {
    pause();
    resumeFromShownFrame();
    const bool ok = stepOnce();
    flushRecorders();
    if (ok) emit stepped();
}

void SimulationController::reset() {
    pause();
    document_.reset();
}

bool SimulationController::advance(double simSeconds) {
    resumeFromShownFrame();
    const double target = document_.world().time() + simSeconds;
    bool ok = true, moved = false;
    // One estimate per 1/60 s of simulated time, as many as playing at 1× would make.
    const double dt = document_.world().settings().dt;
    const long long stride = std::max<long long>(1, std::llround(1.0 / (60.0 * dt)));
    long long steps = 0;
    while (document_.world().time() + 0.5 * document_.world().settings().dt < target) {
        if (!stepOnce()) {
            ok = false;
            break;
        }
        moved = true;
        if (++steps % stride == 0) estimateError();
    }
    flushRecorders();
    if (moved) emit stepped();
    return ok;
}

void SimulationController::tick() {
    const double wall =
        std::min(static_cast<double>(sinceTick_.nsecsElapsed()) * 1e-9, kMaxTickGapSeconds);
    sinceTick_.restart();
    const double dt = document_.world().settings().dt;
    backlog_ += wall * speed_;

    QElapsedTimer budget;
    budget.start();
    const qint64 budgetNs = static_cast<qint64>(kBudgetMs * 1e6);
    double simulated = 0.0;
    bool moved = false;
    while (backlog_ >= dt * (1.0 - kDtSlack)) {
        // At least one step per tick, however slow: the clock must move. After that the budget
        // rules, and what it leaves undone is dropped, not owed (the clock slows instead).
        if (moved && budget.nsecsElapsed() > budgetNs) {
            backlog_ = 0.0;
            break;
        }
        if (!stepOnce()) {
            flushRecorders();
            if (moved) emit stepped();
            return;
        }
        backlog_ -= dt;
        simulated += dt;
        moved = true;
    }
    if (moved) estimateError();
    flushRecorders();
    updateRealTimeFactor(wall, simulated);
    if (moved) emit stepped();
}

void SimulationController::flushRecorders() {
    if (recorder_) recorder_->flush();
    if (probes_) probes_->flush();
}

double SimulationController::lastErrorEstimate() const {
    if (shownFrame_ < 0 || !runRecording_) return lastError_;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (!recorder_) return nan;
    const double t = runRecording_->frame(shownFrame_).time;
    const std::vector<QPointF>& errors = recorder_->errorSamples();
    const auto at = std::lower_bound(errors.begin(), errors.end(), t,
                                     [](const QPointF& p, double time) { return p.x() < time; });
    return at != errors.end() && at->x() == t ? at->y() : nan;
}

void SimulationController::estimateError() {
    if (!estimateErrors_ || msPerStep_ > kMaxEstimateStepMs) {
        lastError_ = std::numeric_limits<double>::quiet_NaN();
        return;
    }
    World& world = document_.world();
    lastError_ = world.estimateLocalError();
    if (recorder_) recorder_->recordError(world.time(), lastError_);
}

bool SimulationController::stepOnce() {
    World& world = document_.world();
    recordFrame();  // the setup's frame, before the first step of a run
    QElapsedTimer timer;
    timer.start();
    const bool ok = world.step();
    const double ms = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
    msPerStep_ = msPerStep_ == 0.0 ? ms : (1.0 - kAverageWeight) * msPerStep_ + kAverageWeight * ms;
    if (!ok) {
        reportDivergence();
        return false;
    }
    if (recorder_) recorder_->record(world);
    if (probes_) probes_->record(world);
    recordFrame();
    return true;
}

// ---- the recording behind the timeline ---------------------------------------------------------

void SimulationController::setRunRecording(RunRecording* recording) {
    forgetRecording();
    runRecording_ = recording;
}

void SimulationController::forgetRecording() {
    if (runRecording_) runRecording_->clear();
    shownFrame_ = -1;
    liveEnd_.reset();
    ++runGeneration_;
    emit frameShown(-1);
}

void SimulationController::recordFrame() {
    if (!runRecording_) return;
    const World& world = document_.world();
    const int n = runRecording_->frameCount();
    if (n > 0 && runRecording_->frame(n - 1).stepCount == world.stepCount() &&
        runRecording_->frame(n - 1).time == world.time())
        return;
    if (n > 0 && runRecording_->frame(n - 1).stepCount >= world.stepCount()) ++runGeneration_;
    runRecording_->record(world);
}

bool SimulationController::showFrame(int index) {
    if (!runRecording_ || index < 0 || index >= runRecording_->frameCount()) return false;
    pause();
    World& world = document_.world();
    const int last = runRecording_->frameCount() - 1;
    if (shownFrame_ < 0) {
        if (index == last) return true;  // already there
        liveEnd_ = std::make_shared<WorldSnapshot>(WorldSnapshot::take(world));
    }
    if (index == last) {
        liveEnd_->restoreInto(world);
        liveEnd_.reset();
        shownFrame_ = -1;
    } else {
        if (!runRecording_->show(world, index)) return false;
        shownFrame_ = index;
    }
    emit frameShown(shownFrame_);
    emit stepped();
    return true;
}

void SimulationController::resumeFromShownFrame() {
    if (shownFrame_ < 0 || !runRecording_) return;
    World& world = document_.world();
    const FrameState& frame = runRecording_->frame(shownFrame_);
    Branch dropped;
    dropped.generation = runGeneration_;
    dropped.step = frame.stepCount;
    dropped.time = frame.time;
    dropped.end = std::move(liveEnd_);
    const int shownIndex = shownFrame_;
    shownFrame_ = -1;
    // A run the user steered (a drag, an edit while paused) cannot be re-simulated from its
    // keyframe; it then goes on from the frame's recorded state with what the world carries now.
    if (!runRecording_->restore(world, dropped.step)) runRecording_->show(world, shownIndex);
    dropped.frames = runRecording_->truncateAfter(dropped.step);
    if (recorder_) dropped.samples = recorder_->takeAfter(dropped.time);
    document_.undoStack()->push(new RewindCommand(*this, std::move(dropped)));
    emit frameShown(-1);
}

void SimulationController::swapBranch(Branch& branch) {
    if (!runRecording_ || branch.generation != runGeneration_ || !branch.end) return;
    pause();
    World& world = document_.world();
    if (shownFrame_ >= 0 && liveEnd_) liveEnd_->restoreInto(world);
    shownFrame_ = -1;
    liveEnd_.reset();
    Branch current;
    current.generation = branch.generation;
    current.step = branch.step;
    current.time = branch.time;
    current.end = std::make_shared<WorldSnapshot>(WorldSnapshot::take(world));
    if (!branch.end->restoreInto(world)) return;
    current.frames = runRecording_->truncateAfter(branch.step);
    runRecording_->append(std::move(branch.frames));
    if (recorder_) {
        current.samples = recorder_->takeAfter(branch.time);
        recorder_->putBack(std::move(branch.samples));
    }
    branch = std::move(current);
    flushRecorders();
    emit frameShown(-1);
    emit stepped();
}

void SimulationController::reportDivergence() {
    pause();
    // In the classroom's words, with the stability advisor's step for this scene and method (it
    // reads the stiffest mode from the force Jacobian); the engine's message is the details.
    const DivergenceReport report = describeDivergence(document_.world());
    emit diverged(report.text, report.details);
}

void SimulationController::updateRealTimeFactor(double wallSeconds, double simSeconds) {
    const qint64 now = clock_.nsecsElapsed();
    recentTicks_.push_back({now, wallSeconds, simSeconds});
    while (!recentTicks_.empty() && recentTicks_.front().endNs < now - kRateWindowNs)
        recentTicks_.pop_front();
    double wall = 0.0, sim = 0.0;
    for (const TickRecord& t : recentTicks_) {
        wall += t.wallSeconds;
        sim += t.simSeconds;
    }
    realTimeFactor_ = wall > 0.0 ? sim / wall : 0.0;
    if (now - lastStatsNs_ >= kStatsIntervalNs) {
        lastStatsNs_ = now;
        emit statsChanged();
    }
}

}  // namespace phasebox
