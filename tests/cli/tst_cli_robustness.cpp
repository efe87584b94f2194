// phasebox-cli under bad input: every option with values it must refuse (zero, negative, NaN,
// infinite, absurdly large, missing, unknown), broken scene files, and runs that would never
// end. Each case exits with status 2 and the exact message within seconds, never hangs; a
// diverging run exits 1 naming the object, the time and what to try.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include "CliTestSupport.h"

#include <cmath>

namespace {

using Result = phasebox::testing::CliResult;

// The first line phasebox-cli itself wrote to standard error (Qt may warn before it, e.g.
// about XDG_RUNTIME_DIR when a plot option brings up the GUI libraries).
QString firstMessage(const QByteArray& err) {
    for (const QString& line : QString::fromUtf8(err).split(QLatin1Char('\n')))
        if (line.startsWith(QLatin1String("phasebox-cli:"))) return line;
    return QString::fromUtf8(err);
}

// With a shorter timeout than the other suites: nothing here may take long.
Result cli(const QStringList& args, int timeoutMs = 60000) {
    return phasebox::testing::runCli(args, timeoutMs);
}

const char* kBall = R"({
  "format": "phasebox-scene", "version": 1, "name": "ball",
  "simulation": { "integrator": "symplectic_euler", "dt": 0.01, "duration": 0.1 },
  "effects": { "gravity": {} },
  "particles": [ { "id": "ball", "position": [0, 1] } ]
})";

// k = 1e6 with m = 1 at dt = 1/60 under explicit Euler: blows up within a few steps.
const char* kStiff = R"({
  "format": "phasebox-scene", "version": 1, "name": "stiff",
  "simulation": { "integrator": "explicit_euler", "dt": 0.016666666666666666, "duration": 10 },
  "particles": [ { "id": "bob", "position": [0, -1.1], "mass": 1 } ],
  "springs": [ { "a": "bob", "anchor": [0, 0], "stiffness": 1e6, "rest_length": 1 } ]
})";

}  // namespace

