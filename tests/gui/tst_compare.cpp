// Compare from here (CONTRACT §8): from a scrubbed moment the run goes on with another method
// while the recorded run is drawn beside it. Both runs start from the same state bit for bit;
// the ghost on the canvas is the recorded frame for the live run's time (matched by time, and
// held at the recording's last frame past its end); explicit Euler's recorded energy grows by
// the closed form (1 + h²ω²) per step while symplectic Euler's live energy stays within h·ω of
// where both began; the plots carry the recorded run's lines under its method's name; leaving
// compare mode (the action, Reset, Undo, another scene) removes every ghost.

#include "app/desktop/CompareDialog.h"
#include "app/desktop/MainWindow.h"
#include "app/desktop/presenters/ComparePresenter.h"
#include "app/document/Document.h"
#include "app/sim/RunRecording.h"
#include "app/sim/SimulationController.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"
#include "tests/gui/MainWindowTestSupport.h"
#include "tests/support/SceneBuilders.h"
#include "tests/support/StateBits.h"
#include "ui/canvas/SceneView.h"
#include "ui/plots/PlotsPanel.h"

#include <QAction>
#include <QChart>
#include <QChartView>
#include <QDoubleSpinBox>
#include <QStandardPaths>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>
#include <QXYSeries>

#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

using namespace phasebox;
using testing::stateBits;
using namespace phasebox::testing::parts;

namespace {

constexpr double kStiffness = 10.0;  // N/m, on 1 kg: ω = √10 rad/s
constexpr double kDt = 0.01;
constexpr int kRecordedSteps = 100;
constexpr int kCursor = 30;

// A 1 kg particle on a spring to a fixed point, stretched 0.5 m along x and let go, no gravity:
// it moves on the x axis as a harmonic oscillator, E = ½·m·v² + ½·k·(x − L)², with explicit
// Euler.
SceneDesc springScene() {
    SceneDesc scene;
    scene.name = "Spring";
    scene.particles.push_back(testing::particle("m", {1.5, 0.0}, 1.0, {0.0, 0.0}, 0.1));
    scene.springs.push_back(testing::anchorSpring("m", {0.0, 0.0}, kStiffness, 1.0));
    scene.simulation.integrator = "explicit_euler";
    scene.simulation.dt = kDt;
    return scene;
}

double totalOf(const EnergyLedger& e) {
    return e.kinetic + e.potential;
}

// The chart's series named name (nullptr when none).
const QXYSeries* seriesNamed(const QChartView* view, const QString& name) {
    if (!view || !view->chart()) return nullptr;
    for (QAbstractSeries* s : view->chart()->series())
        if (s->name() == name) return static_cast<const QXYSeries*>(s);
    return nullptr;
}

int ghostSeriesCount(const QChartView* view) {
    int n = 0;
    if (view && view->chart())
        for (QAbstractSeries* s : view->chart()->series())
            n += s->name().startsWith(QStringLiteral("recorded: ")) ? 1 : 0;
    return n;
}

}  // namespace

