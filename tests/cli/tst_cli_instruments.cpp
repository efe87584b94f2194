// A lesson's saved instruments on the command line (CONTRACT §7): `run` adds the saved probes
// (the table's, the graphs', the timers') to --csv and --json as if given with --probe, first
// and once each; an instrument that names no object is refused at its JSON path (exit 2) by
// every command that builds the scene.

#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "CliTestSupport.h"

#include <cmath>
#include <numbers>

namespace {

using Result = phasebox::testing::CliResult;

// m = 1 kg on a spring of k = 4 N/m to the origin, released at x = 1 m: period π s.
const char* kLesson = R"({
  "format": "phasebox-scene", "version": 2, "name": "spring lesson",
  "simulation": { "integrator": "rk4", "dt": 0.01, "duration": 31.4159265358979 },
  "particles": [ { "id": "ball", "position": [1, 0], "mass": 1 } ],
  "springs": [ { "a": "ball", "anchor": [0, 0], "stiffness": 4, "rest_length": 0 } ],
  "instruments": {
    "probes": ["ball.vx"],
    "graphs": [ { "y": "ball.x" }, { "y": "ball.vx", "x": "ball.x" } ],
    "timers": ["ball.x"],
    "rulers": [ { "ends": ["ball", "0:0"] } ],
    "view": { "center": [0, 0], "width": 4 }
  }
})";

}  // namespace

class TestCliInstruments : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;

    QString write(const QString& name, const QByteArray& text) {
        return phasebox::testing::writeFile(dir_, name, text);
    }

private slots:
    void savedProbesJoinTheCsvFirstAndOnce() {
        const Result r = phasebox::testing::runCli(
            {"run", write("lesson.json", kLesson), "--duration", "0.05", "--csv", "-", "--track",
             "ball", "--probe", "ball.x", "--probe", "system.total"});
        QCOMPARE(r.status, 0);
        QVERIFY2(r.err.isEmpty(), r.err.constData());
        const QStringList lines = QString::fromUtf8(r.out).split('\n', Qt::SkipEmptyParts);
        QVERIFY(lines.size() > 2);
        // The table's ball.vx, then the graphs' ball.x (their ball.vx again is not repeated),
        // then the command line's system.total (its ball.x is the saved one).
        QVERIFY2(lines[0].endsWith(QStringLiteral("ball.vy,ball.vx,ball.x,system.total")),
                 qPrintable(lines[0]));
        const QStringList first = lines[1].split(',');
        QCOMPARE(first[first.size() - 2].toDouble(), 1.0);  // ball.x at the start
        QCOMPARE(first[first.size() - 3].toDouble(), 0.0);  // ball.vx at rest
    }

    void savedProbesReportThePeriodInJson() {
        const Result r =
            phasebox::testing::runCli({"run", write("lesson.json", kLesson), "--json"});
        QCOMPARE(r.status, 0);
        const QJsonObject probes = QJsonDocument::fromJson(r.out).object()["probes"].toObject();
        QCOMPARE(probes.keys(), (QStringList{"ball.vx", "ball.x"}));
        const double period = probes["ball.x"].toObject()["period"].toDouble();
        QVERIFY2(std::abs(period / std::numbers::pi - 1.0) < 1e-3,
                 qPrintable(QString::number(period)));
    }

    void instrumentsNamingNoObjectAreRefusedAtTheirPath() {
        QByteArray text = kLesson;
        text.replace(R"("graphs": [ { "y": "ball.x" })", R"("graphs": [ { "y": "bal.x" })");
        text.replace(R"(["ball", "0:0"])", R"(["ball", "nowhere"])");
        const QString path = write("broken.json", text);
        for (const char* command : {"run", "info"}) {
            const Result r = phasebox::testing::runCli({command, path});
            QCOMPARE(r.status, 2);
            const QString err = QString::fromUtf8(r.err);
            QVERIFY2(err.contains(QStringLiteral("instruments.graphs[0].y: ")), qPrintable(err));
            QVERIFY2(err.contains(QStringLiteral("no object \"bal\"")), qPrintable(err));
            QVERIFY2(err.contains(QStringLiteral("instruments.rulers[0].ends: ")), qPrintable(err));
            QVERIFY2(!err.contains(QStringLiteral("; known:")), qPrintable(err));
        }
    }

    void unknownInstrumentKeysAreRefused() {
        QByteArray text = kLesson;
        text.replace(R"("timers")", R"("timer")");
        const Result r = phasebox::testing::runCli({"info", write("typo.json", text)});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.contains("instruments.timer: unknown key; did you mean \"timers\"?"),
                 r.err.constData());
        text = kLesson;
        text.replace(R"("view": {)", R"("colour": "red", "view": {)");
        const Result other = phasebox::testing::runCli({"info", write("extra.json", text)});
        QCOMPARE(other.status, 2);
        QVERIFY2(other.err.contains("instruments.colour: unknown key; known: probes, graphs"),
                 other.err.constData());
    }
};

QTEST_GUILESS_MAIN(TestCliInstruments)
#include "tst_cli_instruments.moc"
