// The app's energy plot books the push-out of contacts as its own line (CONTRACT §6): a box
// started 5 cm into the floor is pushed out by position correction, which raises its potential
// energy by m·g·d; the recorder, the Plots dock's chart and the energy CSV all carry that
// correction, and it is the ledger's number, not something the plot works out again.
// Large energies are labelled as plain numbers, not printf's exponents.

#include "MainWindowTestSupport.h"
#include "app/desktop/CanvasTools.h"
#include "app/desktop/MainWindow.h"
#include "app/desktop/presenters/PlotsPresenter.h"
#include "app/document/Document.h"
#include "app/sim/Recorder.h"
#include "app/sim/SimulationController.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"
#include "ui/plots/Charts.h"
#include "ui/plots/PlotsPanel.h"

#include <QChart>
#include <QChartView>
#include <QFile>
#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QImage>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPainter>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <memory>
#include <vector>

using namespace phasebox;
using namespace phasebox::testing::parts;

namespace {
constexpr double kMass = 1.0;
constexpr double kDepth = 0.05;  // how far the box starts inside the floor [m]

// scenes::tower(1) with its box 5 cm into the ground.
SceneDesc sunkenBox() {
    SceneDesc scene = scenes::tower(1);
    scene.boxes[0].position = {0.0, 0.5 - kDepth};
    // The box rests in every method's step (the contact's force is held over it), so the
    // solver gives it nothing back but the push, and the correction is m·g·d alone.
    scene.simulation.integrator = "velocity_verlet";
    scene.boxes[0].mass = kMass;
    return scene;
}

QLineSeries* seriesNamed(QChart* chart, const QString& name) {
    for (QAbstractSeries* s : chart->series())
        if (s->name() == name) return qobject_cast<QLineSeries*>(s);
    return nullptr;
}
}  // namespace

class TestEnergyPlot : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void boxDrawnInANewSceneLeavesDriftAndCorrectionFlat();
    void pushOutIsPlottedAsCorrection();
    void correctionLineIsDashedAndColouredApart();
    void legendKeepsWholeNamesInANarrowDock();
    void largeEnergiesReadAsPlainNumbers();
    void clipPlotsKeepWholeLegendNames();
};

// What a class sees first (issue 36): a new scene at its defaults (symplectic Euler, dt 1/60),
// a box drawn with the box tool, Play. The box falls, lands and lies on the floor; from then on
// the plot's drift and correction lines stay flat (within 1 mJ per kg per second, CONTRACT §6)
// instead of falling and rising, straight and opposite, for as long as the scene runs.
void TestEnergyPlot::boxDrawnInANewSceneLeavesDriftAndCorrectionFlat() {
    MainWindow w;
    w.resize(1200, 800);
    w.show();
    w.document().newScene();
    QCOMPARE(w.document().setup().simulation.integrator, std::string("symplectic_euler"));
    // Drawn 1 m above the new scene's ground (y = −2 m): it falls, lands and lies there.
    QCOMPARE(w.document().setup().planes.size(), std::size_t(1));
    const double ground = w.document().setup().planes[0].point[1];
    const QPoint from = canvasOf(w)->toWidget(QPointF(-0.3, ground + 1.4)).toPoint();
    const QPoint to = canvasOf(w)->toWidget(QPointF(0.3, ground + 1.0)).toPoint();
    w.action("toolBox")->trigger();
    testing::drag(canvasOf(w), from, to);
    QCOMPARE(w.document().setup().boxes.size(), std::size_t(1));
    QVERIFY(w.document().setup().boxes[0].position[1] > ground + 1.0);
    const double mass = w.document().setup().boxes[0].resolvedMass();
    QVERIFY(w.controller().advance(10.0));
    w.refreshNow();

    QChart* chart = plotsPanelOf(w)->energyView()->chart();
    QLineSeries* drift = seriesNamed(chart, QStringLiteral("drift"));
    QLineSeries* correction = seriesNamed(chart, QStringLiteral("correction"));
    QVERIFY(drift && correction);
    QVERIFY(drift->count() > 10 && correction->count() > 10);
    QCOMPARE(drift->at(drift->count() - 1).x(), w.document().world().time());
    // Once it has landed (it started within a few metres of the floor): from 3 s to the end.
    const auto spread = [](QLineSeries* s) {
        double low = 1e300, high = -1e300;
        for (int i = 0; i < s->count(); ++i) {
            if (s->at(i).x() < 3.0) continue;
            low = std::min(low, s->at(i).y());
            high = std::max(high, s->at(i).y());
        }
        return high - low;
    };
    const double bound = 1e-3 * mass * 7.0;
    const EnergyLedger& books = w.document().world().energy();
    QVERIFY(books.workNc < 0.0);  // the landing, an inelastic impact (restitution 0.5)
    qInfo(
        "box of %.3g kg drawn in a new scene, 3 s to 10 s: drift moves %.2e J, correction "
        "%.2e J (bound %.2e J); at the end drift %.3g J, correction %.3g J, work_nc %.3g J",
        mass, spread(drift), spread(correction), bound, w.document().world().energy().drift,
        w.document().world().energy().correction, w.document().world().energy().workNc);
    QVERIFY(spread(drift) <= bound);
    QVERIFY(spread(correction) <= bound);
}

