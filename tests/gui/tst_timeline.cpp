// The timeline under the canvas (CONTRACT §8): scrubbing to a recorded time shows the state the
// run had then, bit for bit, in the world the canvas draws, the canvas picture, the status
// readout, the Instruments readouts of the selection (headed as the recorded moment), the plots'
// cursors (energy and phase), the probe graphs' cursors and the data table's row of that time;
// stepping back and then forward frame by frame returns the same frames; Play from an earlier
// moment goes on exactly as the run went on, and drops the later frames as one undoable step (Undo
// brings them back). The contact forces follow the timeline too: at a frame the readouts, probes
// and free body show the forces of the step that ended there, the very values they showed live.
// With sleeping on, frames from before and after a pile fell asleep show as they were, the
// sleepers dimmed.

#include "MainWindowTestSupport.h"
#include "app/desktop/MainWindow.h"
#include "app/document/Document.h"
#include "app/sim/SimulationController.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/FreeBody.h"
#include "physics/world/Probes.h"
#include "physics/world/World.h"
#include "tests/support/StateBits.h"
#include "ui/canvas/SceneView.h"
#include "ui/instruments/GraphsView.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/instruments/ProbeTableView.h"
#include "ui/instruments/ReadoutView.h"
#include "ui/plots/PlotsPanel.h"

#include <QAbstractItemModel>
#include <QAction>
#include <QChart>
#include <QChartView>
#include <QFile>
#include <QItemSelectionModel>
#include <QLabel>
#include <QSlider>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <QXYSeries>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

using namespace phasebox;
using testing::stateBits;
using namespace phasebox::testing::parts;

namespace {

QString statusTime(MainWindow& w) {
    for (const QLabel* l : w.statusBar()->findChildren<QLabel*>())
        if (l->text().startsWith(QStringLiteral("t = "))) return l->text();
    return {};
}

// The x of the energy plot's cursor line, NaN when there is none.
double energyCursor(MainWindow& w) {
    const QChart* chart = plotsPanelOf(w)->energyView()->chart();
    for (QAbstractSeries* s : chart->series())
        if (s->name() == QStringLiteral("cursor")) {
            const auto* line = static_cast<QXYSeries*>(s);
            if (line->count() > 0) return line->at(0).x();
        }
    return std::numeric_limits<double>::quiet_NaN();
}

// The phase plot's cursor dot, NaN when there is none.
QPointF phaseCursor(MainWindow& w) {
    const QChart* chart = plotsPanelOf(w)->phaseView()->chart();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (!chart) return {nan, nan};
    for (QAbstractSeries* s : chart->series())
        if (s->name() == QStringLiteral("cursor")) {
            const auto* dot = static_cast<QXYSeries*>(s);
            if (dot->count() > 0) return dot->at(0);
        }
    return {nan, nan};
}

// What the Instruments dock reads out for the selection.
QStringList readouts(MainWindow& w) {
    const auto* view = w.findChild<ui::ReadoutView*>();
    if (!view) return {};
    QStringList out{view->subject(), view->state()};
    for (const char* label :
         {"position (x, y)", "velocity (vx, vy)", "speed", "angle", "angular velocity ω",
          "kinetic energy", "momentum (px, py)", "angular momentum L", "contact force"})
        out << view->valueText(QString::fromUtf8(label));
    return out;
}

// A box resting on the floor and a smaller one dropped onto it from 0.95 m above its top.
QString writeDropScene(const QTemporaryDir& dir) {
    const QString path = dir.filePath(QStringLiteral("drop.json"));
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    f.write(R"({"format": "phasebox-scene", "version": 2,
        "simulation": {"dt": 0.016666666666666666},
        "effects": {"gravity": {}},
        "planes": [{"id": "ground", "point": [0, 0], "normal": [0, 1]}],
        "boxes": [{"id": "base", "position": [0, 0.5], "size": [1, 1]},
                  {"id": "drop", "position": [0, 2.2], "size": [0.5, 0.5]}]})");
    return path;
}

