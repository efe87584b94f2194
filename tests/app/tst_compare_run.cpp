// CompareRun, the logic behind Compare from here: it keeps the recorded frames from the shown
// moment on, bit for bit, puts the live world into that moment's state with the new settings as
// one undo step, pairs every later time with the last recorded frame at or before it (held at
// the last one past the end), and gives the recorded run's energy and phase series from those
// frames. It refuses without an earlier moment, changing nothing; a scene that sleeps compares
// from a moment asleep.

#include "app/document/Document.h"
#include "app/sim/CompareRun.h"
#include "app/sim/RunRecording.h"
#include "app/sim/SimulationController.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"
#include "tests/support/SceneBuilders.h"
#include "tests/support/StateBits.h"

#include <QTest>
#include <QUndoStack>

#include <bit>
#include <cstdint>
#include <vector>

using namespace phasebox;
using testing::stateBits;

namespace {

constexpr double kDt = 0.01;

SceneDesc springScene(bool sleep = false) {
    SceneDesc scene;
    scene.name = "Spring";
    scene.particles.push_back(testing::particle("m", {1.5, 0.0}, 1.0, {0.0, 0.0}, 0.1));
    scene.springs.push_back(testing::anchorSpring("m", {0.0, 0.0}, 10.0, 1.0));
    scene.simulation.integrator = "explicit_euler";
    scene.simulation.dt = kDt;
    scene.simulation.sleep = sleep;
    return scene;
}

struct Session {
    Document document;
    SimulationController controller{document};
    RunRecording recording;
    std::vector<FrameState> frames;  // the recorded run, as it was before the comparison

    explicit Session(const SceneDesc& scene, int steps = 100) {
        controller.setRunRecording(&recording);
        document.loadFromDesc(scene);
        for (int i = 0; i < steps; ++i) controller.advance(kDt);
        for (int i = 0; i < recording.frameCount(); ++i) frames.push_back(recording.frame(i));
    }
    SimulationDesc with(const char* integrator) const {
        SimulationDesc s = document.setup().simulation;
        s.integrator = integrator;
        return s;
    }
};

}  // namespace

class TestCompareRun : public QObject {
    Q_OBJECT

private slots:
    void startsFromTheShownFrameWithTheNewSettings() {
        Session s(springScene());
        QCOMPARE(static_cast<int>(s.frames.size()), 101);
        QVERIFY(s.controller.showFrame(30));
        CompareRun run;
        QString why;
        QVERIFY2(run.start(s.controller, s.document, s.with("symplectic_euler"), &why),
                 qPrintable(why));
        QVERIFY(run.isActive());
        QCOMPARE(run.recordedSettings().integrator, std::string("explicit_euler"));
        QCOMPARE(s.document.world().settings().integrator, std::string("symplectic_euler"));
        QCOMPARE(stateBits(s.document.world()), stateBits(s.frames[30]));
        // The ghost's frames are the recording's, from the cursor on.
        QCOMPARE(static_cast<int>(run.frames().size()), 71);
        for (int i = 0; i < 71; ++i)
            QCOMPARE(stateBits(run.frames()[i]), stateBits(s.frames[30 + i]));
        // The new run replaces them in the recording; the whole change is one undo step.
        QCOMPARE(s.recording.frameCount(), 31);
        QCOMPARE(run.undoIndex(), s.document.undoStack()->index());
        s.document.undoStack()->undo();
        QCOMPARE(s.recording.frameCount(), 101);
        QCOMPARE(stateBits(s.document.world()), stateBits(s.frames.back()));
        QCOMPARE(s.document.world().settings().integrator, std::string("explicit_euler"));
    }

