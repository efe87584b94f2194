// The run's recording (RunRecording): every recorded frame is the state the run had at that
// step, bit for bit; restoring any step (recorded or thinned out) by keyframe and re-simulation
// gives that step's bits, and the run goes on from there as it went on the first time; memory
// stays within the budget; truncating and appending back gives the recording it was.

#include "app/sim/RunRecording.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"
#include "tests/support/StateBits.h"

#include <QTest>

#include <bit>
#include <cstdint>
#include <vector>

using namespace phasebox;
using testing::stateBits;

namespace {

// Runs the scene for steps steps, recording every one; reference[k] is the state after step k.
struct RecordedRun {
    std::unique_ptr<World> world;
    RunRecording recording;
    std::vector<std::vector<std::uint64_t>> reference;

    RecordedRun(const SceneDesc& scene, int steps, std::size_t budget, long long keyframeEvery)
        : world(buildWorld(scene).world), recording(budget) {
        recording.setKeyframeInterval(keyframeEvery);
        recording.record(*world);
        reference.push_back(stateBits(*world));
        for (int i = 0; i < steps; ++i) {
            world->step();
            recording.record(*world);
            reference.push_back(stateBits(*world));
        }
    }
};

}  // namespace

class TestRunRecording : public QObject {
    Q_OBJECT

private slots:
    void everyFrameIsTheRunsState() {
        RecordedRun run(scenes::pyramid(6), 200, RunRecording::kDefaultBudgetBytes, 50);
        QCOMPARE(run.recording.frameCount(), 201);
        QCOMPARE(run.recording.keyframeCount(), 5);
        for (int i = 0; i <= 200; ++i) {
            const FrameState& f = run.recording.frame(i);
            QCOMPARE(f.stepCount, static_cast<long long>(i));
            QVERIFY(stateBits(f) == run.reference[static_cast<std::size_t>(i)]);
        }
        // Shown frames are those states in the world itself, whatever the order.
        for (int i : {120, 3, 200, 77, 0}) {
            QVERIFY(run.recording.show(*run.world, i));
            QVERIFY(stateBits(*run.world) == run.reference[static_cast<std::size_t>(i)]);
            QCOMPARE(run.world->stepCount(), static_cast<long long>(i));
        }
        QCOMPARE(run.recording.frameAtOrBefore(run.recording.frame(77).time), 77);
        QCOMPARE(run.recording.frameAtOrBefore(-1.0), 0);
        QCOMPARE(run.recording.frameAtOrBefore(1e9), 200);
    }

    // Restoring a step and stepping on retraces the run: stepping back and then forward gives
    // the same frames.
    void restoreAndStepOnRetracesTheRun() {
        for (const char* integrator : {"symplectic_euler", "rk45"}) {
            SceneDesc scene = scenes::pyramid(5);
            scene.simulation.integrator = integrator;
            RecordedRun run(scene, 150, RunRecording::kDefaultBudgetBytes, 40);
            for (long long step : {149LL, 0LL, 41LL, 80LL, 99LL}) {
                QVERIFY(run.recording.restore(*run.world, step));
                QVERIFY(stateBits(*run.world) == run.reference[static_cast<std::size_t>(step)]);
                for (long long k = step + 1; k <= std::min(step + 30, 150LL); ++k) {
                    QVERIFY(run.world->step());
                    QVERIFY2(stateBits(*run.world) == run.reference[static_cast<std::size_t>(k)],
                             qPrintable(QStringLiteral("%1: step %2 from %3")
                                            .arg(integrator)
                                            .arg(k)
                                            .arg(step)));
                }
            }
            QVERIFY(!run.recording.restore(*run.world, 151));
        }
    }

