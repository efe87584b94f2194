// phasebox-cli accuracy end to end (CONTRACT.md §4): the CSV columns, the default dt list, the
// JSON report, the work-precision plot as PNG and SVG, contact scenes, diverging runs and bad
// input, through the real binary.

#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include "CliTestSupport.h"

#include <cmath>
#include <map>

namespace {

using Result = phasebox::testing::CliResult;

Result cli(const QStringList& args) {
    return phasebox::testing::runCli(args);
}

// A unit harmonic oscillator, m = 1 on a spring k = 1 to the origin; one second of it.
const char* kOscillator = R"({
  "format": "phasebox-scene", "version": 1, "name": "oscillator",
  "simulation": { "integrator": "rk4", "dt": 0.02, "duration": 1 },
  "particles": [ { "id": "ball", "position": [1, 0], "velocity": [0, 0.5], "mass": 1, "radius": 0 } ],
  "springs": [ { "a": "ball", "anchor": [0, 0], "stiffness": 1, "rest_length": 0 } ]
})";

// A ball bouncing on the floor: contacts.
const char* kBounce = R"({
  "format": "phasebox-scene", "version": 1, "name": "bounce",
  "simulation": { "dt": 0.02, "duration": 1 },
  "effects": { "gravity": {} },
  "particles": [ { "id": "ball", "position": [0, 1], "radius": 0.1, "restitution": 0.8 } ],
  "planes": [ { "id": "floor", "point": [0, 0], "normal": [0, 1] } ]
})";

// k = 1e6 with m = 1 at dt = 1/60: every explicit method blows up.
const char* kStiff = R"({
  "format": "phasebox-scene", "version": 1, "name": "stiff",
  "simulation": { "dt": 0.016666666666666666, "duration": 0.5 },
  "particles": [ { "id": "bob", "position": [0, -1.1], "mass": 1, "radius": 0 } ],
  "springs": [ { "a": "bob", "anchor": [0, 0], "stiffness": 1e6, "rest_length": 0 } ]
})";

const char* kHeader =
    "integrator,dt,steps,force_evals,cpu_seconds,position_error,energy_drift,order";

}  // namespace

class TestCliAccuracy : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;

    QString write(const QString& name, const char* text) {
        return phasebox::testing::writeFile(dir_, name, text);
    }