// The bits of a vector of doubles.
std::vector<std::uint64_t> bitsOf(const std::vector<double>& values) {
    std::vector<std::uint64_t> bits;
    for (double v : values) bits.push_back(std::bit_cast<std::uint64_t>(v));
    return bits;
}

// What a moment shows of the contact forces: the readout's value and text of the selection
// ("drop"), the probes of both boxes, the world's contact force vectors and the free body's
// contact on the dropped box (the Measure tools' free-body view).
struct Forces {
    std::vector<double> values;
    QString text;
    QString error;  // the status bar's local error estimate
};

Forces contactForcesShown(MainWindow& w) {
    w.refreshNow();
    QCoreApplication::processEvents();
    const World& world = w.document().world();
    Forces f;
    const auto* view = w.findChild<ui::ReadoutView*>();
    for (double v : view->values(QStringLiteral("contact force"))) f.values.push_back(v);
    f.text = view->valueText(QStringLiteral("contact force"));
    for (const QLabel* l : w.statusBar()->findChildren<QLabel*>())
        if (l->text().startsWith(QStringLiteral("local error"))) f.error = l->text();
    for (const char* id : {"base", "drop"}) {
        const ProbeParse probe =
            parseProbe(world, std::string("contact_force(") + id + std::string(")"));
        f.values.push_back(probe ? evaluateProbe(world, *probe.probe) : -1.0);
    }
    for (const RigidBody& b : world.rigidBodies()) {
        const Vec2 force = world.contactForce(b.dof);
        f.values.push_back(force.x());
        f.values.push_back(force.y());
    }
    Vec2 contact = Vec2::Zero();
    if (const std::optional<FreeBody> body = freeBodyOf(world, "drop"))
        for (const BodyForce& force : body->forces)
            if (force.source == BodyForce::Source::Contact) contact = force.force;
    f.values.push_back(contact.x());
    f.values.push_back(contact.y());
    return f;
}

struct Moment {
    std::vector<std::uint64_t> bits;
    QImage canvas;
    QString status;
    QStringList readouts;
};

class Run {
public:
    explicit Run(MainWindow& w) : w_(w) {}
    Moment now() {
        w_.refreshNow();
        QCoreApplication::processEvents();
        return {stateBits(w_.document().world()), canvasOf(w_)->grab().toImage(), statusTime(w_),
                readouts(w_)};
    }
    // Steps the run one step at a time, keeping every moment.
    void steps(int n) {
        for (int i = 0; i < n; ++i) {
            QVERIFY(w_.controller().advance(w_.document().world().settings().dt));
            moments.push_back(now());
        }
    }
    std::vector<Moment> moments;

private:
    MainWindow& w_;
};

}  // namespace