    // Over its budget the recording thins its older half; the newest frames stay complete and
    // a thinned-out step is still restored exactly.
    void staysWithinItsBudget() {
        const std::size_t budget = std::size_t{1} << 20;
        RecordedRun run(scenes::pyramid(6), 1500, budget, 100);
        QVERIFY(run.recording.bytesUsed() <= budget);
        QVERIFY(run.recording.frameCount() < 1501);
        QCOMPARE(run.recording.frame(0).stepCount, 0LL);
        const int last = run.recording.frameCount() - 1;
        QCOMPARE(run.recording.frame(last).stepCount, 1500LL);
        QCOMPARE(run.recording.frame(last - 50).stepCount, 1450LL);
        for (int i = 0; i <= last; ++i) {
            const FrameState& f = run.recording.frame(i);
            QVERIFY(stateBits(f) == run.reference[static_cast<std::size_t>(f.stepCount)]);
        }
        long long thinned = -1;
        for (int i = 1; i <= last && thinned < 0; ++i)
            if (run.recording.frame(i).stepCount != run.recording.frame(i - 1).stepCount + 1)
                thinned = run.recording.frame(i).stepCount - 1;
        QVERIFY(thinned > 0);
        QVERIFY(run.recording.restore(*run.world, thinned));
        QVERIFY(stateBits(*run.world) == run.reference[static_cast<std::size_t>(thinned)]);
        // A smaller budget thins at once.
        run.recording.setBudgetBytes(budget / 2);
        QVERIFY(run.recording.bytesUsed() <= budget / 2);
    }

    void truncateAndAppendBack() {
        RecordedRun run(scenes::pyramid(4), 100, RunRecording::kDefaultBudgetBytes, 30);
        const std::size_t bytes = run.recording.bytesUsed();
        RunRecording::Tail tail = run.recording.truncateAfter(45);
        QCOMPARE(run.recording.frameCount(), 46);
        QCOMPARE(run.recording.keyframeCount(), 2);
        QCOMPARE(tail.frames.size(), std::size_t{55});
        QVERIFY(!run.recording.restore(*run.world, 60));
        run.recording.append(std::move(tail));
        QCOMPARE(run.recording.frameCount(), 101);
        QCOMPARE(run.recording.keyframeCount(), 4);
        QCOMPARE(run.recording.bytesUsed(), bytes);
        QVERIFY(run.recording.restore(*run.world, 95));
        QVERIFY(stateBits(*run.world) == run.reference[95]);
    }

    // A method switched live: a keyframe at the switch, so re-simulation after it runs the new
    // method and before it the old one.
    void aSwitchOfMethodIsRetraced() {
        auto world = buildWorld(scenes::pyramid(4)).world;
        RunRecording recording;
        recording.setKeyframeInterval(1000);
        std::vector<std::vector<std::uint64_t>> reference;
        recording.record(*world);
        reference.push_back(stateBits(*world));
        for (int i = 1; i <= 80; ++i) {
            if (i == 41) world->setIntegrator("rk4");
            world->step();
            recording.record(*world);
            reference.push_back(stateBits(*world));
        }
        QCOMPARE(recording.keyframeCount(), 2);
        for (long long step : {75LL, 20LL, 41LL, 40LL}) {
            QVERIFY(recording.restore(*world, step));
            QVERIFY(stateBits(*world) == reference[static_cast<std::size_t>(step)]);
        }
    }

    // With sleeping on the state's layout changes as the pile falls asleep: the recording goes
    // on through it, every frame is the run's state, and a restore on either side retraces it.
    void recordsThroughFallingAsleep() {
        SceneDesc scene = scenes::pyramid(5);
        scene.simulation.sleep = true;
        RecordedRun run(scene, 150, RunRecording::kDefaultBudgetBytes, 40);
        QCOMPARE(run.recording.frameCount(), 151);
        QVERIFY(run.world->sleepingBodies() == 15);
        QVERIFY(run.recording.frame(150).sleepers);
        QVERIFY(!run.recording.frame(1).sleepers);
        for (int i = 0; i <= 150; ++i)
            QVERIFY(stateBits(run.recording.frame(i)) ==
                    run.reference[static_cast<std::size_t>(i)]);
        for (long long step : {10LL, 149LL, 45LL}) {
            QVERIFY(run.recording.restore(*run.world, step));
            QVERIFY(stateBits(*run.world) == run.reference[static_cast<std::size_t>(step)]);
            for (long long k = step + 1; k <= 150; ++k) {
                QVERIFY(run.world->step());
                QVERIFY(stateBits(*run.world) == run.reference[static_cast<std::size_t>(k)]);
            }
        }
    }

    // A clock that does not move on starts the recording over.
    void aResetStartsOver() {
        RecordedRun run(scenes::pyramid(3), 20, RunRecording::kDefaultBudgetBytes, 10);
        auto fresh = buildWorld(scenes::pyramid(3)).world;
        run.recording.record(*fresh);
        QCOMPARE(run.recording.frameCount(), 1);
        QCOMPARE(run.recording.keyframeCount(), 1);
    }
};

QTEST_GUILESS_MAIN(TestRunRecording)
#include "tst_run_recording.moc"
