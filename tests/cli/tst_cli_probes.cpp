// phasebox-cli run --probe (CONTRACT §7) through the real binary: the CSV's probe columns
// (quoted as CSV asks, after the tracked objects, in command-line order), the JSON statistics
// with the period of a mass on a spring against 2π·√(m/k), and an unknown probe refused with
// the vocabulary.

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "CliTestSupport.h"

#include <cmath>
#include <numbers>

namespace {

using Result = phasebox::testing::CliResult;

Result cli(const QStringList& args) {
    return phasebox::testing::runCli(args);
}

// m = 1 kg on a spring of k = 4 N/m to the origin (rest length 0), released at x = 1 m: period
// 2π·√(m/k) = π s; the run is ten periods. A pinned post sits at (4, 4).
const char* kSpring = R"({
  "format": "phasebox-scene", "version": 1, "name": "spring",
  "simulation": { "integrator": "rk4", "dt": 0.01, "duration": 31.4159265358979 },
  "particles": [ { "id": "ball", "position": [1, 0], "mass": 1 },
                 { "id": "post", "position": [4, 4], "pinned": true } ],
  "springs": [ { "a": "ball", "anchor": [0, 0], "stiffness": 4, "rest_length": 0 } ]
})";

constexpr const char* kHeader =
    "t,kinetic,potential,work_nc,drift,correction,constraint_error,"
    "ball.x,ball.y,ball.vx,ball.vy,post.x,post.y,post.vx,post.vy";

}  // namespace

class TestCliProbes : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;

    QString write(const QString& name, const char* text) {
        return phasebox::testing::writeFile(dir_, name, text);
    }

