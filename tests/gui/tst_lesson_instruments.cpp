// A lesson keeps its instruments (issue #37, CONTRACT §7): a teacher sets up graphs, a period
// timer, a table column, a ruler, a protractor, the free-body view, a zoomed view and the
// error plot, saves, and a fresh window opening the file shows every one of them and, run for
// the same time, reads the same numbers to the last bit. New brings none of them back. Every
// built-in lesson opens from File → Lessons with the instruments its file names, the dock raised
// on them, and runs: a lesson with a period timer reads a period after 5 s.

#include "GuiTestSupport.h"
#include "MainWindowTestSupport.h"
#include "app/desktop/MainWindow.h"
#include "app/desktop/MeasureTools.h"
#include "app/desktop/presenters/InstrumentsPresenter.h"
#include "app/document/Document.h"
#include "app/io/SceneIO.h"
#include "app/sim/ProbeRecorder.h"
#include "app/sim/SimulationController.h"
#include "ui/canvas/SceneView.h"
#include "ui/instruments/GraphsView.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/instruments/ProbePicker.h"
#include "ui/instruments/TimerView.h"
#include "ui/plots/PlotsPanel.h"

#include <QDockWidget>
#include <QFile>
#include <QMenu>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace phasebox;
using namespace phasebox::testing::parts;
using phasebox::testing::visibleParticle;

namespace {

// A bob on a 1 m rod from the origin, released 30° out.
SceneDesc pendulum() {
    SceneDesc scene;
    scene.name = "Pendulum lesson";
    scene.effects.gravity = GravityDesc{};
    const double theta = 30.0 * M_PI / 180.0;
    scene.particles.push_back(visibleParticle("bob", {std::sin(theta), -std::cos(theta)}));
    JointDesc rod;
    rod.id = "rod";
    rod.type = JointType::Rod;
    rod.a = "bob";
    rod.anchor = Point2{0.0, 0.0};
    scene.joints.push_back(rod);
    return scene;
}

struct Window {
    MainWindow w;
    Window() {
        w.resize(1400, 900);
        w.show();
    }
    InstrumentsPresenter& instruments() { return *instrumentsOf(w); }
    MeasureTools& measure() { return *measureToolsOf(w); }
};

struct Readings {
    double period = 0.0, ruler = 0.0, protractor = 0.0, lastTotal = 0.0;
};

Readings run(Window& window) {
    window.w.controller().advance(4.0);
    window.w.refreshNow();
    Readings r;
    r.period = instrumentsPanelOf(window.w)->timer()->period().value_or(-1.0);
    r.ruler = window.measure().rulerLength(0);
    r.protractor = window.measure().protractorDegrees(0);
    const ProbeRecorder& probes = probeRecorderOf(window.w);
    const int total = probes.indexOf(QStringLiteral("system.total"));
    r.lastTotal = total >= 0 ? probes.values(total).back() : -1.0;
    return r;
}

}  // namespace

