// The Instruments dock as a teacher uses it, offscreen (issue 19): the period timer against
// 2π·√(m/k), a graph of a conserved momentum, readouts that say whether they show the live
// state or the setup, New / Open / Reset clearing every instrument, CSV export, pickers that
// offer only valid probes, a probe whose object was deleted shown as invalid, the stopwatch,
// and (issue 17's acceptance) a pendulum built with the canvas tools whose period the timer
// reads against T = 4·√(L/g)·K(sin(θ0/2)); (issue 37) a protractor's probe on a hinged box timed
// against the physical pendulum's period.
//
// With PHASEBOX_SCREENSHOT_DIR set, pictures of the dock's tabs are written there to look at.

#include "GuiTestSupport.h"
#include "MainWindowTestSupport.h"
#include "app/desktop/CanvasTools.h"
#include "app/desktop/DesktopOptions.h"
#include "app/desktop/MainWindow.h"
#include "app/desktop/MeasureTools.h"
#include "app/desktop/presenters/InstrumentsPresenter.h"
#include "app/document/Document.h"
#include "app/io/SceneIO.h"
#include "app/sim/ProbeRecorder.h"
#include "physics/world/Probes.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneView.h"
#include "ui/instruments/GraphsView.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/instruments/ProbeFormat.h"
#include "ui/instruments/ProbePicker.h"
#include "ui/instruments/ProbeTableView.h"
#include "ui/instruments/ReadoutView.h"
#include "ui/instruments/TimerView.h"
#include "ui/plots/ProbeChart.h"

#include <QAction>
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QClipboard>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QGraphicsTextItem>
#include <QGuiApplication>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineSeries>
#include <QProcess>
#include <QSlider>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QValueAxis>

#include <cmath>
#include <numbers>

using namespace phasebox;
using namespace phasebox::testing::parts;
using phasebox::testing::freeScene;
using phasebox::testing::visibleParticle;

namespace {

// A mass m on a spring k (rest length 0) to the origin, released at x = 0.5 m, no gravity: it
// swings along x with T = 2π·√(m/k).
SceneDesc springScene(double k, double m) {
    SceneDesc scene;
    scene.name = "Mass on a spring";
    scene.particles.push_back(visibleParticle("bob", {0.5, 0.0}, m));
    scene.particles.push_back(visibleParticle("marker", {-1.0, 1.0}));
    scene.particles.back().pinned = true;
    SpringDesc spring;
    spring.id = "spring";
    spring.a = "bob";
    spring.anchor = Point2{0.0, 0.0};
    spring.stiffness = k;
    spring.restLength = 0.0;
    scene.springs.push_back(spring);
    return scene;
}

struct Window {
    MainWindow w;
    ui::InstrumentsPanel* panel() { return instrumentsPanelOf(w); }
    InstrumentsPresenter* instruments() { return instrumentsOf(w); }
    Window() {
        w.resize(1400, 900);
        w.show();
        w.findChild<QDockWidget*>(QStringLiteral("instrumentsDock"))->raise();
    }
    void load(const SceneDesc& scene) {
        QString error;
        QVERIFY2(w.document().loadFromDesc(scene, {}, &error), qPrintable(error));
    }
};

QLineSeries* lineOf(QChartView* view) {
    const auto series = view->chart()->series();
    return series.isEmpty() ? nullptr : qobject_cast<QLineSeries*>(series.front());
}

QValueAxis* axisOf(QChartView* view, Qt::Orientation orientation) {
    const auto axes = view->chart()->axes(orientation);
    return axes.isEmpty() ? nullptr : qobject_cast<QValueAxis*>(axes.front());
}

bool isNiceStep(double step) {
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
    for (const double m : {1.0, 2.0, 5.0, 10.0})
        if (std::abs(mantissa - m) < 1e-9) return true;
    return false;
}

QList<QByteArray> readLines(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    QList<QByteArray> lines = file.readAll().split('\n');
    if (!lines.isEmpty() && lines.back().isEmpty()) lines.removeLast();
    return lines;
}

// Pictures of the dock's tabs, to look at, when PHASEBOX_SCREENSHOT_DIR is set.
void saveTabPictures(Window& window, const QString& prefix) {
    const QString dir = qEnvironmentVariable("PHASEBOX_SCREENSHOT_DIR");
    if (dir.isEmpty()) return;
    using Tab = ui::InstrumentsPanel::Tab;
    for (const auto& [tab, name] :
         {std::pair{Tab::Readouts, "readouts"}, std::pair{Tab::Graphs, "graphs"},
          std::pair{Tab::Timer, "timer"}, std::pair{Tab::Table, "table"}}) {
        window.panel()->showTab(tab);
        window.w.refreshNow();
        QApplication::processEvents();
        window.w.findChild<QDockWidget*>(QStringLiteral("instrumentsDock"))
            ->grab()
            .save(QStringLiteral("%1/%2-%3.png").arg(dir, prefix, QLatin1String(name)));
    }
    window.w.grab().save(QStringLiteral("%1/%2-window.png").arg(dir, prefix));
    window.instruments()->exportGraph(0, QStringLiteral("%1/%2-export.png").arg(dir, prefix),
                                      nullptr);
}

}  // namespace