class TestCliRobustness : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;
    QString ball_, stiff_;

    QString write(const QString& name, const QByteArray& bytes) {
        return phasebox::testing::writeFile(dir_, name, bytes);
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        ball_ = write("ball.json", kBall);
        stiff_ = write("stiff.json", kStiff);
    }

    void badOptionsExitTwo_data() {
        QTest::addColumn<QStringList>("args");  // after "run BALL"
        QTest::addColumn<QString>("expected");  // the whole first line of standard error
        auto row = [](const char* name, QStringList args, const QString& message) {
            QTest::newRow(name) << args << QStringLiteral("phasebox-cli: error: ") + message;
        };
        row("dt 0", {"--dt", "0"}, "--dt: must be > 0 and <= 1 (got 0)");
        row("dt -1", {"--dt", "-1"}, "--dt: must be > 0 and <= 1 (got -1)");
        row("dt 2", {"--dt", "2"}, "--dt: must be > 0 and <= 1 (got 2)");
        row("dt nan", {"--dt", "nan"}, "--dt: must be a number (got \"nan\")");
        row("dt inf", {"--dt", "inf"}, "--dt: must be a number (got \"inf\")");
        row("dt 1e-400", {"--dt", "1e-400"}, "--dt: must be a number (got \"1e-400\")");
        row("dt text", {"--dt", "fast"}, "--dt: must be a number (got \"fast\")");
        row("dt empty", {"--dt", ""}, "--dt: must be a number (got \"\")");
        row("substeps 0", {"--substeps", "0"}, "--substeps: must be >= 1 and <= 10000 (got 0)");
        row("substeps -3", {"--substeps", "-3"}, "--substeps: must be >= 1 and <= 10000 (got -3)");
        row("substeps 10001", {"--substeps", "10001"},
            "--substeps: must be >= 1 and <= 10000 (got 10001)");
        row("substeps 1e3", {"--substeps", "1e3"}, "--substeps: must be an integer (got \"1e3\")");
        row("substeps 2^40", {"--substeps", "1099511627776"},
            "--substeps: must be an integer (got \"1099511627776\")");
        row("every 0", {"--every", "0"}, "--every: must be >= 1 (got 0)");
        row("every -1", {"--every", "-1"}, "--every: must be >= 1 (got -1)");
        row("every nan", {"--every", "nan"}, "--every: must be an integer (got \"nan\")");
        row("duration 0", {"--duration", "0"}, "--duration: must be > 0 and <= 1000000 (got 0)");
        row("duration -5", {"--duration", "-5"}, "--duration: must be > 0 and <= 1000000 (got -5)");
        row("duration 1e300", {"--duration", "1e300"},
            "--duration: must be > 0 and <= 1000000 (got 1e300)");
        row("duration inf", {"--duration", "inf"}, "--duration: must be a number (got \"inf\")");
        row("too many steps", {"--duration", "1000000", "--dt", "1e-9"},
            "a run of 1000000 s at dt = 1e-09 s takes 1e+15 steps; at most 1e+09 are allowed: use "
            "a "
            "larger --dt or a shorter --duration");
        row("tolerance 0", {"--tolerance", "0"}, "--tolerance: must be > 0 (got 0)");
        row("tolerance nan", {"--tolerance", "NaN"}, "--tolerance: must be a number (got \"NaN\")");
        row("integrator rk5", {"--integrator", "rk5"},
            "--integrator: unknown integrator \"rk5\"; known: explicit_euler, symplectic_euler, "
            "midpoint, heun, rk4, velocity_verlet, implicit_euler, implicit_midpoint, "
            "adaptive_euler, rk45");
        row("unknown option", {"--frobnicate"},
            "unknown option \"--frobnicate\"; see phasebox-cli run --help");
        row("single dash option", {"--", "x"},
            "unknown option \"--\"; see phasebox-cli run --help");
        row("missing value at the end", {"--dt"}, "--dt needs a value");
        row("missing plot-phase file", {"--plot-phase", "ball.x"},
            "--plot-phase needs ID.COORD and FILE");
        row("second scene", {"other.json"},
            "unexpected argument \"other.json\" (the scene is \"BALL\")");
        row("json and csv on stdout", {"--json", "--csv", "-"},
            "--json and --csv - both write to standard output; give --csv a file");
        // Issue #38: an empty output name was ignored (exit 0), a repeated output option kept
        // only the last one.
        row("csv empty", {"--csv", ""},
            "--csv: the file name is empty; give a file, or - for standard output");
        row("plot-energy empty", {"--plot-energy", ""},
            "--plot-energy: the file name is empty; give a file, or - for standard output");
        row("csv twice", {"--csv", "a.csv", "--csv", "b.csv"},
            "--csv given twice; each output is written once, give it one file");
        row("plot-energy twice", {"--plot-energy", "a.png", "--plot-energy", "b.png"},
            "--plot-energy given twice; each output is written once, give it one file");
        row("plot-phase twice",
            {"--plot-phase", "ball.x", "a.png", "--plot-phase", "ball.y", "b.png"},
            "--plot-phase given twice; each output is written once, give it one file");
        row("json and csv /dev/stdout", {"--json", "--csv", "/dev/stdout"},
            "--json and --csv /dev/stdout both write to standard output; give --csv a file");
        row("unknown track id", {"--track", "ghost"}, "--track: unknown object id \"ghost\"");
        row("phase of nothing", {"--plot-phase", "ghost.x", "p.png"},
            "--plot-phase: unknown object \"ghost.x\" (expected ID.COORD, e.g. ball.x)");
    }

    void badOptionsExitTwo() {
        QFETCH(QStringList, args);
        QFETCH(QString, expected);
        expected.replace(QLatin1String("BALL"), ball_);
        const Result r = cli(QStringList{"run", ball_} + args, 30000);
        QVERIFY2(r.status == 2, qPrintable(QStringLiteral("status %1, stderr: %2")
                                               .arg(r.status)
                                               .arg(QString::fromUtf8(r.err))));
        QCOMPARE(firstMessage(r.err), expected);
        QVERIFY2(r.seconds < 20.0, "refusing an option must not take long");
    }

    void badCommandLines_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("expected");
        QTest::newRow("run without scene")
            << QStringList{"run"} << "phasebox-cli: error: run needs a SCENE file";
        QTest::newRow("unknown command")
            << QStringList{"explode"}
            << "phasebox-cli: error: unknown command \"explode\"; known: "
               "integrators, info, run, scene, accuracy";
        QTest::newRow("integrators with args")
            << QStringList{"integrators", "x"}
            << "phasebox-cli: error: integrators takes no arguments";
        QTest::newRow("info without scene")
            << QStringList{"info"} << "phasebox-cli: error: usage: phasebox-cli info SCENE";
        QTest::newRow("scene unknown") << QStringList{"scene", "nothing"}
                                       << "phasebox-cli: error: unknown scene \"nothing\"; known: ";
    }

    void badCommandLines() {
        QFETCH(QStringList, args);
        QFETCH(QString, expected);
        const Result r = cli(args, 30000);
        QCOMPARE(r.status, 2);
        QVERIFY2(QString::fromUtf8(r.err).startsWith(expected),
                 qPrintable(QString::fromUtf8(r.err)));
    }

    void badSceneFilesExitTwo_data() {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("expected");  // after "phasebox-cli: error: PATH"
        QTest::newRow("empty") << QByteArray() << ": the file is empty";
        QTest::newRow("NaN")
            << QByteArray(
                   R"({"format": "phasebox-scene", "version": 1, "simulation": {"dt": NaN}})")
            << ":1:65: illegal number: NaN is not a number JSON allows; write a finite number";
        QTest::newRow("binary")
            << QByteArray(
                   "\x7f"
                   "ELF\x02\x01\x01\0",
                   8)
            << ":1:5: binary data (byte 0x02), not UTF-8 JSON text: is this a scene file?";
        QTest::newRow("truncated")
            << QByteArray(R"({"format": "phasebox-scene", "version": 1, "particles": [)")
            << ":1:58: the file ends before the JSON is complete (is it truncated?)";
        QTest::newRow("mass 1e300")
            << QByteArray(
                   R"({"format": "phasebox-scene", "version": 1, "particles": [{"position": [0, 0], "mass": 1e300}]})")
            << ": particles[0].mass: must be <= 1e12 (got 1e300)";
        QTest::newRow("duration 1e300")
            << QByteArray(
                   R"({"format": "phasebox-scene", "version": 1, "simulation": {"duration": 1e300}})")
            << ": simulation.duration: must be <= 1e6 (got 1e300)";
        // Issue #38: simulation.sleep took any value; it is a boolean (CONTRACT §6).
        QTest::newRow("sleep a string")
            << QByteArray(
                   R"({"format": "phasebox-scene", "version": 2, "simulation": {"sleep": "yes"}})")
            << ": simulation.sleep: must be true or false";
        QTest::newRow("sleep a number")
            << QByteArray(
                   R"({"format": "phasebox-scene", "version": 2, "simulation": {"sleep": 1}})")
            << ": simulation.sleep: must be true or false";
        // Issue #38: Qt calls a comment or a single-quoted string an "unterminated object"
        // somewhere after it, and drops the backslash of an invalid escape ("C:\lessons" read
        // as "C:lessons"). Each is named where it starts.
        QTest::newRow("line comment") << QByteArray(
                                             "{\"format\": \"phasebox-scene\", \"version\": 1,\n"
                                             "  // the ball\n  \"particles\": []}")
                                      << ":2:3: JSON has no comments; remove the // comment";
        QTest::newRow("block comment")
            << QByteArray("{\"format\": \"phasebox-scene\", /* v1 */ \"version\": 1}")
            << ":1:30: JSON has no comments; remove the /* */ comment";
        QTest::newRow("comment after the object")
            << QByteArray("{\"format\": \"phasebox-scene\", \"version\": 1}\n// end\n")
            << ":2:1: JSON has no comments; remove the // comment";
        QTest::newRow("single-quoted value")
            << QByteArray("{\"format\": 'phasebox-scene', \"version\": 1}")
            << ":1:12: strings take double quotes (\"...\"), not single quotes";
        QTest::newRow("single-quoted key")
            << QByteArray("{\"format\": \"phasebox-scene\",\n 'version': 1}")
            << ":2:2: strings take double quotes (\"...\"), not single quotes";
        QTest::newRow("invalid escape")
            << QByteArray(R"({"format": "phasebox-scene", "version": 1, "name": "C:\lessons"})")
            << ":1:55: invalid escape \\l; write \\\\ for a backslash";
        QTest::newRow("invalid unicode escape")
            << QByteArray(R"({"format": "phasebox-scene", "version": 1, "name": "\u12"})")
            << ":1:53: invalid escape \\u: it takes four hexadecimal digits (\\u00e9)";
        // Issue #38: polygons have the boxes' size floor (1 µm across); a 1e-9 triangle loaded
        // and diverged. A polygon's size is its width, its least extent across (a box's is its
        // shorter side), here the height of a 2e-9 x 1e-9 triangle.
        QTest::newRow("polygon 1e-9")
            << QByteArray(
                   R"({"format": "phasebox-scene", "version": 2, "polygons": [{"position": [0, 0], "vertices": [[-1e-9, 0], [1e-9, 0], [0, 1e-9]]}]})")
            << ": polygons[0].vertices: the polygon is too small: its width is 1e-9 m; it must "
               "be at least 1e-6 m across, as a box's sides must";
    }

    void badSceneFilesExitTwo() {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, expected);
        const QString path = write(
            QStringLiteral("bad-%1.json").arg(QTest::currentDataTag()).replace(' ', '-'), bytes);
        for (const char* command : {"run", "info"}) {
            const Result r = cli({QString::fromLatin1(command), path}, 30000);
            QCOMPARE(r.status, 2);
            QCOMPARE(firstMessage(r.err),
                     QStringLiteral("phasebox-cli: error: ") + path + expected);
        }
    }

    // Issue #38: `accuracy --duration 1e7` blamed the scene file (simulation.duration); the
    // message names the option.
    void accuracyDurationOutOfRangeNamesTheOption() {
        const Result r = cli({"accuracy", ball_, "--duration", "1e7"}, 30000);
        QCOMPARE(r.status, 2);
        QCOMPARE(
            firstMessage(r.err),
            QStringLiteral("phasebox-cli: error: --duration: must be > 0 and <= 1e6 (got 1e7)"));
    }

    // An output that cannot be written is exit 3 (CONTRACT §4), not bad input.
    void unwritableCsvExitsThree() {
        const QString plain = write("plain.txt", "a file, not a folder");
        const Result r = cli({"run", ball_, "--csv", plain + "/out.csv"}, 30000);
        QCOMPARE(r.status, 3);
        QVERIFY2(r.err.startsWith("phasebox-cli: error: " +
                                  (plain + "/out.csv: cannot write the CSV file: ").toUtf8()),
                 r.err.constData());
        QCOMPARE(QFile(plain).size(), qint64(20));
    }

    void divergenceExitsOneNamingObjectTimeAndRemedy() {
        const Result r = cli({"run", stiff_}, 60000);
        QCOMPARE(r.status, 1);
        const QString err = QString::fromUtf8(r.err);
        QVERIFY2(err.startsWith(
                     QStringLiteral("phasebox-cli: diverged: the simulation diverged at t = ")),
                 qPrintable(err));
        for (const char* part : {"in object \"bob\"", "the state was restored to t = ",
                                 "smaller dt", "more sub-steps", "implicit integrator"})
            QVERIFY2(err.contains(QLatin1String(part)),
                     qPrintable(QStringLiteral("missing \"%1\" in: %2").arg(part, err)));

        // --json: the same facts as fields, and the reported state is the last good one.
        const Result j = cli({"run", stiff_, "--json"}, 60000);
        QCOMPARE(j.status, 1);
        const QJsonObject report = QJsonDocument::fromJson(j.out).object();
        QVERIFY(report.value("diverged").toBool());
        const QJsonObject d = report.value("divergence").toObject();
        QCOMPARE(d.value("object").toString(), QStringLiteral("bob"));
        QVERIFY(d.value("time").toDouble() > 0.0);
        QVERIFY(d.value("restored_time").toDouble() < d.value("time").toDouble());
        QCOMPARE(report.value("sim_time").toDouble(), d.value("restored_time").toDouble());
        // steps and sim_time describe the same (restored) state.
        QCOMPARE(report.value("steps").toDouble() * report.value("dt").toDouble(),
                 report.value("sim_time").toDouble());
        const QJsonObject bob = report.value("objects").toObject().value("bob").toObject();
        for (const char* key : {"position", "velocity"})
            for (const QJsonValue v : bob.value(key).toArray())
                QVERIFY(std::isfinite(v.toDouble()));
    }

    void longestAllowedRunStartsAndCanBeStopped() {
        // A legal but long run (1e6 s at dt = 1e-3: a billion steps) is accepted; what matters
        // here is that it neither allocates per step up front nor refuses. It is stopped after a
        // moment; its memory after a second stays small.
        QProcess p;
        p.start(QStringLiteral(PHASEBOX_CLI),
                {"run", ball_, "--duration", "1000000", "--dt", "0.001"});
        QVERIFY(p.waitForStarted());
        QTest::qWait(1500);
        QCOMPARE(p.state(), QProcess::Running);
        QFile status(QStringLiteral("/proc/%1/status").arg(p.processId()));
        qint64 rssKb = -1;
        if (status.open(QIODevice::ReadOnly))
            for (const QByteArray& line : status.readAll().split('\n'))
                if (line.startsWith("VmRSS:"))
                    rssKb = line.mid(6).trimmed().split(' ').first().toLongLong();
        p.kill();
        p.waitForFinished();
        qInfo("a 1e9-step run after 1.5 s: resident %lld kB", rssKb);
        QVERIFY(rssKb > 0);
        QVERIFY2(rssKb < 1024 * 1024,
                 "memory reserved for every step up front?");  // ASan builds are larger
    }
};

QTEST_GUILESS_MAIN(TestCliRobustness)
#include "tst_cli_robustness.moc"