private slots:
    void csvHasContractColumnsAndDefaultDts() {
        const Result r = cli({"accuracy", write("osc.json", kOscillator), "--csv", "-"});
        QCOMPARE(r.status, 0);
        const QStringList lines = QString::fromUtf8(r.out).split('\n', Qt::SkipEmptyParts);
        QVERIFY(lines.size() > 1);
        // The contract's columns exactly, in order; extensions may only follow them.
        QVERIFY2(lines[0] == kHeader || lines[0].startsWith(QString(kHeader) + ","),
                 qPrintable(lines[0]));
        QCOMPARE(lines.size(), 1 + 10 * 6);
        std::map<QString, QList<double>> dts;
        for (const QString& line : lines.mid(1)) {
            const QStringList f = line.split(',');
            QVERIFY(f.size() >= 8);
            dts[f[0]].append(f[1].toDouble());
            QVERIFY(f[5].toDouble() >= 0.0);  // position_error
            QVERIFY(f[4].toDouble() >= 0.0);  // cpu_seconds
        }
        QCOMPARE(dts.size(), std::size_t(10));
        for (const char* name : {"explicit_euler", "symplectic_euler", "midpoint", "heun", "rk4",
                                 "velocity_verlet", "implicit_euler", "implicit_midpoint"}) {
            const QList<double>& list = dts[name];
            QCOMPARE(list.size(), 6);
            for (int k = 0; k < 6; ++k) QCOMPARE(list[k], 0.02 / (1 << k));
        }
        // The first record of a method has no order; rk4's next ones are near 4.
        const QStringList rk4First = lines.filter(QRegularExpression("^rk4,")).first().split(',');
        QCOMPARE(rk4First[7], QString());
        const QStringList rk4Second = lines.filter(QRegularExpression("^rk4,"))[1].split(',');
        QVERIFY2(std::abs(rk4Second[7].toDouble() - 4.0) < 0.3, qPrintable(rk4Second.join(',')));
    }

    void csvToFileAndTableOtherwise() {
        const QString scene = write("osc.json", kOscillator);
        const QString csv = dir_.filePath("acc.csv");
        Result r =
            cli({"accuracy", scene, "--integrators", "rk4,heun", "--dt", "0.1,0.05", "--csv", csv});
        QCOMPARE(r.status, 0);
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 5);
        QVERIFY(lines[1].startsWith("rk4,0.1,10,40,"));  // 10 steps, 4 evaluations each
        r = cli({"accuracy", scene, "--integrators", "rk4", "--dt", "0.1,0.05"});
        QCOMPARE(r.status, 0);
        const QString text = QString::fromUtf8(r.out);
        QVERIFY2(text.contains("reference:  exact: harmonic oscillator"), qPrintable(text));
        QVERIFY(text.contains("integrator") && text.contains("rk4"));
    }

    void jsonHasRecords() {
        const Result r =
            cli({"accuracy", write("osc.json", kOscillator), "--json", "--integrators",
                 "rk4,implicit_euler,rk45", "--dt", "0.1,0.05,0.025", "--tolerances", "1e-4,1e-6"});
        QCOMPARE(r.status, 0);
        QJsonParseError error;
        const QJsonObject o = QJsonDocument::fromJson(r.out, &error).object();
        QVERIFY2(error.error == QJsonParseError::NoError, qPrintable(error.errorString()));
        QCOMPARE(o["scene"].toString(), QString("oscillator"));
        QCOMPARE(o["reference"].toString(), QString("exact: harmonic oscillator"));
        QCOMPARE(o["contacts"].toBool(), false);
        QVERIFY(o.contains("note"));
        const QJsonArray records = o["records"].toArray();
        QCOMPARE(records.size(), 3 + 3 + 2);
        for (const QJsonValue& v : records) {
            const QJsonObject rec = v.toObject();
            for (const char* key : {"integrator", "dt", "steps", "force_evals", "cpu_seconds",
                                    "position_error", "energy_drift", "order", "tolerance"})
                QVERIFY2(rec.contains(key), key);
            QVERIFY(rec["position_error"].toDouble() > 0.0);
        }
        QVERIFY(records[0].toObject()["order"].isNull());
        QVERIFY(std::abs(records[2].toObject()["order"].toDouble() - 4.0) < 0.3);
        QVERIFY(std::abs(records[5].toObject()["order"].toDouble() - 1.0) < 0.3);
        const QJsonObject adaptive = records[7].toObject();
        QCOMPARE(adaptive["integrator"].toString(), QString("rk45"));
        QCOMPARE(adaptive["tolerance"].toDouble(), 1e-6);
        QCOMPARE(adaptive["dt"].toDouble(), 0.1);  // the frame step it lands on
        QVERIFY(adaptive["order"].isNull());
        QVERIFY(records[0].toObject()["tolerance"].isNull());
    }

    void plotWritesPngAndSvg() {
        const QString scene = write("osc.json", kOscillator);
        const QString png = dir_.filePath("wp.png"), svg = dir_.filePath("wp.svg");
        Result r =
            cli({"accuracy", scene, "--integrators", "rk4,symplectic_euler,rk45", "--plot", png});
        QCOMPARE(r.status, 0);
        const QImage image(png);
        QVERIFY(!image.isNull());
        QVERIFY(image.width() >= 800 && image.height() >= 500);
        r = cli({"accuracy", scene, "--integrators", "rk4", "--plot", svg, "--json"});
        QCOMPARE(r.status, 0);
        QVERIFY(!QJsonDocument::fromJson(r.out).isNull());  // the plot does not disturb stdout
        QFile f(svg);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        QVERIFY(text.contains("<svg"));
        QVERIFY(text.contains("CPU time [s], left is faster"));
        QVERIFY(text.contains("position error [m], lower is better"));
    }

    void contactSceneSaysOrdersDoNotApply() {
        const Result r = cli({"accuracy", write("bounce.json", kBounce), "--json", "--integrators",
                              "symplectic_euler,rk4", "--dt", "0.02,0.01"});
        QCOMPARE(r.status, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o["contacts"].toBool(), true);
        QCOMPARE(o["reference"].toString(), QString("rk45 tol 1e-12"));
        QVERIFY(o["note"].toString().contains("contact events make every method first-order"));
        for (const QJsonValue& v : o["records"].toArray()) QVERIFY(v.toObject()["order"].isNull());
        QVERIFY(QString::fromUtf8(r.err).contains("first-order"));
        const Result table =
            cli({"accuracy", write("bounce.json", kBounce), "--integrators", "rk4"});
        QVERIFY(QString::fromUtf8(table.out).contains(
            "note:       contact events make every method first-order"));
    }

    void divergedRunsAreDataNotFailure() {
        const Result r = cli({"accuracy", write("stiff.json", kStiff), "--json", "--integrators",
                              "explicit_euler,implicit_euler", "--dt", "0.016666666666666666"});
        QCOMPARE(r.status, 0);
        const QJsonArray records = QJsonDocument::fromJson(r.out).object()["records"].toArray();
        QCOMPARE(records.size(), 2);
        QVERIFY(records[0].toObject()["position_error"].isNull());
        QCOMPARE(records[0].toObject()["diverged"].toBool(), true);
        QCOMPARE(records[1].toObject()["diverged"].toBool(), false);
        QVERIFY(QString::fromUtf8(r.err).contains("diverged"));
        const Result csv = cli({"accuracy", write("stiff.json", kStiff), "--csv", "-",
                                "--integrators", "explicit_euler", "--dt", "0.016666666666666666"});
        QCOMPARE(csv.status, 0);
        QVERIFY(QString::fromUtf8(csv.out).split('\n')[1].split(',')[5] == "inf");
    }

    void badInputExitsTwo_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QString scene = write("osc.json", kOscillator);
        QTest::newRow("no scene") << QStringList{"accuracy"} << "needs a SCENE";
        QTest::newRow("unknown integrator")
            << QStringList{"accuracy", scene, "--integrators", "rk4,rk5"}
            << "unknown integrator \"rk5\"; known: explicit_euler";
        QTest::newRow("dt zero") << QStringList{"accuracy", scene, "--dt", "0.01,0"}
                                 << "--dt: must be > 0";
        QTest::newRow("dt negative")
            << QStringList{"accuracy", scene, "--dt", "-0.01"} << "--dt: must be > 0";
        QTest::newRow("dt not a number")
            << QStringList{"accuracy", scene, "--dt", "fast"} << "must be a number";
        QTest::newRow("duration") << QStringList{"accuracy", scene, "--duration", "0"}
                                  << "--duration: must be > 0";
        QTest::newRow("unreadable scene")
            << QStringList{"accuracy", dir_.filePath("missing.json")} << "missing.json";
        QTest::newRow("plot type")
            << QStringList{"accuracy", scene, "--plot", dir_.filePath("x.gif")} << ".png or .svg";
        QTest::newRow("unknown option")
            << QStringList{"accuracy", scene, "--fast"} << "unknown option";
        // Issue #38: refused at once as `run` refuses it (it ran unbounded).
        QTest::newRow("dt 1e-10")
            << QStringList{"accuracy", scene, "--dt", "0.01,1e-10", "--duration", "10"}
            << "a run of 10 s at dt = 1e-10 s takes 1e+11 steps; at most 1e+09 are allowed: use "
               "a larger --dt or a shorter --duration";
    }

    void badInputExitsTwo() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const Result r = cli(args);
        QCOMPARE(r.status, 2);
        // Qt may warn on stderr before the command runs (a plot starts a QApplication), so
        // look for the error line rather than at the first line.
        const QString err = QString::fromUtf8(r.err);
        const QStringList errors =
            err.split('\n').filter(QRegularExpression("^phasebox-cli: error: "));
        QVERIFY2(!errors.isEmpty(), qPrintable(err));
        QVERIFY2(errors.join('\n').contains(message), qPrintable(err));
        QVERIFY(r.out.isEmpty());
    }

    void helpSaysDivergenceExitsZero() {
        const Result r = cli({"accuracy", "--help"});
        QCOMPARE(r.status, 0);
        QVERIFY(QString::fromUtf8(r.out).contains("exit status: 0 even when some runs diverged"));
    }
};

QTEST_GUILESS_MAIN(TestCliAccuracy)
#include "tst_cli_accuracy.moc"
