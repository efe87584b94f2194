// Properties while it runs (issue #37): at the setup the panel shows the setup, labelled so;
// once the clock has left 0 it shows the live state of the run (the numbers the canvas draws),
// labelled live with the time (at an earlier moment the timeline shows, that moment's state,
// labelled recorded with its time), and Reset brings the setup back. A rigid body's every field
// fits the dock of a window at its first size, and at 1024 x 700 every page of the
// Instruments dock fits its width (nothing cut at the right edge).

#include "MainWindowTestSupport.h"
#include "app/desktop/MainWindow.h"
#include "app/document/Document.h"
#include "app/sim/SimulationController.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneView.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/panels/PropertiesPanel.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QStandardPaths>
#include <QTest>

#include <cmath>

using namespace phasebox;
using namespace phasebox::testing::parts;

namespace {

// A box released 1 m above the ground (its bottom at y = -1): it falls, bounces and rests.
SceneDesc droppedBox() {
    SceneDesc scene;
    scene.name = "A box on the floor";
    scene.effects.gravity = GravityDesc{};
    BoxDesc box;
    box.id = "crate";
    box.position = {0.0, 0.3};
    box.size = {1.0, 0.6};
    scene.boxes.push_back(box);
    PlaneDesc ground;
    ground.id = "ground";
    ground.point = {0.0, -2.0};
    scene.planes.push_back(ground);
    return scene;
}

double shown(ui::PropertiesPanel* panel, const char* key) {
    auto* spin = qobject_cast<QDoubleSpinBox*>(panel->editor(QString::fromLatin1(key)));
    return spin ? spin->value() : std::nan("");
}

}  // namespace

class TestLiveProperties : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void showsTheLiveStateWhileRunningAndTheSetupAtReset() {
        MainWindow w;
        w.resize(1400, 880);
        w.show();
        QString error;
        QVERIFY2(w.document().loadFromDesc(droppedBox(), {}, &error), qPrintable(error));
        w.document().setSelection({QStringLiteral("crate")});
        ui::PropertiesPanel* panel = propertiesPanelOf(w);
        QVERIFY(panel->hasObject());
        QVERIFY(!panel->showsLiveState());
        QVERIFY(panel->stateNote().startsWith(QStringLiteral("Setup")));
        QCOMPARE(shown(panel, "position.y"), 0.3);

        // Running: every frame shows the run's state, not the setup's 0.3 m.
        w.controller().play();
        QVERIFY(QTest::qWaitFor([&] { return w.document().world().time() > 0.2; }, 10000));
        w.controller().pause();
        w.refreshNow();
        const World& world = w.document().world();
        QVERIFY(panel->showsLiveState());
        QVERIFY2(panel->stateNote().contains(
                     QStringLiteral("Live at t = %1 s").arg(world.time(), 0, 'f', 3)),
                 qPrintable(panel->stateNote()));
        QVERIFY(world.bodyPosition(0).y() < 0.25);
        QVERIFY(std::abs(shown(panel, "position.y") - world.bodyPosition(0).y()) < 1e-3);
        QVERIFY(std::abs(shown(panel, "velocity.y") - world.bodyVelocity(0).y()) < 1e-3);

        // At rest on the floor after 3 s: the live y is the resting height, -1.7 m.
        QVERIFY(w.controller().advance(3.0));
        w.refreshNow();
        QVERIFY(std::abs(shown(panel, "position.y") + 1.7) < 2e-3);
        const QString liveNote = panel->stateNote();

        // An earlier moment on the timeline: its state, named as recorded.
        auto* timeline = w.findChild<QSlider*>(QStringLiteral("timelineSlider"));
        QVERIFY(timeline);
        timeline->setValue(timeline->maximum() / 10);
        QVERIFY(world.time() > 0.0 && world.time() < 1.0);
        QVERIFY2(panel->stateNote().startsWith(
                     QStringLiteral("Recorded at t = %1 s").arg(world.time(), 0, 'f', 3)),
                 qPrintable(panel->stateNote()));
        QVERIFY(panel->showsLiveState());
        QVERIFY(std::abs(shown(panel, "position.y") - world.bodyPosition(0).y()) < 1e-3);
        QVERIFY(world.bodyPosition(0).y() > -1.6);  // still falling then
        timeline->setValue(timeline->maximum());
        QCOMPARE(panel->stateNote(), liveNote);
        QVERIFY(std::abs(shown(panel, "position.y") + 1.7) < 2e-3);