    void theGhostIsMatchedByTime() {
        Session s(springScene());
        QVERIFY(s.controller.showFrame(30));
        CompareRun run;
        QVERIFY(run.start(s.controller, s.document, s.with("midpoint"), nullptr));
        QCOMPARE(run.startTime(), s.frames[30].time);
        QCOMPARE(run.endTime(), s.frames[100].time);
        QCOMPARE(run.frameAt(s.frames[29].time), -1);
        QVERIFY(!run.ghostAt(s.frames[29].time));
        for (int i = 30; i <= 100; ++i) {
            QCOMPARE(run.frameAt(s.frames[i].time), i - 30);
            // Half a step later is still that frame; a rounding below the next one too.
            QCOMPARE(run.frameAt(s.frames[i].time + 0.5 * kDt), i - 30);
            if (i < 100) QCOMPARE(run.frameAt(s.frames[i + 1].time - 1e-12), i + 1 - 30);
            const World* ghost = run.ghostAt(s.frames[i].time + 0.5 * kDt);
            QVERIFY(ghost);
            QCOMPARE(stateBits(*ghost), stateBits(s.frames[i]));
        }
        QVERIFY(!run.pastEnd(s.frames[100].time));
        QVERIFY(run.pastEnd(s.frames[100].time + kDt));
        QCOMPARE(stateBits(*run.ghostAt(5.0)), stateBits(s.frames[100]));
        // The recorded run's series come from the same frames.
        const Recorder& series = run.series(QStringLiteral("m"), QStringLiteral("x"));
        QCOMPARE(static_cast<int>(series.energySamples().size()), 71);
        QCOMPARE(static_cast<int>(series.phaseSamples().size()), 71);
        for (int i = 0; i < 71; ++i) {
            const FrameState& f = s.frames[30 + i];
            QCOMPARE(series.energySamples()[i].t, f.time);
            QCOMPARE(series.energySamples()[i].kinetic, f.ledger.kinetic);
            QCOMPARE(series.energySamples()[i].potential, f.ledger.potential);
            QCOMPARE(series.phaseSamples()[i].coordinate, f.q[0]);
            QCOMPARE(series.phaseSamples()[i].velocity, f.u[0]);
        }
        run.end();
        QVERIFY(!run.isActive());
        QVERIFY(!run.ghostAt(s.frames[50].time));
    }

    void refusedWithoutAnEarlierMoment() {
        Session s(springScene());
        const auto before = stateBits(s.document.world());
        const int commands = s.document.undoStack()->count();
        CompareRun run;
        QString why;
        QVERIFY(!run.start(s.controller, s.document, s.with("symplectic_euler"), &why));
        QVERIFY(!why.isEmpty());
        QVERIFY(!run.isActive());
        QCOMPARE(stateBits(s.document.world()), before);
        QCOMPARE(s.document.undoStack()->count(), commands);
    }

    // With sleeping on, a moment when the pile was asleep compares too: the live world starts
    // from every body's state then (the switch of method wakes them) and the ghost shows the
    // recorded frames, sleepers and all.
    void comparesFromAMomentAsleep() {
        SceneDesc scene = scenes::pyramid(3);
        scene.simulation.sleep = true;
        scene.simulation.dt = kDt;
        Session s(scene, 200);
        int shown = -1;
        for (int i = 0; i < static_cast<int>(s.frames.size()) && shown < 0; ++i)
            if (s.frames[static_cast<std::size_t>(i)].sleepers) shown = i + 10;
        QVERIFY2(shown > 0 && shown < 190, "the pyramid did not fall asleep");
        QVERIFY(s.controller.showFrame(shown));
        QCOMPARE(s.document.world().sleepingBodies(), 6);
        std::vector<std::uint64_t> then;
        testing::appendBodyBits(s.document.world(), then, false);
        CompareRun run;
        QString why;
        QVERIFY2(run.start(s.controller, s.document, s.with("velocity_verlet"), &why),
                 qPrintable(why));
        QCOMPARE(s.document.world().sleepingBodies(), 0);  // the switch woke it
        std::vector<std::uint64_t> now;
        testing::appendBodyBits(s.document.world(), now, false);
        QVERIFY(now == then);
        QVERIFY(run.frames().front().sleepers);
        for (std::size_t i = 0; i < run.frames().size(); ++i)
            QCOMPARE(stateBits(run.frames()[i]),
                     stateBits(s.frames[static_cast<std::size_t>(shown) + i]));
    }
};

QTEST_GUILESS_MAIN(TestCompareRun)
#include "tst_compare_run.moc"