private slots:
    void csvHasOneQuotedColumnPerProbe() {
        const Result r =
            cli({"run", write("spring.json", kSpring), "--duration", "0.05", "--csv", "-",
                 "--probe", "distance(ball,post)", "--probe", "ball.x", "--probe", "system.px"});
        QCOMPARE(r.status, 0);
        QVERIFY2(r.err.isEmpty(), r.err.constData());
        const QStringList lines = QString::fromUtf8(r.out).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1 + 6);  // header, t = 0 and five steps
        QCOMPARE(lines[0], QString::fromLatin1(kHeader) +
                               QStringLiteral(",\"distance(ball,post)\",ball.x,system.px"));
        for (int i = 1; i < lines.size(); ++i) {
            const QStringList v = lines[i].split(',');
            QCOMPARE(v.size(), 15 + 3);
            const double x = v[7].toDouble(), y = v[8].toDouble(), vx = v[9].toDouble();
            // The probe columns against the tracked ones and the geometry: the post is pinned
            // at (4, 4), so it adds no momentum.
            QCOMPARE(v[15].toDouble(), std::hypot(4.0 - x, 4.0 - y));
            QCOMPARE(v[16], v[7]);
            QCOMPARE(v[17].toDouble(), vx);
        }
        QCOMPARE(lines[1].split(',')[15].toDouble(), 5.0);

        // --every thins the rows, not the columns; the probe's text is the header as given.
        const Result thin =
            cli({"run", write("spring.json", kSpring), "--duration", "0.05", "--csv", "-",
                 "--every", "2", "--track", "ball", "--probe", "angle( post , ball,post )"});
        QCOMPARE(thin.status, 0);
        const QStringList rows = QString::fromUtf8(thin.out).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(rows.size(), 1 + 4);  // t = 0, steps 2 and 4, the last step
        QVERIFY2(rows[0].endsWith(QStringLiteral("ball.vy,\"angle( post , ball,post )\"")),
                 qPrintable(rows[0]));
        QCOMPARE(rows[1].split(',').last().toDouble(), 0.0);
    }

    void jsonReportsStatisticsAndThePeriod() {
        const Result r = cli({"run", write("spring.json", kSpring), "--json", "--probe", "ball.x",
                              "--probe", "post.x", "--probe", "system.total"});
        QCOMPARE(r.status, 0);
        const QJsonObject report = QJsonDocument::fromJson(r.out).object();
        const QJsonObject probes = report["probes"].toObject();
        QCOMPARE(probes.keys(), (QStringList{"ball.x", "post.x", "system.total"}));

        const QJsonObject x = probes["ball.x"].toObject();
        const double expected = 2.0 * std::numbers::pi * std::sqrt(1.0 / 4.0);
        QVERIFY(x["period"].isDouble());
        const double period = x["period"].toDouble();
        qInfo(
            "ball.x: period %.9f s, 2pi*sqrt(m/k) %.9f s (relative error %.2e); min %.6f, "
            "max %.6f, mean %.2e, final %.6f",
            period, expected, period / expected - 1.0, x["min"].toDouble(), x["max"].toDouble(),
            x["mean"].toDouble(), x["final"].toDouble());
        QVERIFY(std::abs(period / expected - 1.0) < 1e-3);
        QCOMPARE(x["max"].toDouble(), 1.0);  // the start
        QVERIFY(std::abs(x["min"].toDouble() + 1.0) < 1e-3);
        QVERIFY(std::abs(x["mean"].toDouble()) < 1e-2);  // ten whole periods
        // final is the state the report shows: the same x as `objects`.
        QCOMPARE(x["final"].toDouble(),
                 report["objects"]["ball"]["position"].toArray().at(0).toDouble());
        QVERIFY(std::abs(x["final"].toDouble() - std::cos(2.0 * 31.4159265358979)) < 1e-3);

        // A pinned post does not move: every statistic is its x, and no period.
        const QJsonObject post = probes["post.x"].toObject();
        for (const char* key : {"final", "min", "max", "mean"}) QCOMPARE(post[key].toDouble(), 4.0);
        QVERIFY(post.contains("period") && post["period"].isNull());

        // The ledger's total: 2 J (½·k·x0²) throughout, RK4's drift aside.
        const QJsonObject total = probes["system.total"].toObject();
        QVERIFY(std::abs(total["max"].toDouble() - 2.0) < 1e-6);
        QVERIFY(std::abs(total["min"].toDouble() - 2.0) < 1e-6);

        // The human summary lists them too.
        const Result text = cli({"run", write("spring.json", kSpring), "--probe", "ball.x"});
        QCOMPARE(text.status, 0);
        QVERIFY2(text.out.contains("probe ball.x: final "), text.out.constData());
        QVERIFY(text.out.contains(", period 3.14"));
    }

    void unknownProbeIsRefusedWithTheVocabulary() {
        const QString csv = dir_.filePath("never.csv");
        const Result r = cli({"run", write("spring.json", kSpring), "--csv", csv, "--probe",
                              "ball.x", "--probe", "ball.z"});
        QCOMPARE(r.status, 2);
        QVERIFY(r.out.isEmpty());
        const QString err = QString::fromUtf8(r.err);
        QVERIFY2(
            err.startsWith("phasebox-cli: error: unknown probe \"ball.z\"; known: ID.x, ID.y, "),
            qPrintable(err));
        for (const char* form :
             {"ID.speed", "ID.omega", "ID.L", "system.kinetic", "system.work_nc", "system.com_x",
              "distance(A,B)", "angle(A,B,C)", "force(JOINT)", "contact_force(ID)"})
            QVERIFY2(err.contains(QLatin1String(form)), form);
        QCOMPARE(err.count('\n'), 1);  // one line
        QVERIFY(!QFile::exists(csv));  // refused before anything was written

        const Result ghost = cli({"run", write("spring.json", kSpring), "--probe", "ghost.x"});
        QCOMPARE(ghost.status, 2);
        QVERIFY2(
            ghost.err.startsWith(
                "phasebox-cli: error: unknown probe \"ghost.x\": no object \"ghost\"; known: "),
            ghost.err.constData());
        const Result missing = cli({"run", write("spring.json", kSpring), "--probe"});
        QCOMPARE(missing.status, 2);
        QVERIFY(missing.err.contains("--probe needs a value"));
    }

    void helpListsTheProbes() {
        const Result r = cli({"run", "--help"});
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.contains("--probe EXPR"));
        QVERIFY(r.out.contains("contact_force(ID)"));
    }
};

QTEST_GUILESS_MAIN(TestCliProbes)
#include "tst_cli_probes.moc"