        w.action(QStringLiteral("reset"))->trigger();
        w.refreshNow();
        QVERIFY(!panel->showsLiveState());
        QCOMPARE(shown(panel, "position.y"), 0.3);
    }

    void aRigidBodysFieldsFitTheDock() {
        MainWindow w;
        w.resize(1400, 880);
        w.show();
        QString error;
        QVERIFY2(w.document().loadFromDesc(droppedBox(), {}, &error), qPrintable(error));
        w.document().setSelection({QStringLiteral("crate")});
        w.findChild<QDockWidget*>(QStringLiteral("propertiesDock"))->raise();
        QApplication::processEvents();
        auto* scroll = propertiesPanelOf(w)->findChild<QScrollArea*>(QStringLiteral("formScroll"));
        QVERIFY(scroll);
        QVERIFY(propertiesPanelOf(w)->keys().size() >= 12);
        QCOMPARE(scroll->verticalScrollBar()->maximum(), 0);  // nothing hidden below
    }

    // A lesson opened before a small window is first shown (from the command line): the first
    // show's column widths leave the canvas its half of the window.
    void aLessonOpenedBeforeShowingLeavesTheCanvasItsShare() {
        MainWindow w;
        w.resize(1024, 700);
        QVERIFY(w.openFile(QStringLiteral(":/lessons/simple-pendulum.phasebox.json"), true));
        w.show();
        QApplication::processEvents();
        QTest::qWait(50);
        QVERIFY(w.findChild<QDockWidget*>(QStringLiteral("instrumentsDock"))->isVisible());
        QVERIFY2(canvasOf(w)->width() >= 1024 / 2 - 2,
                 qPrintable(QString::number(canvasOf(w)->width())));
    }

    void instrumentsFitASmallWindow() {
        MainWindow w;
        w.resize(1024, 700);
        w.show();
        QVERIFY(w.openFile(QStringLiteral(":/lessons/simple-pendulum.phasebox.json"), true));
        QVERIFY(w.controller().advance(3.0));
        auto* dock = w.findChild<QDockWidget*>(QStringLiteral("instrumentsDock"));
        dock->raise();
        everyInstrumentsPageFits(w, QString());
    }

    // Raised before the window is first shown (`phasebox --probe`) or from the menu after, the
    // instruments' pages fit their dock at 1024 x 700: the canvas takes its share of a small
    // window from the docks down to the pages' width, not below it.
    void instrumentsRaisedFitASmallWindow() {
        for (const bool beforeShowing : {true, false}) {
            MainWindow w;
            w.resize(1024, 700);
            if (!beforeShowing) w.show();
            QVERIFY(w.openFile(QStringLiteral(":/scenes/spring-oscillator.phasebox.json"), true));
            QVERIFY(instrumentsOf(w)->plotProbe(QStringLiteral("light.y")));
            w.show();
            QApplication::processEvents();
            QTest::qWait(50);
            // A second graph, against a probe, once the window is up: the pages' rows widen.
            QVERIFY(instrumentsOf(w)->plotProbe(QStringLiteral("light.vy"),
                                                QStringLiteral("distance(light,heavy)")));
            QVERIFY(w.controller().advance(1.0));
            everyInstrumentsPageFits(w, beforeShowing ? QStringLiteral("before showing, ")
                                                      : QStringLiteral("after showing, "));
            QVERIFY2(canvasOf(w)->width() >= 1024 / 2 - 2,
                     qPrintable(QString::number(canvasOf(w)->width())));
        }
    }

private:
    // Every page of the Instruments dock, shown in turn, fits the dock's width (no horizontal
    // scroll bar); label says where, in a failure's message.
    static void everyInstrumentsPageFits(MainWindow& w, const QString& label) {
        auto* scroll = w.findChild<QScrollArea*>(QStringLiteral("instrumentsScroll"));
        QVERIFY(scroll && scroll->isVisible());
        using Tab = ui::InstrumentsPanel::Tab;
        for (const Tab tab : {Tab::Readouts, Tab::Graphs, Tab::Timer, Tab::Table}) {
            instrumentsPanelOf(w)->showTab(tab);
            w.refreshNow();
            QApplication::processEvents();
            QVERIFY2(scroll->horizontalScrollBar()->maximum() == 0,
                     qPrintable(QStringLiteral("%1tab %2: %3 px wider than the dock")
                                    .arg(label)
                                    .arg(int(tab))
                                    .arg(scroll->horizontalScrollBar()->maximum())));
        }
    }
};

QTEST_MAIN(TestLiveProperties)
#include "tst_live_properties.moc"