class TestInstruments : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    // Ticks of 1, 2 or 5 × 10^k, with the decimals the step needs.
    void niceTicksReadWell() {
        const ui::NiceTicks a = ui::niceTicks(0.0, 10.3, 6);
        QCOMPARE(a.step, 2.0);
        QCOMPARE(a.first, 0.0);
        QCOMPARE(a.labelFormat, QStringLiteral("%.0f"));
        const ui::NiceTicks b = ui::niceTicks(-0.137, 0.342, 6);
        QCOMPARE(b.step, 0.1);
        QVERIFY(std::abs(b.first - -0.1) < 1e-12);
        QCOMPARE(b.labelFormat, QStringLiteral("%.1f"));
        const ui::NiceTicks c = ui::niceTicks(1.2e-9, 4.1e-9, 6);
        QVERIFY(std::abs(c.step - 5e-10) < 1e-22);
        QCOMPARE(c.labelFormat, QStringLiteral("%.1e"));
        // A small change of a large value: fixed decimals, as many as the step needs.
        const ui::NiceTicks d = ui::niceTicks(1.49974, 1.50001, 6);
        QVERIFY(std::abs(d.step - 5e-5) < 1e-17);
        QCOMPARE(d.labelFormat, QStringLiteral("%.5f"));
        QCOMPARE(ui::niceTicks(0.0, 4e-6, 6).labelFormat, QStringLiteral("%.6f"));
        QCOMPARE(ui::niceTicks(0.0, 4e-7, 6).labelFormat, QStringLiteral("%.0e"));
        for (double range : {0.003, 0.07, 1.0, 13.0, 420.0, 9.9e4})
            QVERIFY(isNiceStep(ui::niceTicks(0.0, range, 6).step));
        // A constant is drawn flat at its value, not as rounding noise filling the plot.
        const auto [lo, hi] = ui::paddedRange(0.4, 0.4 + 1e-16);
        QVERIFY(lo < 0.4 && hi > 0.4 && hi - lo > 0.05);
    }

    // A graph as small as the dock draws three of them (the rolling race's): every value label
    // of its y axis is whole, none elided to "…" and none dropped, and there are at least three.
    void smallGraphsShowTheirYLabels_data() {
        QTest::addColumn<double>("top");
        for (double top : {3.9, 6.7, 10.1, 0.042, 1234.0})
            QTest::newRow(qPrintable(QString::number(top))) << top;
    }
    void smallGraphsShowTheirYLabels() {
        QFETCH(double, top);
        QVector<QPointF> points;
        for (int k = 0; k <= 180; ++k) points.push_back({k / 60.0, top * k / 180.0});
        ui::ProbeGraphView view;
        view.resize(230, 160);
        view.show();
        QCoreApplication::processEvents();
        view.setSeries(points, QStringLiteral("time [s]"), QStringLiteral("m/s"), true, {});
        auto* chartView = view.findChild<QChartView*>();
        QVERIFY(chartView);
        QCoreApplication::processEvents();
        chartView->grab();  // lays the chart out at its size
        QStringList shown, hidden;
        const double plotLeft = chartView->chart()->plotArea().left();
        for (QGraphicsItem* item : chartView->scene()->items()) {
            auto* text = dynamic_cast<QGraphicsTextItem*>(item);
            if (!text || text->toPlainText().isEmpty()) continue;
            // The y labels are left of the plot area.
            if (text->sceneBoundingRect().right() > plotLeft + 1.0) continue;
            if (text->toPlainText() == QLatin1String("m/s")) continue;
            (text->isVisible() ? shown : hidden) << text->toPlainText();
        }
        qInfo("top %g: view %dx%d, plot %gx%g; shown %s; hidden %s", top, chartView->width(),
              chartView->height(), chartView->chart()->plotArea().width(),
              chartView->chart()->plotArea().height(), qPrintable(shown.join(' ')),
              qPrintable(hidden.join(' ')));
        QVERIFY2(hidden.isEmpty(), qPrintable(hidden.join(' ')));
        QVERIFY2(shown.size() >= 3, qPrintable(shown.join(' ')));
        for (const QString& label : shown)
            QVERIFY2(!label.contains(QChar(0x2026)) && !label.contains("..."), qPrintable(label));
    }

    // Issue 19's acceptance: the period timer on a mass on a spring reads 2π·√(m/k) within
    // 0.1%, and lists the crossings its period is the mean interval of.
    void periodTimerMeasuresTwoPiRootMOverK() {
        const double k = 50.0, m = 2.0;
        const double exact = 2.0 * std::numbers::pi * std::sqrt(m / k);
        Window window;
        window.load(springScene(k, m));
        window.panel()->timer()->picker()->enter(QStringLiteral("bob.x"));
        QVERIFY(!window.panel()->timer()->picker()->isInvalid());
        QVERIFY(window.w.controller().advance(8.0 * exact));
        window.w.refreshNow();
        const std::optional<double> period = window.panel()->timer()->period();
        QVERIFY(period.has_value());
        qInfo("period timer: T = %.6f s, 2π·√(m/k) = %.6f s, error %.2e", *period, exact,
              *period / exact - 1.0);
        QVERIFY2(std::abs(*period / exact - 1.0) < 1e-3,
                 qPrintable(QString("T %1 s, exact %2 s").arg(*period).arg(exact)));
        // The crossings shown are the ones the period is the mean interval of.
        const ProbeRecorder& probes = probeRecorderOf(window.w);
        const std::vector<double> crossings = probes.crossings(probes.indexOf("bob.x"));
        QVERIFY(crossings.size() >= 7);
        QCOMPARE(window.panel()->timer()->crossingCount(), static_cast<int>(crossings.size()));
        const double mean = (crossings.back() - crossings.front()) / double(crossings.size() - 1);
        QVERIFY(std::abs(mean - *period) < 1e-9);
        QVERIFY(window.panel()->timer()->periodText().contains(QStringLiteral("T = 1.25")));
        // The same number as phasebox-cli run --probe reports for the same run.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("spring.phasebox.json"));
        QVERIFY(window.w.saveFile(path));
        QProcess cli;
        cli.start(QStringLiteral(PHASEBOX_CLI),
                  {"run", path, "--duration",
                   QString::number(window.w.document().world().time(), 'g', 17), "--probe", "bob.x",
                   "--json"});
        QVERIFY(cli.waitForFinished(60000));
        QCOMPARE(cli.exitCode(), 0);
        const QJsonObject json = QJsonDocument::fromJson(cli.readAllStandardOutput()).object();
        const double cliPeriod = json["probes"].toObject()["bob.x"].toObject()["period"].toDouble();
        qInfo("phasebox-cli run --probe bob.x: period %.12f s, the timer %.12f s", cliPeriod,
              *period);
        QVERIFY(std::abs(cliPeriod - *period) < 1e-9);
        QVERIFY(window.instruments()->plotProbe(QStringLiteral("bob.x")));
        QVERIFY(window.instruments()->plotProbe(QStringLiteral("bob.vx"), QStringLiteral("bob.x")));
        window.w.document().setSelection({QStringLiteral("bob")});
        saveTabPictures(window, QStringLiteral("spring"));
    }

    // A free system's momentum, graphed: every point is the initial 0.4 kg·m/s, and the axis
    // shows a flat line at that value with nice ticks.
    void graphOfSystemMomentumStaysConstant() {
        Window window;
        window.load(freeScene());
        QVERIFY(window.instruments()->plotProbe(QStringLiteral("system.px")));
        QVERIFY(window.instruments()->plotProbe(QStringLiteral("system.py")));
        QCOMPARE(window.panel()->graphs()->count(), 2);  // several graphs at once
        QVERIFY(window.w.controller().advance(5.0));
        window.w.refreshNow();
        for (const auto& [index, expected] : {std::pair{0, 0.4}, std::pair{1, 0.8}}) {
            QChartView* view = window.panel()->graphs()->graph(index)->chartView();
            QLineSeries* line = lineOf(view);
            QVERIFY(line && line->count() >= 290);
            double worst = 0.0;
            for (const QPointF& p : line->points())
                worst = std::max(worst, std::abs(p.y() - expected));
            qInfo("system momentum graph %d: %lld points, largest departure %.2e kg·m/s", index,
                  static_cast<long long>(line->count()), worst);
            QVERIFY2(worst < 1e-9, qPrintable(QString::number(worst)));
            QValueAxis* y = axisOf(view, Qt::Vertical);
            QVERIFY(y->min() < expected && y->max() > expected);
            QVERIFY(y->max() - y->min() > 0.1 * expected);  // flat, not magnified noise
            QVERIFY(isNiceStep(y->tickInterval()));
            QVERIFY(isNiceStep(axisOf(view, Qt::Horizontal)->tickInterval()));
            QCOMPARE(y->titleText(), QStringLiteral("kg·m/s"));
        }
        // And one probe against another: a spring's phase portrait.
        QVERIFY(window.instruments()->plotProbe(QStringLiteral("a.vx"), QStringLiteral("a.x")));
        window.w.refreshNow();
        QChartView* phase = window.panel()->graphs()->graph(2)->chartView();
        QCOMPARE(axisOf(phase, Qt::Horizontal)->titleText(), QStringLiteral("a.x [m]"));
        QVERIFY(lineOf(phase)->count() > 0);  // recorded from when it was chosen
        saveTabPictures(window, QStringLiteral("free"));
    }

    // Readouts: the live state while running, labelled with the time, a moment the timeline
    // shows labelled as recorded, and the setup after Reset, labelled so.
    void readoutShowsLiveStateWhileRunningAndSetupAfterReset() {
        Window window;
        window.load(springScene(50.0, 2.0));
        window.panel()->showTab(ui::InstrumentsPanel::Tab::Readouts);
        window.w.document().setSelection({QStringLiteral("bob")});
        ui::ReadoutView* readouts = window.panel()->readouts();
        QCOMPARE(readouts->state(), QStringLiteral("setup"));
        QCOMPARE(readouts->subject(), QStringLiteral("bob (particle)"));
        QCOMPARE(readouts->valueText(QStringLiteral("position (x, y)")),
                 QStringLiteral("(0.50000, 0)"));
        QVERIFY(readouts->valueText(QStringLiteral("angle")).isEmpty());  // a particle's none

        // Running: the live state, with the time.
        window.w.controller().play();
        QTRY_VERIFY_WITH_TIMEOUT(window.w.document().world().time() > 0.2, 5000);
        QVERIFY(window.w.controller().isRunning());
        QTRY_VERIFY(readouts->state().startsWith(QStringLiteral("live, t = ")));
        window.w.controller().pause();
        window.w.refreshNow();
        const World& world = window.w.document().world();
        QCOMPARE(readouts->state(), QStringLiteral("live, t = %1 s").arg(world.time(), 0, 'f', 2));
        const Vec2 x = world.particlePosition(0);
        QVERIFY(std::abs(x.x() - 0.5) > 1e-3);
        QCOMPARE(
            readouts->valueText(QStringLiteral("position (x, y)")),
            QStringLiteral("(%1, %2)").arg(ui::formatReading(x.x()), ui::formatReading(x.y())));

        // An earlier moment on the timeline: named as recorded, with its time, and read then.
        const double liveTime = world.time();
        const QString livePosition = readouts->valueText(QStringLiteral("position (x, y)"));
        auto* timeline = window.w.findChild<QSlider*>(QStringLiteral("timelineSlider"));
        QVERIFY(timeline && timeline->maximum() > 4);
        timeline->setValue(timeline->maximum() / 2);
        QVERIFY(world.time() > 0.0 && world.time() < liveTime);
        QCOMPARE(readouts->state(),
                 QStringLiteral("recorded, t = %1 s").arg(world.time(), 0, 'f', 3));
        const Vec2 then = world.particlePosition(0);
        QCOMPARE(readouts->valueText(QStringLiteral("position (x, y)")),
                 QStringLiteral("(%1, %2)")
                     .arg(ui::formatReading(then.x()), ui::formatReading(then.y())));
        timeline->setValue(0);  // the setup's frame is a recorded moment too
        QCOMPARE(readouts->state(), QStringLiteral("recorded, t = 0.000 s"));
        QCOMPARE(readouts->valueText(QStringLiteral("position (x, y)")),
                 QStringLiteral("(0.50000, 0)"));
        timeline->setValue(timeline->maximum());  // the live end again
        QCOMPARE(readouts->state(), QStringLiteral("live, t = %1 s").arg(liveTime, 0, 'f', 2));
        QCOMPARE(readouts->valueText(QStringLiteral("position (x, y)")), livePosition);

        // Reset: the setup again.
        window.w.action("reset")->trigger();
        QCOMPARE(readouts->state(), QStringLiteral("setup"));
        QCOMPARE(readouts->valueText(QStringLiteral("position (x, y)")),
                 QStringLiteral("(0.50000, 0)"));
        QCOMPARE(readouts->valueText(QStringLiteral("speed")), QStringLiteral("0"));

        // Two and three objects: the ruler and the protractor.
        window.w.document().setSelection({QStringLiteral("bob"), QStringLiteral("marker")});
        QCOMPARE(readouts->valueText(QStringLiteral("distance bob–marker")),
                 ui::formatReading(std::hypot(1.5, 1.0)));
    }

    // New, Open and Reset clear every instrument: graphs, table, period timer, stopwatch.
    void newOpenResetRevertClearTheInstruments() {
        QTemporaryDir dir;
        Window window;
        window.load(springScene(50.0, 2.0));
        const QString path = dir.filePath(QStringLiteral("spring.phasebox.json"));
        QVERIFY(window.instruments()->plotProbe(QStringLiteral("bob.x")));
        QVERIFY(window.instruments()->timeProbe(QStringLiteral("bob.x")));
        // Saved with the scene (CONTRACT §7): Open and Revert bring them back.
        QString error;
        QVERIFY2(window.w.saveFile(path, &error), qPrintable(error));
        ui::GraphsView* graphs = window.panel()->graphs();
        ui::TimerView* timer = window.panel()->timer();
        ui::ProbeTableView* table = window.panel()->table();

        const auto runAndCheckFull = [&] {
            window.instruments()->startStopStopwatch();
            QVERIFY(window.w.controller().advance(3.0));
            window.instruments()->lapStopwatch();
            window.w.refreshNow();
            QVERIFY(graphs->graph(0)->pointCount() > 150);
            QVERIFY(table->model()->rowCount() > 150);
            QVERIFY(timer->period().has_value());
            QVERIFY(timer->crossingCount() >= 2);
            QCOMPARE(timer->lapCount(), 1);
            QVERIFY(timer->stopwatchText() != QStringLiteral("0.000 s"));
        };
        const auto checkCleared = [&](const char* what) {
            window.w.refreshNow();
            QVERIFY2(graphs->graph(0)->pointCount() <= 1, what);
            QVERIFY2(table->model()->rowCount() <= 1, what);
            QVERIFY2(probeRecorderOf(window.w).times().size() <= 1, what);
            QVERIFY2(!timer->period().has_value(), what);
            QCOMPARE(timer->crossingCount(), 0);
            QCOMPARE(timer->lapCount(), 0);
            QCOMPARE(timer->stopwatchText(), QStringLiteral("0.000 s"));
            QVERIFY2(!window.instruments()->stopwatch().isRunning(), what);
        };

        runAndCheckFull();
        window.w.action("reset")->trigger();
        checkCleared("reset");
        // The probes stay chosen after Reset: the next run records them from its start.
        QVERIFY(window.w.controller().advance(0.5));
        QCOMPARE(probeRecorderOf(window.w).times().size(), std::size_t(31));
        QCOMPARE(probeRecorderOf(window.w).times().front(), 0.0);

        runAndCheckFull();
        QVERIFY(window.w.openFile(path, true));
        checkCleared("open");

        // Revert (File menu): an edit and a run dropped, the file's scene back as saved.
        runAndCheckFull();
        QVERIFY(window.w.document().moveObject(QStringLiteral("bob"), {0.9, 0.0}));
        QVERIFY(window.w.document().isModified());
        QVERIFY(window.w.action("revert")->isEnabled());
        window.w.action("revert")->trigger();
        checkCleared("revert");
        QVERIFY(!window.w.document().isModified());
        QCOMPARE(window.w.document().setup().particles.front().position[0], 0.5);
        QCOMPARE(window.w.document().world().time(), 0.0);
        QVERIFY(!window.w.document().undoStack()->canUndo());

        runAndCheckFull();
        window.w.action("new")->trigger();
        checkCleared("new");
        QVERIFY(!window.w.action("revert")->isEnabled());  // nothing to revert to
        // The new scene has no bob, and none of the last scene's instruments.
        QCOMPARE(graphs->count(), 1);
        QVERIFY(graphs->graph(0)->yPicker()->probe().isEmpty());
        QVERIFY(timer->picker()->probe().isEmpty());
        QCOMPARE(probeRecorderOf(window.w).probeCount(), 0);
        QVERIFY(window.w.controller().advance(0.5));
        window.w.refreshNow();
        QCOMPARE(graphs->graph(0)->pointCount(), 0);
    }

    // CSV: the table's header is t and every recorded probe (quoted where it holds a comma),
    // one row per sample; a graph's CSV is t, then its x probe, then its y probe. Pictures too.
    void csvExportWritesHeaderAndRows() {
        QTemporaryDir dir;
        Window window;
        window.load(springScene(50.0, 2.0));
        QVERIFY(window.instruments()->plotProbe(QStringLiteral("bob.x")));
        QVERIFY(window.instruments()->plotProbe(QStringLiteral("bob.vx"), QStringLiteral("bob.x")));
        QVERIFY(window.instruments()->timeProbe(QStringLiteral("bob.speed")));
        window.panel()->table()->picker()->enter(QStringLiteral("distance(bob,marker)"));
        QVERIFY(window.w.controller().advance(1.0));
        QString error;
        const QString tablePath = dir.filePath(QStringLiteral("table.csv"));
        QVERIFY2(window.instruments()->exportTable(tablePath, &error), qPrintable(error));
        const QList<QByteArray> lines = readLines(tablePath);
        QCOMPARE(lines.size(), 1 + 61);  // t = 0 and 60 steps
        QCOMPARE(lines[0], QByteArray("t,bob.x,bob.vx,bob.speed,\"distance(bob,marker)\""));
        QVERIFY2(lines[1].startsWith("0,0.5,0,0,1.802775637"), lines[1].constData());
        const QList<QByteArray> last = lines.back().split(',');
        QCOMPARE(last.size(), 5);
        const World& world = window.w.document().world();
        QVERIFY(std::abs(last[0].toDouble() - world.time()) < 1e-12);
        QCOMPARE(last[1].toDouble(), world.particlePosition(0).x());
        QCOMPARE(last[2].toDouble(), world.particleVelocity(0).x());

        const QString graphCsv = dir.filePath(QStringLiteral("graph.csv"));
        QVERIFY2(window.instruments()->exportGraph(1, graphCsv, &error), qPrintable(error));
        const QList<QByteArray> graphLines = readLines(graphCsv);
        QCOMPARE(graphLines[0], QByteArray("t,bob.x,bob.vx"));
        QCOMPARE(graphLines.size(), 62);
        for (const char* format : {"png", "svg"}) {
            const QString picture = dir.filePath(QStringLiteral("graph.") + format);
            QVERIFY2(window.instruments()->exportGraph(0, picture, &error), qPrintable(error));
            QVERIFY(QFile(picture).size() > 1000);
        }
        QVERIFY(QImage(dir.filePath(QStringLiteral("graph.png"))).width() == 1200);
        // A graph without a probe has nothing to export.
        QVERIFY(window.panel()->graphs()->addGraph());
        QVERIFY(!window.instruments()->exportGraph(2, dir.filePath("empty.csv"), &error));

        // Copy: tab-separated, the selected rows or all.
        window.instruments()->copyTable();
        const QString copied = QGuiApplication::clipboard()->text();
        QVERIFY(copied.startsWith(
            QStringLiteral("t\tbob.x\tbob.vx\tbob.speed\tdistance(bob,marker)\n0\t0.5\t")));
        QCOMPARE(copied.count(QLatin1Char('\n')), 62);
        window.w.refreshNow();
        window.panel()->showTab(ui::InstrumentsPanel::Tab::Table);
        QTableView* table = window.panel()->table()->table();
        table->selectRow(3);
        window.instruments()->copyTable();
        QCOMPARE(QGuiApplication::clipboard()->text().count(QLatin1Char('\n')), 2);
        // Ctrl+C in the table copies its rows, not the scene's objects (the window's Copy).
        QGuiApplication::clipboard()->clear();
        table->selectRow(5);
        table->setFocus();
        QTest::keyClick(table, Qt::Key_C, Qt::ControlModifier);
        const QString row = QGuiApplication::clipboard()->text();
        QVERIFY2(row.startsWith(QStringLiteral("t\tbob.x")) && row.count(QLatin1Char('\n')) == 2,
                 qPrintable(row));
    }

    // The pickers offer only probes that parse in this scene; typed text that is no probe is
    // refused with the reason.
    void invalidProbesAreNotOffered() {
        Window window;
        SceneDesc scene = springScene(50.0, 2.0);
        BoxDesc wall;
        wall.id = "wall";
        wall.position = {3.0, 0.0};
        wall.isStatic = true;
        scene.boxes.push_back(wall);
        window.load(scene);
        ui::ProbePicker* picker = window.panel()->graphs()->graph(0)->yPicker();
        const QStringList offered = picker->offered();
        QCOMPARE(offered, window.instruments()->offered());
        for (const char* valid : {"bob.x", "bob.L", "system.total", "system.com_x", "wall.angle",
                                  "contact_force(bob)", "marker.x"})
            QVERIFY2(offered.contains(QLatin1String(valid)), valid);
        for (const char* invalid : {"bob.angle", "bob.omega", "contact_force(wall)",
                                    "contact_force(marker)", "spring.x", "force(spring)"})
            QVERIFY2(!offered.contains(QLatin1String(invalid)), invalid);
        const World& world = window.w.document().world();
        for (const QString& probe : offered)
            QVERIFY2(parseProbe(world, probe.toStdString()), qPrintable(probe));

        // The selection's probes come first, with the ruler between two objects.
        window.w.document().setSelection({QStringLiteral("bob"), QStringLiteral("wall")});
        QCOMPARE(picker->offered().front(), QStringLiteral("bob.x"));
        QVERIFY(picker->offered().contains(QStringLiteral("distance(bob,wall)")));

        // Typed: refused with the reason, the graph unchanged.
        picker->enter(QStringLiteral("bob.x"));
        QVERIFY(!picker->isInvalid());
        for (const char* typed : {"bob.angle", "nobody.x", "contact_force(wall)", "bob.z"}) {
            picker->enter(QLatin1String(typed));
            QVERIFY2(picker->isInvalid(), typed);
            QVERIFY(!probeRecorderOf(window.w).probes().contains(QLatin1String(typed)));
        }
        QCOMPARE(probeRecorderOf(window.w).probes(), QStringList{QStringLiteral("bob.x")});
        const auto* status = window.w.findChild<QLabel*>(QStringLiteral("statusMessage"));
        QVERIFY2(status->text().contains(QStringLiteral("unknown probe \"bob.z\"")),
                 qPrintable(status->text()));
        QVERIFY(!window.instruments()->plotProbe(QStringLiteral("bob.angle")));
        // And from the command line: exit 2 with the list of known probes.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("s.phasebox.json"));
        QVERIFY(window.w.saveFile(path));
        QProcess app;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("QT_QPA_PLATFORM", "offscreen");
        app.setProcessEnvironment(env);
        app.start(QStringLiteral(PHASEBOX_DESKTOP),
                  {"--screenshot", dir.filePath("x.png"), "--probe", "bob.angle", path});
        QVERIFY(app.waitForFinished(60000));
        QCOMPARE(app.exitCode(), 2);
        QVERIFY(app.readAllStandardError().contains("known: ID.x"));
    }

    // A probe whose object is deleted is shown as invalid (and records nothing) rather than
    // crashing or reading another object; undo brings it back.
    void deletedObjectMakesItsProbeInvalid() {
        Window window;
        window.load(freeScene());
        QVERIFY(window.instruments()->plotProbe(QStringLiteral("b.x")));
        QVERIFY(window.instruments()->timeProbe(QStringLiteral("b.vx")));
        QVERIFY(window.w.controller().advance(0.5));
        QVERIFY(window.w.document().deleteObjects({QStringLiteral("b")}));
        QVERIFY(window.w.controller().advance(0.5));
        window.w.refreshNow();
        ui::ProbeGraphView* graph = window.panel()->graphs()->graph(0);
        QVERIFY2(graph->message().contains(QStringLiteral("no object \"b\"")),
                 qPrintable(graph->message()));
        const ProbeRecorder& probes = probeRecorderOf(window.w);
        const int b = probes.indexOf(QStringLiteral("b.x"));
        QVERIFY(!probes.isValid(b));
        QVERIFY(std::isnan(probes.values(b).back()));
        QVERIFY(!window.instruments()->offered().contains(QStringLiteral("b.x")));
        window.w.document().undoStack()->undo();
        QVERIFY(window.w.controller().advance(0.2));
        window.w.refreshNow();
        QVERIFY(probes.isValid(b));
        QVERIFY(std::isfinite(probes.values(b).back()));
        QVERIFY(!graph->message().contains(QStringLiteral("no object")));
    }

    // Memory stays bounded on a long run (every other sample dropped past the limit, as the
    // Recorder does) while the period, counted at every step, stays exact.
    void longRunsKeepMemoryBoundedAndThePeriodExact() {
        const double k = 50.0, m = 2.0;
        const double exact = 2.0 * std::numbers::pi * std::sqrt(m / k);
        Window window;
        window.load(springScene(k, m));
        ProbeRecorder& probes = probeRecorderOf(window.w);
        probes.setMaxSamples(200);
        QVERIFY(window.instruments()->timeProbe(QStringLiteral("bob.x")));
        QVERIFY(window.instruments()->plotProbe(QStringLiteral("bob.x")));
        QVERIFY(window.w.controller().advance(40.0 * exact));  // 3016 steps
        window.w.refreshNow();
        QVERIFY(probes.times().size() < 200);
        QVERIFY(probes.stride() >= 16);
        QCOMPARE(probes.values(0).size(), probes.times().size());
        const std::optional<double> period = window.panel()->timer()->period();
        QVERIFY(period && std::abs(*period / exact - 1.0) < 1e-3);
        QVERIFY(window.panel()->graphs()->graph(0)->pointCount() == int(probes.times().size()));
        // The decimated series still finds the crossings (about 12 samples a period here).
        QVERIFY(window.panel()->timer()->crossingCount() >= 38);
    }

    // A blow-up restores an earlier frame: the instruments keep the history up to it, finite.
    void divergenceKeepsTheHistoryBeforeIt() {
        Window window;
        QVERIFY(
            window.w.openFile(QStringLiteral(":/scenes/stiff-spring-blowup.phasebox.json"), true));
        SimulationDesc s = window.w.document().setup().simulation;
        s.integrator = "symplectic_euler";
        QVERIFY(window.w.document().applySimulationSettings(s));
        QVERIFY(window.instruments()->plotProbe(QStringLiteral("system.total")));
        QVERIFY(!window.w.controller().advance(2.0));
        window.w.refreshNow();
        const ProbeRecorder& probes = probeRecorderOf(window.w);
        const double t = window.w.document().world().time();
        QVERIFY(probes.times().size() >= 2);
        QVERIFY(probes.times().back() <= t + 1e-12);
        for (const double v : probes.values(0)) QVERIFY(std::isfinite(v));
        QVERIFY(window.panel()->graphs()->graph(0)->pointCount() >= 2);
    }

    // The stopwatch runs on simulated time: it stands still while paused and in slow motion.
    void stopwatchRunsOnSimulatedTime() {
        Window window;
        window.load(springScene(50.0, 2.0));
        InstrumentsPresenter* instruments = window.instruments();
        QVERIFY(window.w.controller().advance(1.0));
        window.w.action("stopwatch")->trigger();  // Ctrl+T
        QVERIFY(instruments->stopwatch().isRunning());
        QVERIFY(window.w.controller().advance(1.5));
        window.w.action("stopwatchLap")->trigger();
        QVERIFY(window.w.controller().advance(0.5));
        instruments->startStopStopwatch();
        QVERIFY(window.w.controller().advance(1.0));  // stopped: not counted
        window.w.refreshNow();
        const double dt = window.w.document().setup().simulation.dt;
        QVERIFY(std::abs(instruments->stopwatch().elapsed(window.w.document().world().time()) -
                         2.0) < 0.5 * dt);
        QCOMPARE(window.panel()->timer()->stopwatchText(), QStringLiteral("2.000 s"));
        QCOMPARE(window.panel()->timer()->lapCount(), 1);
        QVERIFY(std::abs(instruments->stopwatch().laps().front() - 1.5) < 0.5 * dt);
    }

    // Issue 17's acceptance: a pendulum built with the canvas tools (a particle, then a rod
    // dragged from it to a fixed point a metre away, level with it: θ0 = 90°), its period read
    // from the period timer on the bob's x probe, against T = 4·√(L/g)·K(sin(θ0/2)) within 0.5%,
    // under the new scene's symplectic Euler at dt 1/60.
    void pendulumBuiltWithTheToolsHasTheEllipticPeriod() {
        Window window;
        QWidget* canvas = canvasOf(window.w);
        // Issue 17's pendulum: 1 m (to the pixel), its lowest point 0.25 m above the new
        // scene's ground (y = −2), inside the canvas as the new scene shows it.
        const QPoint pivot = canvasOf(window.w)->toWidget(QPointF(-0.5, -0.75)).toPoint();
        const QPoint bob = canvasOf(window.w)->toWidget(QPointF(0.5, -0.75)).toPoint();
        QVERIFY(canvas->rect().contains(pivot) && canvas->rect().contains(bob));
        window.w.action("toolParticle")->trigger();
        QTest::mouseClick(canvas, Qt::LeftButton, {}, bob);
        window.w.action("toolJoint")->trigger();
        auto* type = window.w.findChild<QComboBox*>(QStringLiteral("jointType"));
        QVERIFY(type);
        type->setCurrentIndex(type->findText(QStringLiteral("rod")));
        QCOMPARE(toolsOf(window.w)->jointType(), JointType::Rod);
        QTest::mousePress(canvas, Qt::LeftButton, {}, bob);
        for (int k = 1; k <= 4; ++k) QTest::mouseMove(canvas, bob + (pivot - bob) * k / 4);
        QTest::mouseRelease(canvas, Qt::LeftButton, {}, pivot);
        QCOMPARE(window.w.document().setup().joints.size(), std::size_t(1));
        QCOMPARE(window.w.document().setup().joints[0].type, JointType::Rod);
        QVERIFY(!window.w.document().setup().joints[0].b);

        // The timer on the bob's x, chosen from what the picker offers.
        ui::ProbePicker* picker = window.panel()->timer()->picker();
        QVERIFY(picker->offered().contains(QStringLiteral("p0.x")));
        QVERIFY(picker->offered().contains(QStringLiteral("force(j0)")));
        picker->setCurrentIndex(picker->findText(QStringLiteral("p0.x")));
        emit picker->activated(picker->currentIndex());
        QVERIFY(probeRecorderOf(window.w).probes().contains(QStringLiteral("p0.x")));

        const World& world = window.w.document().world();
        const QPointF top = canvasOf(window.w)->toWorld(QPointF(pivot));
        const Vec2 start = world.particlePosition(0);
        const double length = (start - Vec2(top.x(), top.y())).norm();
        const double theta0 = std::atan2(std::abs(start.x() - top.x()), top.y() - start.y());
        const double exact =
            4.0 * std::sqrt(length / 9.81) * std::comp_ellint_1(std::sin(0.5 * theta0));
        QVERIFY(window.w.controller().advance(5.3 * exact));
        window.w.refreshNow();
        const std::optional<double> period = window.panel()->timer()->period();
        QVERIFY(period.has_value());
        qInfo(
            "pendulum from the tools: L = %.4f m, θ0 = %.2f°, T = %.5f s, exact %.5f s, "
            "error %.2e (%d crossings)",
            length, theta0 * 180.0 / std::numbers::pi, *period, exact, *period / exact - 1.0,
            window.panel()->timer()->crossingCount());
        QVERIFY2(std::abs(*period / exact - 1.0) < 5e-3,
                 qPrintable(QString("T %1 s, exact %2 s").arg(*period).arg(exact)));
        QVERIFY(window.panel()->timer()->crossingCount() >= 5);
        window.w.document().setSelection({QStringLiteral("p0")});
        saveTabPictures(window, QStringLiteral("pendulum"));
    }

    // Issue 37's angles: a box hinged to the world and released at 90° is a physical pendulum
    // (L = I_pivot/(m·d), I_pivot = m·(w² + h²)/12 + m·d²). The pickers offer its joint's angle,
    // a protractor from straight down at the pivot to the box is the probe
    // angle(0:-1,0:0,box), the same angle, graphed; the timer on it reads the elliptic period.
    void protractorOnAHingedBoxTimesThePhysicalPendulum() {
        const double d = 0.9, w = 0.3, h = 0.6, theta0 = 0.5 * std::numbers::pi;
        const QByteArray json = QStringLiteral(R"({
  "format": "phasebox-scene", "version": 2,
  "simulation": { "integrator": "rk4", "dt": 0.002, "duration": 10 },
  "effects": { "gravity": { "g": [0, -9.81] } },
  "boxes": [ { "id": "box", "position": [%1, 0], "size": [%2, %3], "mass": 1.5 } ],
  "joints": [ { "id": "pivot", "type": "hinge", "a": "box", "anchor": [0, 0] } ]
})")
                                    .arg(d)
                                    .arg(w)
                                    .arg(h)
                                    .toUtf8();
        const SceneLoadResult loaded = SceneIO::parse(json, QStringLiteral("hinged box"));
        QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
        Window window;
        window.load(*loaded.scene);
        QVERIFY(window.instruments()->offered().contains(QStringLiteral("pivot.angle")));
        QString error;
        QVERIFY2(measureToolsOf(window.w)->addProtractor(QStringLiteral("0:-1,0:0,box"), &error),
                 qPrintable(error));
        const QString probe = measureToolsOf(window.w)->protractorProbe(0);
        QCOMPARE(probe, QStringLiteral("angle(0:-1,0:0,box)"));
        QVERIFY(window.instruments()->offered().contains(probe));
        QVERIFY2(window.instruments()->plotProbe(probe, {}, &error), qPrintable(error));
        QVERIFY(window.instruments()->timeProbe(probe, &error));
        QCOMPARE(measureToolsOf(window.w)->protractorDegrees(0), 90.0);

        const double lengthEq = ((w * w + h * h) / 12.0 + d * d) / d;
        const double exact =
            4.0 * std::sqrt(lengthEq / 9.81) * std::comp_ellint_1(std::sin(0.5 * theta0));
        QVERIFY(window.w.controller().advance(4.2 * exact));
        window.w.refreshNow();
        const std::optional<double> period = window.panel()->timer()->period();
        QVERIFY(period.has_value());
        qInfo(
            "protractor on a box hinged at 90 deg: T = %.9f s, 4*sqrt(L/g)*K(sin 45°) = %.9f s, "
            "error %.2e (%d crossings)",
            *period, exact, *period / exact - 1.0, window.panel()->timer()->crossingCount());
        // RK4 at 2 ms over four periods: 3.5e-10 measured (the crossings' linear interpolation
        // and RK4's h⁴), held to 1e-8.
        QVERIFY(std::abs(*period / exact - 1.0) < 1e-8);
        // The protractor reads the joint's angle: the same line from the same vertex.
        const World& world = window.w.document().world();
        const ProbeParse joint = parseProbe(world, "pivot.angle");
        QVERIFY(joint);
        QVERIFY(std::abs(measureToolsOf(window.w)->protractorDegrees(0) -
                         std::abs(evaluateProbe(world, *joint.probe)) * 180.0 / std::numbers::pi) <
                1e-9);
        window.w.document().setSelection({QStringLiteral("box")});
        saveTabPictures(window, QStringLiteral("protractor-pendulum"));
    }

    // --probe EXPR fills the first graph of the screenshot.
    void commandLineProbeFillsTheFirstGraph() {
        QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("shot.png"));
        QProcess app;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("QT_QPA_PLATFORM", "offscreen");
        app.setProcessEnvironment(env);
        app.start(
            QStringLiteral(PHASEBOX_DESKTOP),
            {"--screenshot", png, "--run-for", "2", "--probe", "light.y", "--probe", "system.total",
             QStringLiteral(PHASEBOX_SOURCE_DIR
                            "/resources/scenes/spring-oscillator.phasebox.json")});
        QVERIFY(app.waitForFinished(60000));
        QCOMPARE(app.exitCode(), 0);
        QVERIFY(!QImage(png).isNull());
        DesktopOptions options;
        QString error;
        QVERIFY(parseDesktopOptions({"phasebox", "--probe", "a.x", "--probe", "distance(a,b)"},
                                    options, &error));
        QCOMPARE(options.probes, (QStringList{"a.x", "distance(a,b)"}));
    }
};

QTEST_MAIN(TestInstruments)
#include "tst_instruments.moc"