class TestLessonInstruments : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void savedInstrumentsReopenWithTheSameReadings() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("pendulum.phasebox.json"));
        Readings before;
        {
            Window teacher;
            QString error;
            QVERIFY2(teacher.w.document().loadFromDesc(pendulum(), {}, &error), qPrintable(error));
            QVERIFY(teacher.instruments().plotProbe(QStringLiteral("bob.x")));
            QVERIFY(
                teacher.instruments().plotProbe(QStringLiteral("bob.vx"), QStringLiteral("bob.x")));
            QVERIFY(teacher.instruments().timeProbe(QStringLiteral("bob.x")));
            QVERIFY(teacher.instruments().addTableColumn(QStringLiteral("system.total")));
            QVERIFY(teacher.measure().addRuler(QStringLiteral("bob,0:0"), &error));
            QVERIFY(teacher.measure().addProtractor(QStringLiteral("0:-1,0:0,bob"), &error));
            teacher.w.document().setSelection({QStringLiteral("bob")});
            teacher.measure().setFreeBodyShown(true);
            canvasOf(teacher.w)->showWidth(QPointF(0.25, -0.5), 3.0);
            plotsPanelOf(teacher.w)->showLowerPlot(ui::PlotsPanel::Plot::Error);
            QVERIFY2(teacher.w.saveFile(path, &error), qPrintable(error));
            before = run(teacher);
        }
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        QVERIFY2(text.contains("\"version\": 2") && text.contains("\"instruments\""),
                 text.constData());

        Window student;
        QVERIFY(student.w.openFile(path, true));
        ui::GraphsView* graphs = instrumentsPanelOf(student.w)->graphs();
        QCOMPARE(graphs->count(), 2);
        QCOMPARE(graphs->graph(0)->yPicker()->probe(), QStringLiteral("bob.x"));
        QCOMPARE(graphs->graph(1)->yPicker()->probe(), QStringLiteral("bob.vx"));
        QCOMPARE(graphs->graph(1)->xPicker()->probe(), QStringLiteral("bob.x"));
        QCOMPARE(instrumentsPanelOf(student.w)->timer()->picker()->probe(),
                 QStringLiteral("bob.x"));
        QVERIFY(probeRecorderOf(student.w).indexOf(QStringLiteral("system.total")) >= 0);
        QCOMPARE(instrumentsPanelOf(student.w)->currentTab(), ui::InstrumentsPanel::Tab::Graphs);
        QCOMPARE(student.measure().rulerCount(), 1);
        QCOMPARE(student.measure().protractorCount(), 1);
        QVERIFY(student.measure().freeBodyShown());
        QCOMPARE(student.w.document().selection(), QStringList{QStringLiteral("bob")});
        QVERIFY(std::abs(canvasOf(student.w)->shownWidth() - 3.0) < 1e-9);
        QVERIFY(std::abs(canvasOf(student.w)->view().centre().x() - 0.25) < 1e-12);
        QCOMPARE(plotsPanelOf(student.w)->lowerPlot(), ui::PlotsPanel::Plot::Error);

        // The same run reads the same numbers: the timer's period, the ruler (the rod's 1 m),
        // the protractor (the swing, at most 30°) and the energy in the table.
        const Readings after = run(student);
        QCOMPARE(after.period, before.period);
        QVERIFY(after.period > 0.0);
        QCOMPARE(after.ruler, before.ruler);
        QVERIFY(std::abs(after.ruler - 1.0) < 1e-6);
        QCOMPARE(after.protractor, before.protractor);
        QVERIFY(after.protractor <= 30.0 + 1e-6);
        QCOMPARE(after.lastTotal, before.lastTotal);

        // Saving again writes the same instruments.
        const QString again = QDir(dir.path()).filePath(QStringLiteral("again.phasebox.json"));
        QString error;
        QVERIFY2(student.w.saveFile(again, &error), qPrintable(error));
        QFile second(again);
        QVERIFY(second.open(QIODevice::ReadOnly));
        const QByteArray secondText = second.readAll();
        const auto instrumentsOf = [](const QByteArray& t) {
            return t.mid(t.indexOf("\"instruments\""));
        };
        QCOMPARE(instrumentsOf(secondText), instrumentsOf(text));

        // New: none of the lesson's instruments stay.
        student.w.action(QStringLiteral("new"))->trigger();
        QCOMPARE(graphs->count(), 1);
        QVERIFY(graphs->graph(0)->yPicker()->probe().isEmpty());
        QCOMPARE(student.measure().rulerCount(), 0);
        QCOMPARE(student.measure().protractorCount(), 0);
        QVERIFY(!student.measure().freeBodyShown());
        QCOMPARE(probeRecorderOf(student.w).probeCount(), 0);
        QVERIFY(SceneIO::serialize(student.w.document().sceneToSave()).indexOf("instruments") < 0);
    }
    // File → Lessons: each lesson opens with its notes and the instruments its file names (the
    // graphs, the timed probe, the probes they read recorded), the Instruments dock shown on the
    // tab the lesson measures with, and runs 5 s; a timed swing has a period by then.
    void lessonsMenuOpensEveryLessonWithItsInstruments() {
        Window window;
        MainWindow& w = window.w;
        auto* menu = w.findChild<QMenu*>(QStringLiteral("lessonsMenu"));
        QVERIFY(menu);
        auto* dock = w.findChild<QDockWidget*>(QStringLiteral("instrumentsDock"));
        QVERIFY(dock);
        const QList<QAction*> actions = menu->actions();
        QCOMPARE(actions.size(), 12);
        int timed = 0;
        for (QAction* a : actions) {
            dock->hide();
            a->trigger();
            const QString path = a->data().toString();
            QCOMPARE(w.document().filePath(), path);
            QCOMPARE(QString::fromStdString(w.document().setup().name), a->text());
            const SceneLoadResult loaded = SceneIO::load(path);
            QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
            const InstrumentsDesc& in = loaded.scene->instruments;
            ui::InstrumentsPanel* panel = instrumentsPanelOf(w);
            ui::GraphsView* graphs = panel->graphs();
            if (in.graphs.empty()) {
                QVERIFY(graphs->graph(0)->yPicker()->probe().isEmpty());
            } else {
                QCOMPARE(graphs->count(), static_cast<int>(in.graphs.size()));
                for (int i = 0; i < graphs->count(); ++i) {
                    QCOMPARE(graphs->graph(i)->yPicker()->probe(),
                             QString::fromStdString(in.graphs[std::size_t(i)].y));
                    QCOMPARE(graphs->graph(i)->xPicker()->probe(),
                             QString::fromStdString(in.graphs[std::size_t(i)].x));
                }
            }
            QCOMPARE(panel->timer()->picker()->probe(),
                     in.timers.empty() ? QString() : QString::fromStdString(in.timers.front()));
            // The window records the table's, the graphs' and the timed probe (the first
            // timer; the others are kept for Save).
            std::vector<std::string> recorded = in.probes;
            for (const GraphDesc& g : in.graphs) recorded.insert(recorded.end(), {g.y, g.x});
            if (!in.timers.empty()) recorded.push_back(in.timers.front());
            for (const std::string& probe : recorded)
                QVERIFY2(
                    probe.empty() || probeRecorderOf(w).indexOf(QString::fromStdString(probe)) >= 0,
                    probe.c_str());
            QCOMPARE(dock->isVisible(), !in.graphs.empty() || !in.timers.empty() || in.stopwatch ||
                                            !in.probes.empty());
            if (!in.graphs.empty())
                QCOMPARE(panel->currentTab(), ui::InstrumentsPanel::Tab::Graphs);
            else if (!in.timers.empty())
                QCOMPARE(panel->currentTab(), ui::InstrumentsPanel::Tab::Timer);
            else if (!in.probes.empty())
                QCOMPARE(panel->currentTab(), ui::InstrumentsPanel::Tab::Table);
            QVERIFY2(w.controller().advance(5.0), qPrintable(path));
            w.refreshNow();
            if (!in.timers.empty()) {
                const std::optional<double> period = panel->timer()->period();
                QVERIFY2(period && *period > 0.0, qPrintable(path));
                ++timed;
            }
        }
        QCOMPARE(timed, 2);  // the simple pendulum and the bead on the hoop
    }
};

QTEST_MAIN(TestLessonInstruments)
#include "tst_lesson_instruments.moc"