class TestCompare : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void init() {
        window_ = std::make_unique<MainWindow>();
        window_->resize(1024, 700);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
        QVERIFY(window_->document().loadFromDesc(springScene()));
        window_->document().setSelection({QStringLiteral("m")});  // its phase plot: x against vx
        compare_ = window_->findChild<ComparePresenter*>();
        QVERIFY(compare_);
        for (int i = 0; i < kRecordedSteps; ++i) QVERIFY(window_->controller().advance(kDt));
        const RunRecording* recording = window_->controller().runRecording();
        QCOMPARE(recording->frameCount(), kRecordedSteps + 1);
        recorded_.clear();
        for (int i = 0; i < recording->frameCount(); ++i) recorded_.push_back(recording->frame(i));
        QVERIFY(window_->controller().showFrame(kCursor));
    }
    void cleanup() { window_.reset(); }

    void bothRunsStartFromTheRecordedState() {
        MainWindow& w = *window_;
        QVERIFY(w.action("compareFromHere")->isEnabled());
        QVERIFY(!w.action("leaveCompare")->isEnabled());
        // The timeline offers it beside the time, named for screen readers.
        auto* button = w.findChild<QToolButton*>(QStringLiteral("timelineCompare"));
        QVERIFY(button && button->isVisible());
        QCOMPARE(button->defaultAction(), w.action("compareFromHere"));
        QVERIFY(!button->accessibleName().isEmpty());

        SimulationDesc symplectic = w.document().setup().simulation;
        symplectic.integrator = "symplectic_euler";
        QVERIFY(compare_->start(symplectic));
        QVERIFY(compare_->run().isActive());
        QCOMPARE(w.document().world().settings().integrator, std::string("symplectic_euler"));
        QCOMPARE(w.controller().shownFrame(), -1);
        // The live world and the ghost both hold the recorded frame at the cursor, bit for bit.
        QCOMPARE(stateBits(w.document().world()), stateBits(recorded_[kCursor]));
        const World* ghost = canvasOf(w)->ghost();
        QVERIFY(ghost);
        QCOMPARE(stateBits(*ghost), stateBits(recorded_[kCursor]));
        QCOMPARE(button->defaultAction(), w.action("leaveCompare"));
    }

    void theGhostIsTheRecordedRunAndTheEnergiesPart() {
        MainWindow& w = *window_;
        SimulationDesc symplectic = w.document().setup().simulation;
        symplectic.integrator = "symplectic_euler";
        QVERIFY(compare_->start(symplectic));
        const double e0 = totalOf(recorded_[kCursor].ledger);
        const double omega = std::sqrt(kStiffness);
        for (int k = 1; k <= kRecordedSteps - kCursor; ++k) {
            QVERIFY(w.controller().advance(kDt));
            const World* ghost = canvasOf(w)->ghost();
            QVERIFY(ghost);
            // The ghost is the recorded frame of the same time.
            QCOMPARE(ghost->time(), w.document().world().time());
            QCOMPARE(stateBits(*ghost), stateBits(recorded_[kCursor + k]));
            // Explicit Euler on a harmonic oscillator: E_(n+1) = (1 + h²ω²)·E_n exactly.
            const double expected = e0 * std::pow(1.0 + kDt * kDt * omega * omega, k);
            QVERIFY2(std::abs(totalOf(ghost->energy()) - expected) <= 1e-9 * expected,
                     qPrintable(QString::number(totalOf(ghost->energy()) - expected)));
            // Symplectic Euler keeps a modified energy within h·ω/2 of E: E stays within h·ω.
            const double live = totalOf(w.document().world().energy());
            QVERIFY2(std::abs(live - e0) <= kDt * omega * e0, qPrintable(QString::number(live)));
        }
        // 70 steps on, the recorded run has gained (1.001)^70 − 1 = 7.2 %: they have parted.
        const double ghostEnergy = totalOf(canvasOf(w)->ghost()->energy());
        const double liveEnergy = totalOf(w.document().world().energy());
        QVERIFY(ghostEnergy - liveEnergy > 0.03 * e0);

        // The plots: the recorded run's total energy and phase trace under its method's name.
        w.refreshNow();
        const QString name = QStringLiteral("recorded: Explicit Euler");
        const QXYSeries* energy = seriesNamed(plotsPanelOf(w)->energyView(), name);
        QVERIFY(energy);
        QVERIFY(energy->pen().style() == Qt::DashLine);
        QCOMPARE(energy->count(), kRecordedSteps - kCursor + 1);
        for (int i = 0; i < energy->count(); ++i) {
            QCOMPARE(energy->at(i).x(), recorded_[kCursor + i].time);
            QCOMPARE(energy->at(i).y(), totalOf(recorded_[kCursor + i].ledger));
        }
        const QXYSeries* phase = seriesNamed(plotsPanelOf(w)->phaseView(), name);
        QVERIFY(phase);
        QCOMPARE(phase->count(), kRecordedSteps - kCursor + 1);
        for (int i = 0; i < phase->count(); ++i) {
            QCOMPARE(phase->at(i).x(), recorded_[kCursor + i].q[0]);
            QCOMPARE(phase->at(i).y(), recorded_[kCursor + i].u[0]);
        }

        // Past the recording's end the ghost stays at its last frame, and says so.
        QVERIFY(w.controller().advance(0.2));
        QVERIFY(w.document().world().time() > recorded_.back().time);
        QCOMPARE(stateBits(*canvasOf(w)->ghost()), stateBits(recorded_.back()));
        QVERIFY(canvasOf(w)->ghostCaption().contains(QStringLiteral("ended")));

        // Leaving compare mode removes the ghost from the canvas and the plots.
        w.action("leaveCompare")->trigger();
        w.refreshNow();
        QVERIFY(!compare_->run().isActive());
        QVERIFY(!canvasOf(w)->ghost());
        QCOMPARE(ghostSeriesCount(plotsPanelOf(w)->energyView()), 0);
        QCOMPARE(ghostSeriesCount(plotsPanelOf(w)->phaseView()), 0);
    }

    // Another dt: the ghost is matched by time, not by frame index.
    void anotherDtIsMatchedByTime() {
        MainWindow& w = *window_;
        SimulationDesc half = w.document().setup().simulation;
        half.dt = 0.5 * kDt;
        QVERIFY(compare_->start(half));
        QCOMPARE(stateBits(w.document().world()), stateBits(recorded_[kCursor]));
        for (int k = 1; k <= 40; ++k) {
            QVERIFY(w.controller().advance(0.5 * kDt));
            const double t = w.document().world().time();
            // The last recorded frame at or before t (two half steps sum to a whole with
            // another rounding than one step: within 1e-9 s counts as the same time).
            int index = 0;
            for (int i = 0; i < static_cast<int>(recorded_.size()); ++i)
                if (recorded_[i].time <= t + 1e-9) index = i;
            QCOMPARE(index, kCursor + k / 2);
            QCOMPARE(stateBits(*canvasOf(w)->ghost()), stateBits(recorded_[index]));
        }
        // The legend names what differs: the recorded method and its dt.
        w.refreshNow();
        QVERIFY(seriesNamed(plotsPanelOf(w)->energyView(),
                            QStringLiteral("recorded: Explicit Euler, dt 0.01 s")));
    }

    void resetUndoAndAnotherSceneLeaveCompare() {
        MainWindow& w = *window_;
        SimulationDesc symplectic = w.document().setup().simulation;
        symplectic.integrator = "symplectic_euler";
        const auto expectGone = [&w, this] {
            w.refreshNow();
            QVERIFY(!compare_->run().isActive());
            QVERIFY(!canvasOf(w)->ghost());
            QCOMPARE(ghostSeriesCount(plotsPanelOf(w)->energyView()), 0);
            QCOMPARE(ghostSeriesCount(plotsPanelOf(w)->phaseView()), 0);
        };
        // Undo: the comparison (rewind and switch of method) is one step; undoing it brings the
        // recorded run back, whole, and the ghost goes.
        const int commands = w.document().undoStack()->count();
        QVERIFY(compare_->start(symplectic));
        QCOMPARE(w.document().undoStack()->count(), commands + 1);
        QVERIFY(w.controller().advance(0.1));
        w.document().undoStack()->undo();
        expectGone();
        QCOMPARE(w.document().world().settings().integrator, std::string("explicit_euler"));
        QCOMPARE(stateBits(w.document().world()), stateBits(recorded_.back()));

        // Reset.
        QVERIFY(w.controller().showFrame(kCursor));
        QVERIFY(compare_->start(symplectic));
        QVERIFY(w.controller().advance(0.1));
        w.action("reset")->trigger();
        expectGone();

        // Another scene.
        for (int i = 0; i < 50; ++i) QVERIFY(w.controller().advance(kDt));
        QVERIFY(w.controller().showFrame(10));
        QVERIFY(compare_->start(symplectic));
        QVERIFY(w.document().loadFromDesc(scenes::pyramid(3)));
        expectGone();
        QVERIFY(!w.action("compareFromHere")->isEnabled());
    }

    // Going back before the comparison's start and playing on from there drops the comparison
    // run, and with it the ghost; scrubbing to that moment only hides the canvas's ghost.
    void playFromBeforeTheStartLeavesCompare() {
        MainWindow& w = *window_;
        SimulationDesc symplectic = w.document().setup().simulation;
        symplectic.integrator = "symplectic_euler";
        QVERIFY(compare_->start(symplectic));
        QVERIFY(w.controller().advance(0.2));
        QVERIFY(w.controller().showFrame(10));
        w.refreshNow();
        QVERIFY(compare_->run().isActive());
        QVERIFY(!canvasOf(w)->ghost());
        QCOMPARE(ghostSeriesCount(plotsPanelOf(w)->energyView()), 0);  // cut at the cursor
        QVERIFY(w.controller().advance(kDt));
        w.refreshNow();
        QVERIFY(!compare_->run().isActive());
        QVERIFY(!canvasOf(w)->ghost());
    }

    // The dialog proposes the method after the recorded one and keeps the recorded dt exactly
    // when its field (which rounds) is left alone.
    void theDialogProposesTheNextMethod() {
        MainWindow& w = *window_;
        SimulationDesc scene = w.document().setup().simulation;
        SimulationSettings recorded;
        recorded.integrator = "explicit_euler";
        recorded.dt = 1.0 / 60.0;
        recorded.contactModel = ContactModel::Penalty;
        CompareDialog dialog(scene, recorded, 0.5);
        const SimulationDesc chosen = dialog.settings();
        QCOMPARE(chosen.integrator, std::string("symplectic_euler"));
        QCOMPARE(chosen.dt, 1.0 / 60.0);
        QCOMPARE(chosen.contactModel, ContactModel::Penalty);
        QCOMPARE(chosen.substeps, scene.substeps);
        auto* dt = dialog.findChild<QDoubleSpinBox*>(QStringLiteral("compareDt"));
        QVERIFY(dt);
        dt->setValue(0.005);
        QCOMPARE(dialog.settings().dt, 0.005);
        // The menu entry opens it, named and reachable from the Simulation menu.
        QVERIFY(!w.action("compareFromHere")->text().isEmpty());
        w.action("compareFromHere")->trigger();
        auto* shown = w.findChild<CompareDialog*>(QStringLiteral("compareDialog"));
        QVERIFY(shown && shown->isVisible());
        shown->accept();
        QCoreApplication::processEvents();
        QVERIFY(compare_->run().isActive());
        QCOMPARE(w.document().world().settings().integrator, std::string("symplectic_euler"));
        QCOMPARE(stateBits(w.document().world()), stateBits(recorded_[kCursor]));
    }

    // At the live end there is no recorded run ahead to compare with.
    void refusedWithoutAnEarlierMoment() {
        MainWindow& w = *window_;
        QVERIFY(w.controller().showFrame(kRecordedSteps));  // back at the live end
        QVERIFY(!w.action("compareFromHere")->isEnabled());
        SimulationDesc symplectic = w.document().setup().simulation;
        symplectic.integrator = "symplectic_euler";
        const auto before = stateBits(w.document().world());
        QVERIFY(!compare_->start(symplectic));
        QCOMPARE(stateBits(w.document().world()), before);
        QVERIFY(!canvasOf(w)->ghost());
    }

private:
    std::unique_ptr<MainWindow> window_;
    ComparePresenter* compare_ = nullptr;
    std::vector<FrameState> recorded_;
};

QTEST_MAIN(TestCompare)
#include "tst_compare.moc"
