// The app's energy plot books the push-out of contacts as its own line (CONTRACT §6): a box
// started 5 cm into the floor is pushed out by position correction, which raises its potential
// energy by m·g·d; the recorder, the Plots dock's chart and the energy CSV all carry that
// correction, and it is the ledger's number, not something the plot works out again.

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
#include <QLegend>
#include <QLineSeries>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <memory>

using namespace phasebox;

namespace {
constexpr double kMass = 1.0;
constexpr double kDepth = 0.05;  // how far the box starts inside the floor [m]

// scenes::tower(1) with its box 5 cm into the ground.
SceneDesc sunkenBox() {
    SceneDesc scene = scenes::tower(1);
    scene.boxes[0].position = {0.0, 0.5 - kDepth};
    // Velocity Verlet is exact under constant gravity: the box at rest then gets nothing back
    // from the solver but the push, so the correction is m·g·d alone. (Under symplectic Euler the
    // solver also returns, each step, the ½·m·g²·h² that the method's step took, and books it
    // as correction too.)
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
    void pushOutIsPlottedAsCorrection();
    void correctionLineIsDashedAndColouredApart();
    void legendKeepsWholeNamesInANarrowDock();
};

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
    QVERIFY(lines.front().endsWith(",drift,correction"));
    QCOMPARE(lines.back().split(',').back().toDouble(), ledger.correction);
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

// Six names do not fit one row of a narrow dock: the legend moves to the right side instead of
// cutting them short, and comes back below the plot when the dock is wide again.
void TestEnergyPlot::legendKeepsWholeNamesInANarrowDock() {
    const ui::EnergySample samples[] = {{0.0, 1.0, 2.0, 0.0, 0.0, 0.0},
                                        {1.0, 0.5, 2.0, -0.1, 0.01, 0.4}};
    ui::PlotsPanel panel;
    panel.resize(400, 600);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setEnergy(samples, {}, QStringLiteral("Energy"));
    QCOMPARE(panel.energyView()->chart()->legend()->alignment(), Qt::AlignRight);
    panel.resize(1400, 600);
    QTRY_COMPARE(panel.energyView()->chart()->legend()->alignment(), Qt::AlignBottom);
    panel.resize(400, 600);
    QTRY_COMPARE(panel.energyView()->chart()->legend()->alignment(), Qt::AlignRight);
}

QTEST_MAIN(TestEnergyPlot)
#include "tst_energy_plot.moc"
