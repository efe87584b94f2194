// Numbers follow the language in the window and never in files (issue: every classroom): in
// German a readout of the selection, the energy plot's axis numbers and the timeline's time show
// a decimal comma, while the scene the window saves and the energy CSV it exports keep the
// decimal point that scripts and other programs read.

#include "app/desktop/MainWindow.h"
#include "app/document/Document.h"
#include "app/i18n/Language.h"
#include "app/sim/Recorder.h"
#include "app/sim/SimulationController.h"
#include "physics/world/World.h"
#include "tests/gui/MainWindowTestSupport.h"
#include "ui/instruments/ReadoutView.h"
#include "ui/plots/PlotsPanel.h"

#include <QAction>
#include <QChart>
#include <QChartView>
#include <QDockWidget>
#include <QFile>
#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace phasebox;
using namespace phasebox::testing::parts;

namespace {
const QRegularExpression kCommaNumber(QStringLiteral("^[−-]?\\d+,\\d+$"));
const QRegularExpression kPointNumber(QStringLiteral("^[−-]?\\d+\\.\\d+$"));

// The texts a chart view draws: title, axis titles, tick labels, legend.
QStringList drawnTexts(const QChartView* view) {
    QStringList texts;
    for (const QGraphicsItem* item : view->scene()->items())
        if (const auto* text = qgraphicsitem_cast<const QGraphicsTextItem*>(item))
            if (text->isVisible()) texts << text->toPlainText();
    return texts;
}

QString readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}
}  // namespace

class TestLocaleNumbers : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void cleanup() { i18n::install(QStringLiteral("en")); }
    void germanWindowShowsCommasAndWritesPoints();
};

void TestLocaleNumbers::germanWindowShowsCommasAndWritesPoints() {
    QVERIFY(i18n::install(QStringLiteral("de")));
    MainWindow w;
    w.resize(1024, 700);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(QStringLiteral(":/scenes/spring-oscillator.phasebox.json"), true));
    w.document().setSelection({QStringLiteral("light")});
    w.action(QStringLiteral("showInstruments"))->trigger();
    const double dt = w.document().world().settings().dt;
    for (int i = 0; i < 30; ++i) QVERIFY(w.controller().advance(dt));
    w.refreshNow();
    QCoreApplication::processEvents();

    // A readout: the selected ball's values, each with a decimal comma.
    const auto* readout = w.findChild<ui::ReadoutView*>();
    QVERIFY(readout);
    const auto* table = readout->findChild<QTableWidget*>();
    QVERIFY(table);
    int commas = 0;
    for (int r = 0; r < table->rowCount(); ++r)
        for (int c = 0; c < table->columnCount(); ++c) {
            const QTableWidgetItem* item = table->item(r, c);
            if (!item) continue;
            for (const QString& word : item->text().split(
                     QRegularExpression(QStringLiteral("[\\s()]+")), Qt::SkipEmptyParts)) {
                QVERIFY2(!kPointNumber.match(word).hasMatch(), qPrintable(item->text()));
                if (kCommaNumber.match(word).hasMatch()) ++commas;
            }
        }
    QVERIFY2(commas >= 3, qPrintable(QString::number(commas)));

    // The plots again in front of the instruments that share their place.
    plotsPanelOf(w)->window()->findChild<QDockWidget*>(QStringLiteral("plotsDock"))->raise();
    w.refreshNow();
    QCoreApplication::processEvents();

    // The energy plot's tick labels: the time axis runs over half a second, in steps of a
    // fraction of one, so some ticks have decimals, every one of them a comma.
    const QStringList texts = drawnTexts(plotsPanelOf(w)->energyView());
    int tickCommas = 0;
    for (const QString& text : texts) {
        QVERIFY2(!kPointNumber.match(text).hasMatch(), qPrintable(texts.join(QLatin1Char('|'))));
        if (kCommaNumber.match(text).hasMatch()) ++tickCommas;
    }
    QVERIFY2(tickCommas >= 2, qPrintable(texts.join(QLatin1Char('|'))));

    // The timeline: shown and recorded time.
    const auto* time = w.findChild<QLabel*>(QStringLiteral("timelineTime"));
    QVERIFY(time);
    const QString seconds = QLocale(QLocale::German).toString(30 * dt, 'f', 3);
    QCOMPARE(time->text(), QStringLiteral("%1 / %1 s").arg(seconds));
    QVERIFY(seconds.contains(QLatin1Char(',')));

    // Files: the saved scene reads back as JSON with the same step, written with a point.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString scenePath = dir.filePath(QStringLiteral("saved.phasebox.json"));
    QVERIFY(w.saveFile(scenePath));
    const QString scene = readAll(scenePath);
    QJsonParseError parseError;
    const QJsonDocument json = QJsonDocument::fromJson(scene.toUtf8(), &parseError);
    QVERIFY2(parseError.error == QJsonParseError::NoError, qPrintable(parseError.errorString()));
    QCOMPARE(json.object()
                 .value(QStringLiteral("simulation"))
                 .toObject()
                 .value(QStringLiteral("dt"))
                 .toDouble(),
             dt);
    QVERIFY(scene.contains(QString::number(dt, 'g', 17).left(4)));
    QVERIFY(QString::number(dt, 'g', 17).left(4).contains(QLatin1Char('.')));

    // The energy CSV: every row has the header's fields (t, the ledger's lines), each a C-locale
    // number; a decimal comma would have split a field in two.
    const QString csvPath = dir.filePath(QStringLiteral("energy.csv"));
    QString error;
    QVERIFY2(recorderOf(w).writeEnergyCsv(csvPath, &error), qPrintable(error));
    const QStringList lines = readAll(csvPath).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QVERIFY(lines.size() > 10);
    const qsizetype columns = lines.front().split(QLatin1Char(',')).size();
    QVERIFY(columns >= 6);
    int points = 0;
    for (const QString& line : lines.mid(1)) {
        const QStringList fields = line.split(QLatin1Char(','));
        QCOMPARE(fields.size(), columns);
        for (const QString& field : fields) {
            bool ok = false;
            QLocale::c().toDouble(field, &ok);
            QVERIFY2(ok, qPrintable(line));
            if (field.contains(QLatin1Char('.'))) ++points;
        }
    }
    QVERIFY(points > lines.size());
}

QTEST_MAIN(TestLocaleNumbers)
#include "tst_locale_numbers.moc"