class TestTimeline : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void init() {
        window_ = std::make_unique<MainWindow>();
        window_->resize(1024, 700);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
        QVERIFY(window_->document().loadFromDesc(scenes::pyramid(5)));
    }
    void cleanup() { window_.reset(); }

    void scrubShowsTheRecordedMoment() {
        MainWindow& w = *window_;
        // A box of the second row: its phase plot (y against vy) and its readouts.
        w.document().setSelection({QStringLiteral("r1c2")});
        w.action("showInstruments")->trigger();
        QCoreApplication::processEvents();
        int box = -1;
        for (std::size_t i = 0; i < w.document().world().rigidBodies().size(); ++i)
            if (w.document().world().rigidBodies()[i].id == "r1c2") box = static_cast<int>(i);
        QVERIFY(box >= 0);
        Run run(w);
        run.moments.push_back(run.now());
        run.steps(90);
        QVERIFY(run.moments.back().readouts.size() > 2);
        QVERIFY(!run.moments.back().readouts[2].isEmpty());
        auto* slider = w.findChild<QSlider*>(QStringLiteral("timelineSlider"));
        QVERIFY(slider);
        QCOMPARE(slider->maximum(), 90);
        QCOMPARE(slider->value(), 90);
        QVERIFY(std::isnan(energyCursor(w)));
        for (int frame : {37, 3, 88, 0, 61}) {
            slider->setValue(frame);  // as a drag does
            const Moment shown = run.now();
            const Moment& then = run.moments[static_cast<std::size_t>(frame)];
            QVERIFY2(shown.bits == then.bits, qPrintable(QStringLiteral("frame %1").arg(frame)));
            QCOMPARE(shown.status, then.status);
            // The same values; the heading names the recorded moment instead of the live run.
            QCOMPARE(shown.readouts.mid(2), then.readouts.mid(2));
            QCOMPARE(shown.readouts[0], then.readouts[0]);
            QCOMPARE(
                shown.readouts[1],
                QStringLiteral("recorded, t = %1 s").arg(w.document().world().time(), 0, 'f', 3));
            const World& world = w.document().world();
            QCOMPARE(phaseCursor(w),
                     QPointF(world.bodyPosition(box).y(), world.bodyVelocity(box).y()));
            QVERIFY2(shown.canvas == then.canvas,
                     qPrintable(QStringLiteral("canvas at frame %1").arg(frame)));
            QCOMPARE(energyCursor(w), w.document().world().time());
            QCOMPARE(w.controller().shownFrame(), frame);
        }
        // The live end again: the run's state, no cursor.
        slider->setValue(90);
        const Moment live = run.now();
        QVERIFY(live.bits == run.moments.back().bits);
        QCOMPARE(live.readouts, run.moments.back().readouts);
        QVERIFY(live.readouts[1].startsWith(QStringLiteral("live, t = ")));
        QCOMPARE(w.controller().shownFrame(), -1);
        QVERIFY(std::isnan(energyCursor(w)));
    }

    // The Instruments dock follows the timeline: a graph against time marks the shown time, a
    // graph against a probe the probes' values then, the data table makes the row of that time
    // current with the values the live run showed at that step, and the readouts name the
    // recorded moment; back at the live end none of the marks remain and the readouts say
    // "live". The dock's shown tab follows a scrub at once, the others when shown.
    void instrumentsFollowTheTimeline() {
        MainWindow& w = *window_;
        w.document().setSelection({QStringLiteral("r1c2")});
        w.action("showInstruments")->trigger();
        InstrumentsPresenter* instruments = instrumentsOf(w);
        QVERIFY(instruments->plotProbe(QStringLiteral("r1c2.y")));
        QVERIFY(instruments->plotProbe(QStringLiteral("r1c2.vy"), QStringLiteral("r1c2.y")));
        ui::InstrumentsPanel* panel = instrumentsPanelOf(w);
        ui::ProbeGraphView* byTime = panel->graphs()->graph(0);
        ui::ProbeGraphView* curve = panel->graphs()->graph(1);
        const ProbeRecorder& probes = probeRecorderOf(w);
        const int y = probes.indexOf(QStringLiteral("r1c2.y")) + 1;  // table columns: t first
        const int vy = probes.indexOf(QStringLiteral("r1c2.vy")) + 1;
        QVERIFY(y > 0 && vy > 0);
        const ui::ProbeTableView* table = panel->table();
        // What the table showed live at each step: its newest row, every column as read.
        const auto newestRow = [&] {
            w.refreshNow();
            const QAbstractItemModel* model = table->table()->model();
            std::vector<double> row;
            for (int c = 0; c < model->columnCount(); ++c)
                row.push_back(model->index(model->rowCount() - 1, c).data(Qt::UserRole).toDouble());
            return row;
        };
        std::vector<std::vector<double>> live{newestRow()};
        constexpr int kSteps = 60;
        for (int i = 0; i < kSteps; ++i) {
            QVERIFY(w.controller().advance(w.document().world().settings().dt));
            live.push_back(newestRow());
            QVERIFY(byTime->cursor().isEmpty() && curve->cursor().isEmpty());
            QCOMPARE(table->shownRow(), -1);
        }
        QCOMPARE(table->table()->model()->rowCount(), kSteps + 1);
        QCOMPARE(live.back()[0], w.document().world().time());
        auto* slider = w.findChild<QSlider*>(QStringLiteral("timelineSlider"));
        const QString shots = qEnvironmentVariable("PHASEBOX_SCREENSHOT_DIR");
        using Tab = ui::InstrumentsPanel::Tab;
        for (int frame : {23, 0, 59, 41}) {
            const std::vector<double>& then = live[static_cast<std::size_t>(frame)];
            panel->showTab(Tab::Graphs);
            slider->setValue(frame);  // no refreshNow: the shown tab follows by itself
            // (QCOMPARE of doubles is fuzzy: these compare bits.)
            const double t = w.document().world().time();
            QVERIFY(bitsOf({t}) == bitsOf({then[0]}));
            const QVector<QPointF> line = byTime->cursor(), dot = curve->cursor();
            QCOMPARE(line.size(), 2);
            QVERIFY(bitsOf({line[0].x(), line[1].x()}) == bitsOf({t, t}));
            QCOMPARE(dot.size(), 1);
            QVERIFY(bitsOf({dot[0].x(), dot[0].y()}) == bitsOf({then[y], then[vy]}));
            if (!shots.isEmpty()) {  // a picture to look at, once the layout has settled
                QCoreApplication::processEvents();
                w.grab().save(QStringLiteral("%1/timeline-graphs-%2.png").arg(shots).arg(frame));
            }
            panel->showTab(Tab::Table);
            const int row = table->table()->currentIndex().row();
            QCOMPARE(row, frame);
            QCOMPARE(table->shownRow(), frame);
            QVERIFY(table->table()->selectionModel()->isRowSelected(row));
            const QAbstractItemModel* model = table->table()->model();
            std::vector<double> shown;
            for (int c = 0; c < model->columnCount(); ++c)
                shown.push_back(model->index(row, c).data(Qt::UserRole).toDouble());
            QVERIFY2(bitsOf(shown) == bitsOf(then),
                     qPrintable(QStringLiteral("table row at frame %1").arg(frame)));
            if (!shots.isEmpty()) {  // a picture to look at, once the layout has settled
                QCoreApplication::processEvents();
                w.grab().save(QStringLiteral("%1/timeline-table-%2.png").arg(shots).arg(frame));
            }
            panel->showTab(Tab::Readouts);
            QCOMPARE(panel->readouts()->state(),
                     QStringLiteral("recorded, t = %1 s").arg(then[0], 0, 'f', 3));
            if (!shots.isEmpty()) {
                QCoreApplication::processEvents();
                w.grab().save(QStringLiteral("%1/timeline-readouts-%2.png").arg(shots).arg(frame));
            }
        }
        // The live end: no cursor, no row held, the live heading.
        slider->setValue(kSteps);
        QCOMPARE(w.controller().shownFrame(), -1);
        QCOMPARE(panel->readouts()->state(),
                 QStringLiteral("live, t = %1 s").arg(live.back()[0], 0, 'f', 2));
        panel->showTab(Tab::Graphs);
        QVERIFY(byTime->cursor().isEmpty());
        QVERIFY(curve->cursor().isEmpty());
        QVERIFY(byTime->pointCount() > kSteps / 2);
        panel->showTab(Tab::Table);
        QCOMPARE(table->shownRow(), -1);
        QVERIFY(!table->table()->selectionModel()->hasSelection());
    }

    // With sleeping on, the layout of the state changes as the pile falls asleep: frames from
    // either side show as they were, every body's state bit for bit and the canvas picture the
    // same (the sleepers dimmed where they slept).
    void scrubAcrossFallingAsleep() {
        MainWindow& w = *window_;
        SceneDesc scene = scenes::pyramid(5);
        scene.simulation.sleep = true;
        QVERIFY(w.document().loadFromDesc(scene));
        const auto bodies = [&w] {
            std::vector<std::uint64_t> bits;
            testing::appendBodyBits(w.document().world(), bits);
            return bits;
        };
        Run run(w);
        run.moments.push_back(run.now());
        std::vector<std::vector<std::uint64_t>> states{bodies()};
        int asleepAt = -1;
        constexpr int kSteps = 150, kBoxes = 15;
        for (int i = 1; i <= kSteps; ++i) {
            run.steps(1);
            states.push_back(bodies());
            if (asleepAt < 0 && w.document().world().sleepingBodies() == kBoxes) asleepAt = i;
        }
        QVERIFY2(asleepAt > 0 && asleepAt < kSteps - 10, "the pyramid did not fall asleep");
        auto* slider = w.findChild<QSlider*>(QStringLiteral("timelineSlider"));
        QVERIFY(slider);
        for (int frame : {asleepAt + 5, 3, asleepAt - 1, kSteps, asleepAt, 0}) {
            slider->setValue(frame);
            const Moment shown = run.now();
            const auto index = static_cast<std::size_t>(frame);
            QVERIFY2(shown.bits == run.moments[index].bits,
                     qPrintable(QStringLiteral("frame %1").arg(frame)));
            QVERIFY(bodies() == states[index]);
            QCOMPARE(w.document().world().sleepingBodies(), frame >= asleepAt ? kBoxes : 0);
            QVERIFY2(shown.canvas == run.moments[index].canvas,
                     qPrintable(QStringLiteral("canvas at frame %1").arg(frame)));
        }
        // Asleep the boxes are drawn dimmed: the picture is not the one of the moment before.
        QVERIFY(run.moments[static_cast<std::size_t>(asleepAt)].canvas !=
                run.moments[static_cast<std::size_t>(asleepAt - 1)].canvas);
    }

    void stepBackThenForwardReturnsTheSameFrames() {
        MainWindow& w = *window_;
        Run run(w);
        run.moments.push_back(run.now());
        run.steps(40);
        w.action("jumpToStart")->trigger();
        QVERIFY(run.now().bits == run.moments[0].bits);
        w.findChild<QSlider*>(QStringLiteral("timelineSlider"))->setValue(30);
        for (int k = 1; k <= 6; ++k) {
            w.action("frameBack")->trigger();
            QVERIFY(run.now().bits == run.moments[static_cast<std::size_t>(30 - k)].bits);
        }
        for (int k = 1; k <= 6; ++k) {
            w.action("frameForward")->trigger();
            QVERIFY(run.now().bits == run.moments[static_cast<std::size_t>(24 + k)].bits);
        }
        QCOMPARE(w.controller().shownFrame(), 30);
    }

    void playFromAnEarlierMomentIsOneUndoableStep() {
        MainWindow& w = *window_;
        Run run(w);
        run.moments.push_back(run.now());
        run.steps(150);  // keyframes every 120 steps: the resume below re-simulates from one
        const int commands = w.document().undoStack()->count();
        w.findChild<QSlider*>(QStringLiteral("timelineSlider"))->setValue(130);
        w.controller().singleStep();
        // The run went on from frame 130 exactly as it did the first time.
        QVERIFY(run.now().bits == run.moments[131].bits);
        QCOMPARE(w.controller().shownFrame(), -1);
        auto* slider = w.findChild<QSlider*>(QStringLiteral("timelineSlider"));
        QCOMPARE(slider->maximum(), 131);
        QCOMPARE(w.document().undoStack()->count(), commands + 1);
        w.document().undoStack()->undo();
        QCOMPARE(slider->maximum(), 150);
        QVERIFY(run.now().bits == run.moments[150].bits);
        w.document().undoStack()->redo();
        QCOMPARE(slider->maximum(), 131);
        QVERIFY(run.now().bits == run.moments[131].bits);
    }

    // A box dropped onto a box at rest: scrubbed to before the impact, to the impact and around
    // it, every contact force shown is the one shown live at that step, bit for bit, and so is
    // each step back and forward.
    void contactForcesFollowTheTimeline() {
        MainWindow& w = *window_;
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QVERIFY(w.openFile(writeDropScene(dir), true));
        w.document().setSelection({QStringLiteral("drop")});
        w.action("showInstruments")->trigger();
        const double dt = w.document().world().settings().dt;
        std::vector<Forces> live{contactForcesShown(w)};
        constexpr int kSteps = 60;
        for (int i = 0; i < kSteps; ++i) {
            QVERIFY(w.controller().advance(dt));
            live.push_back(contactForcesShown(w));
        }
        // The impact: the first step with a contact force on the dropped box (values[2]: its
        // probe). Before it the box falls free and the one below rests on the floor.
        int impact = -1;
        for (int k = 0; k <= kSteps && impact < 0; ++k)
            if (live[static_cast<std::size_t>(k)].values[2] > 0.0) impact = k;
        QVERIFY2(impact > 5 && impact < kSteps - 5, qPrintable(QString::number(impact)));
        const Forces& before = live[static_cast<std::size_t>(impact - 1)];
        QCOMPARE(before.values[2], 0.0);
        QVERIFY(before.values[1] > 0.0);
        // The impact's force on the dropped box is far above its weight (an impulse over dt).
        double dropWeight = 0.0;
        for (const RigidBody& b : w.document().world().rigidBodies())
            if (b.id == "drop") dropWeight = b.mass * 9.81;
        QVERIFY(dropWeight > 0.0);
        QVERIFY(live[static_cast<std::size_t>(impact)].values[2] > dropWeight);
        QVERIFY(!live.back().error.isEmpty());  // an estimate every step at dt 1/60
        QVERIFY(effectsPanelOf(w)->costNote().isEmpty());

        auto* slider = w.findChild<QSlider*>(QStringLiteral("timelineSlider"));
        QCOMPARE(slider->maximum(), kSteps);
        const auto same = [&](int frame) {
            const Forces shown = contactForcesShown(w);
            const Forces& then = live[static_cast<std::size_t>(frame)];
            return bitsOf(shown.values) == bitsOf(then.values) && shown.text == then.text &&
                   shown.error == then.error && w.controller().shownFrame() == frame;
        };
        for (int frame : {impact - 1, impact, 0, impact + 1, 3, impact - 1, kSteps - 1}) {
            slider->setValue(frame);
            QVERIFY2(same(frame), qPrintable(QStringLiteral("frame %1").arg(frame)));
        }
        // The step costs are the run's, and say so: a frame keeps no timing.
        QVERIFY(!effectsPanelOf(w)->costNote().isEmpty());
        slider->setValue(impact + 3);
        for (int k = 1; k <= 6; ++k) {
            w.action("frameBack")->trigger();
            QVERIFY2(same(impact + 3 - k), qPrintable(QStringLiteral("back %1").arg(k)));
        }
        for (int k = 1; k <= 6; ++k) {
            w.action("frameForward")->trigger();
            QVERIFY2(same(impact - 3 + k), qPrintable(QStringLiteral("forward %1").arg(k)));
        }
        // The live end again.
        slider->setValue(kSteps);
        QCOMPARE(w.controller().shownFrame(), -1);
        QVERIFY(bitsOf(contactForcesShown(w).values) ==
                bitsOf(live[static_cast<std::size_t>(kSteps)].values));
        QVERIFY(effectsPanelOf(w)->costNote().isEmpty());
    }

    // The timeline fits under the canvas in a small window and shows the recording's memory.
    void fitsAndShowsItsBudget() {
        MainWindow& w = *window_;
        auto* timeline = w.findChild<QWidget*>(QStringLiteral("timeline"));
        QVERIFY(timeline && timeline->isVisible());
        QVERIFY(timeline->geometry().bottom() <= w.centralWidget()->height());
        QVERIFY(canvasOf(w)->height() > 200);
        w.controller().advance(0.5);
        w.refreshNow();
        const auto* memory = w.findChild<QLabel*>(QStringLiteral("timelineMemory"));
        QVERIFY(memory && memory->text().endsWith(QStringLiteral("MB of")));
    }

private:
    std::unique_ptr<MainWindow> window_;
};

QTEST_MAIN(TestTimeline)
#include "tst_timeline.moc"
