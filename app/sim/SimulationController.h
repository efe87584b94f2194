#pragma once
// Drives the document's world in (scaled) real time: fixed-dt steps on a ~60 Hz timer with a
// frame budget.
//
// Each tick adds the wall time since the last tick, times the speed, to a backlog of
// simulated time and takes as many world steps as the backlog holds, but stops when the
// tick's wall budget is spent and drops the rest of the backlog. A scene too heavy for real
// time therefore runs in slow motion (realTimeFactor() < speed) instead of freezing the
// window: the event loop gets control back every tick. A step is never split or skipped,
// so the run is the same sequence of dt steps however fast the machine is.

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <deque>
#include <limits>
#include <memory>

namespace phasebox {

class Document;
class ProbeRecorder;
class Recorder;
class RunRecording;
class WorldSnapshot;

class SimulationController : public QObject {
    Q_OBJECT

public:
    explicit SimulationController(Document& document, QObject* parent = nullptr);

    bool isRunning() const { return timer_.isActive(); }
    // Simulated seconds per wall second, clamped to [0.25, 4].
    void setSpeed(double speed);
    double speed() const { return speed_; }
    // Simulated time per wall time over the last second (0 while paused).
    double realTimeFactor() const { return realTimeFactor_; }
    // Wall milliseconds per world step, a moving average.
    double msPerStep() const { return msPerStep_; }

    // The recorder is fed after every successful step (and flushed once per tick), so the
    // plots get every sample, not one per frame. nullptr to stop.
    void setRecorder(Recorder* recorder) { recorder_ = recorder; }
    // The instruments' probes, fed and flushed like the recorder.
    void setProbeRecorder(ProbeRecorder* probes) { probes_ = probes; }

    // The run's recording behind the timeline (RunRecording): a frame after every step, the
    // setup's frame before the first. nullptr to stop.
    void setRunRecording(RunRecording* recording);
    RunRecording* runRecording() const { return runRecording_; }
    // Shows a recorded frame (and pauses): the world takes that frame's state, clock and ledger,
    // so the canvas, plots, readouts and instruments show that moment. The last frame is the
    // run's live end, put back whole. False for an index out of range.
    bool showFrame(int index);
    // The frame shown, -1 at the live end.
    int shownFrame() const { return shownFrame_; }
    // Play and Step from a shown frame go on from its whole state (the recording's keyframe
    // before it, re-simulated) and drop the later frames and plot samples, as one step on the
    // document's undo stack; undoing it brings the dropped branch back. A run steered by hand
    // between the keyframe and the frame cannot be re-simulated: it then goes on from the
    // frame's recorded state.
    void resumeFromShownFrame();

    // One branch of a run after a step: what a rewind drops, what its undo puts back.
    struct Branch;
    // Swaps the recording, plot samples and world after the branch's step with the branch's.
    void swapBranch(Branch& branch);

    // Runs synchronously until the world's clock has advanced by simSeconds (to within half a
    // step), without the timer or the frame budget: for tests, the command line and
    // "--run-for". Returns false when the simulation diverged (which is reported as in play).
    bool advance(double simSeconds);

    // The live error estimate (World::estimateLocalError, about three steps' work) once per
    // displayed frame, recorded by the recorder. Skipped while a step costs more than
    // kMaxEstimateStepMs, so a heavy scene does not slow down four-fold for it.
    void setEstimateErrors(bool on) { estimateErrors_ = on; }
    bool estimatesErrors() const { return estimateErrors_; }
    // The estimate of the moment shown (m or rad): the last one at the live end; at a recorded
    // frame the one made at its very time, NaN when none was made then (estimates are made once
    // per displayed frame, not every step).
    double lastErrorEstimate() const;
    static constexpr double kMaxEstimateStepMs = 4.0;

    static constexpr double kMinSpeed = 0.25;
    static constexpr double kMaxSpeed = 4.0;
    static constexpr int kTickMs = 16;         // ~60 Hz
    static constexpr double kBudgetMs = 12.0;  // leaves the rest of a 16 ms frame for painting

public slots:
    void play();
    void pause();
    // Paused, and the figures of the scene before (error estimate, cost of a step) gone.
    void forgetScene();
    void togglePlay();
    // One world step, paused or not.
    void singleStep();
    // Pauses and rebuilds the world from the setup (Document::reset).
    void reset();

signals:
    void runningChanged(bool running);
    // After each tick (or single step, or advance) that moved the clock.
    void stepped();
    void statsChanged();
    // The world diverged and was restored to its last good state; the controller paused.
    // The message says in plain words when, in which object and what to try (DivergenceReport);
    // details hold the engine's technical message and the stability advisor's.
    void diverged(const QString& message, const QString& details);
    // The timeline's frame changed: showFrame() (-1 back at the live end), or the recording
    // grew or was cut.
    void frameShown(int index);

private:
    void tick();
    // One world step, timed and recorded; false when it diverged (already reported).
    bool stepOnce();
    void reportDivergence();
    void updateRealTimeFactor(double wallSeconds, double simSeconds);
    void estimateError();
    void flushRecorders();
    void recordFrame();
    void forgetRecording();

    Document& document_;
    RunRecording* runRecording_ = nullptr;
    int shownFrame_ = -1;
    // The world's whole state at the live end while an earlier frame is shown.
    std::shared_ptr<WorldSnapshot> liveEnd_;
    // Which run the recording is of: a new scene or an edit starts another, and a branch kept
    // by an undo command for an older one is not swapped in.
    long long runGeneration_ = 0;
    Recorder* recorder_ = nullptr;
    ProbeRecorder* probes_ = nullptr;
    QTimer timer_;
    QElapsedTimer sinceTick_;
    double speed_ = 1.0;
    double backlog_ = 0.0;  // simulated seconds owed to the wall clock

    // Statistics: the ticks of the last second (wall, simulated) for the real-time factor.
    struct TickRecord {
        qint64 endNs;
        double wallSeconds, simSeconds;
    };
    QElapsedTimer clock_;
    std::deque<TickRecord> recentTicks_;
    qint64 lastStatsNs_ = 0;
    double realTimeFactor_ = 0.0;
    double msPerStep_ = 0.0;
    bool estimateErrors_ = true;
    double lastError_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace phasebox