void TestEnergyPlot::pushOutIsPlottedAsCorrection() {
    Document doc;
    QVERIFY(doc.loadFromDesc(sunkenBox()));
    SimulationController controller(doc);
    Recorder recorder;
    controller.setRecorder(&recorder);
    ui::PlotsPanel panel;
    PlotsPresenter presenter(panel, doc, controller, recorder);
    QVERIFY(controller.advance(2.0));
    presenter.refresh();

    const EnergyLedger& ledger = doc.world().energy();
    const auto& gravity = doc.setup().effects.gravity;
    QVERIFY(gravity.has_value());
    const double mgd = kMass * std::hypot(gravity->g[0], gravity->g[1]) * kDepth;
    const auto& samples = recorder.energySamples();
    QVERIFY(!samples.empty());
    qInfo(
        "after %.3f s: recorded correction %.4f J, ledger %.4f J (m·g·d = %.4f J), "
        "work_nc %.2e J, drift %.2e J",
        samples.back().t, samples.back().correction, ledger.correction, mgd, ledger.workNc,
        ledger.drift);
    // The recorder keeps the ledger's correction, and the push-out is m·g·d of it.
    QCOMPARE(samples.back().correction, ledger.correction);
    QVERIFY2(
        std::abs(samples.back().correction - mgd) < 0.05 * mgd,
        qPrintable(
            QStringLiteral("correction %1 J, m·g·d %2 J").arg(samples.back().correction).arg(mgd)));

    // The Plots dock's chart has a correction line ending at the ledger's number.
    QChart* chart = panel.energyView()->chart();
    QLineSeries* correction = seriesNamed(chart, QStringLiteral("correction"));
    QVERIFY(correction);
    QVERIFY(correction->count() > 0);
    QCOMPARE(correction->at(correction->count() - 1).y(), ledger.correction);
    QCOMPARE(correction->at(correction->count() - 1).x(), doc.world().time());
    for (const char* name : {"kinetic", "potential", "total", "work_nc", "drift"})
        QVERIFY2(seriesNamed(chart, QString::fromLatin1(name)), name);

    // And the energy CSV has it as the last column.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("energy.csv"));
    QString error;
    QVERIFY2(presenter.exportPlot(ui::PlotsPanel::Plot::Energy, path, &error), qPrintable(error));
    QFile csv(path);
    QVERIFY(csv.open(QIODevice::ReadOnly | QIODevice::Text));
    const QList<QByteArray> lines = csv.readAll().trimmed().split('\n');
    QVERIFY(lines.size() > 2);
    QVERIFY(lines.front().endsWith(",drift,correction,total"));
    const QList<QByteArray> last = lines.back().split(',');
    QCOMPARE(last[5].toDouble(), ledger.correction);
}

void TestEnergyPlot::correctionLineIsDashedAndColouredApart() {
    const ui::EnergySample samples[] = {{0.0, 1.0, 2.0, 0.0, 0.0, 0.0},
                                        {1.0, 0.5, 2.0, -0.1, 0.01, 0.4}};
    std::unique_ptr<QChart> chart(ui::createEnergyChart(samples, {}, QStringLiteral("Energy")));
    QLineSeries* correction = seriesNamed(chart.get(), QStringLiteral("correction"));
    QVERIFY(correction);
    QCOMPARE(correction->pen().style(), Qt::DashLine);
    QCOMPARE(correction->at(1).y(), 0.4);
    for (QAbstractSeries* s : chart->series()) {
        if (s == correction) continue;
        auto* line = qobject_cast<QLineSeries*>(s);
        QVERIFY(line);
        QVERIFY2(line->pen().color() != correction->pen().color(), qPrintable(s->name()));
    }
}

// Six names do not fit one row of a narrow dock: the chart's legend gives way to the panel's
// compact one below it, which holds every name whole and leaves the chart its whole width (a
// legend down the side narrowed the time axis until its numbers were cut); back in a wide dock
// the chart's own legend returns below the plot.
void TestEnergyPlot::legendKeepsWholeNamesInANarrowDock() {
    const ui::EnergySample samples[] = {{0.0, 1.0, 2.0, 0.0, 0.0, 0.0},
                                        {1.0, 0.5, 2.0, -0.1, 0.01, 0.4}};
    ui::PlotsPanel panel;
    panel.resize(300, 600);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setEnergy(samples, {}, QStringLiteral("Energy"));
    QChart* chart = panel.energyView()->chart();
    QVERIFY(!chart->legend()->isVisible());
    QTRY_VERIFY(panel.energyLegend()->isVisible());
    const QString text = panel.energyLegend()->text();
    for (const QLegendMarker* marker : chart->legend()->markers())
        QVERIFY2(text.contains(marker->label()), qPrintable(marker->label()));
    // The compact legend's rows fit the panel: its height for its width holds all of it.
    QVERIFY(panel.energyLegend()->height() >=
            panel.energyLegend()->heightForWidth(panel.energyLegend()->width()));
    QVERIFY(chart->plotArea().width() > 0.6 * panel.energyView()->width());
    panel.resize(1400, 600);
    QTRY_VERIFY(chart->legend()->isVisible());
    QCOMPARE(chart->legend()->alignment(), Qt::AlignBottom);
    QTRY_VERIFY(!panel.energyLegend()->isVisible());
    panel.resize(300, 600);
    QTRY_VERIFY(!chart->legend()->isVisible());
    QTRY_VERIFY(panel.energyLegend()->isVisible());
}

// A pile's energies are thousands of joules: the energy axis labels them as numbers a class
// reads ("12000", "14000"), on whole steps, never printf's "1.4e+04".
void TestEnergyPlot::largeEnergiesReadAsPlainNumbers() {
    std::vector<ui::EnergySample> samples;
    for (int i = 0; i <= 100; ++i) {
        const double t = 0.02 * i;
        samples.push_back({t, 1500.0 * t, 15000.0 - 1500.0 * t, 0.0, 0.0, 0.0});
    }
    ui::PlotsPanel panel;
    panel.resize(420, 600);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setEnergy(samples, {}, QStringLiteral("Energy"));
    QCoreApplication::processEvents();
    const QRegularExpression exponent(QStringLiteral("\\d[eE][+−-]?\\d"));
    const QRegularExpression whole(QStringLiteral("^[−-]?\\d{4,5}$"));
    QStringList texts;
    int plain = 0;
    for (const QGraphicsItem* item : panel.energyView()->scene()->items())
        if (const auto* text = qgraphicsitem_cast<const QGraphicsTextItem*>(item);
            text && text->isVisible()) {
            texts << text->toPlainText();
            QVERIFY2(!exponent.match(texts.back()).hasMatch(), qPrintable(texts.back()));
            if (whole.match(texts.back()).hasMatch()) ++plain;
        }
    QVERIFY2(plain >= 3, qPrintable(texts.join(QLatin1Char('|'))));
}

// A clip draws its plots beside the canvas at a third of its width (ClipRenderer): where the six
// names do not fit one row, the legend goes down the side, each name whole; where they fit it
// stays below the plot.
void TestEnergyPlot::clipPlotsKeepWholeLegendNames() {
    const ui::EnergySample samples[] = {{0.0, 1.0, 2.0, 0.0, 0.0, 0.0},
                                        {1.0, 0.5, 2.0, -0.1, 0.01, 0.4}};
    QImage frame(960, 540, QImage::Format_RGB32);
    QPainter painter(&frame);
    std::unique_ptr<QChart> narrow(ui::createEnergyChart(samples, {}, QStringLiteral("Energy")));
    QVERIFY(ui::legendRowWidth(narrow.get()) > 384.0);
    ui::paintChart(narrow.get(), painter, QRectF(576, 0, 384, 270));
    QLegend* legend = narrow->legend();
    QCOMPARE(legend->alignment(), Qt::AlignRight);
    const QFontMetricsF metrics(legend->font());
    for (QLegendMarker* marker : legend->markers())
        QVERIFY2(legend->geometry().width() > metrics.horizontalAdvance(marker->label()),
                 qPrintable(marker->label()));
    std::unique_ptr<QChart> wide(ui::createEnergyChart(samples, {}, QStringLiteral("Energy")));
    QVERIFY(ui::legendRowWidth(wide.get()) < 1200.0);
    ui::paintChart(wide.get(), painter, QRectF(0, 0, 1200, 400));
    QCOMPARE(wide->legend()->alignment(), Qt::AlignBottom);
}

QTEST_MAIN(TestEnergyPlot)
#include "tst_energy_plot.moc"
