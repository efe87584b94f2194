// phasebox-cli's outputs when writing fails or the target is not a plain file (issue #20,
// CONTRACT.md §4): a failed write exits 3 with the path and the system's reason and keeps an
// earlier file whole; a device or FIFO is written in place, never replaced by a regular file;
// standard output is checked too; an output that is the scene being read, and a scene that is
// a FIFO, device or folder, are refused at once with exit 2; standard error carries only
// "phasebox-cli:" lines.

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include "CliTestSupport.h"
#include "tests/support/OutputTargets.h"

#include <sys/resource.h>
#include <unistd.h>

namespace {

using Result = phasebox::testing::CliResult;
using phasebox::testing::FifoReader;
using phasebox::testing::isFifo;
using phasebox::testing::isStillDevice;
using phasebox::testing::readAll;
using phasebox::testing::SystemDevice;

const char* kBall = R"({
  "format": "phasebox-scene", "version": 1, "name": "ball",
  "simulation": { "integrator": "symplectic_euler", "dt": 0.01, "duration": 0.1 },
  "effects": { "gravity": {} },
  "particles": [ { "id": "ball", "position": [0, 1] } ]
})";

Result cli(const QStringList& args, int timeoutMs = 60000) {
    return phasebox::testing::runCli(args, timeoutMs);
}

// Starts the CLI in p (set up by the caller) and waits up to a minute for it.
Result finish(QProcess& p, const QStringList& args) {
    p.start(QStringLiteral(PHASEBOX_CLI), args);
    Result r;
    if (!p.waitForFinished(60000)) {
        p.kill();
        p.waitForFinished();
        return r;
    }
    r.status = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

// Runs the CLI with a file-size limit (RLIMIT_FSIZE, set in the child between fork and exec)
// and, when given, standard output going to a file. SIGXFSZ keeps its default action in the
// child: the program itself must not die of it.
Result cliLimited(const QStringList& args, rlim_t bytes, const QString& stdoutFile = {}) {
    QProcess p;
    p.setChildProcessModifier([bytes] {
        rlimit limit{};
        ::getrlimit(RLIMIT_FSIZE, &limit);
        limit.rlim_cur = bytes;
        ::setrlimit(RLIMIT_FSIZE, &limit);
    });
    if (!stdoutFile.isEmpty()) p.setStandardOutputFile(stdoutFile);
    return finish(p, args);
}

// Runs the CLI with standard output going to stdoutFile, appended when append is set (the
// shell's `> FILE` and `>> FILE`).
Result cliToFile(const QStringList& args, const QString& stdoutFile, bool append = false) {
    QProcess p;
    p.setStandardOutputFile(stdoutFile, append ? QIODevice::Append : QIODevice::Truncate);
    return finish(p, args);
}

// Every line of standard error is one of phasebox-cli's own.
QString strayStderrLine(const QByteArray& err) {
    for (const QString& line : QString::fromUtf8(err).split(QLatin1Char('\n'), Qt::SkipEmptyParts))
        if (!line.startsWith(QLatin1String("phasebox-cli: "))) return line;
    return {};
}

}  // namespace

class TestCliOutputs : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;
    QString ball_;

    QString write(const QString& name, const QByteArray& bytes) {
        return phasebox::testing::writeFile(dir_, name, bytes);
    }
    // A device that behaves as /dev/full or /dev/null, named name (testing::makeDevice: a
    // private node where mknod is allowed, else a link to the system's device).
    QString device(const QString& name, SystemDevice kind) {
        const QString path = dir_.filePath(name);
        QFile::remove(path);
        return phasebox::testing::makeDevice(path, kind) ? path : QString();
    }
    QString fifo(const QString& name) {
        const QString path = dir_.filePath(name);
        QFile::remove(path);
        return phasebox::testing::makeFifo(path) ? path : QString();
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        ball_ = write("ball.json", kBall);
    }

    // --csv onto a full device: exit 3, the path and ENOSPC's words, and the device is still a
    // device (QSaveFile alone renames a regular file over it).
    void csvOntoFullDeviceExitsThreeAndKeepsTheDevice() {
        const QString full = device("full", SystemDevice::Full);
        QVERIFY(!full.isEmpty());
        const Result r = cli({"run", ball_, "--csv", full});
        QCOMPARE(r.status, 3);
        QCOMPARE(QString::fromUtf8(r.err).trimmed(),
                 QStringLiteral("phasebox-cli: error: %1: cannot write the CSV file: No space "
                                "left on device")
                     .arg(full));
        QVERIFY2(isStillDevice(full, SystemDevice::Full),
                 "the device was replaced by a regular file");
    }

    void plotOntoFullDeviceExitsThree() {
        const QString full = device("full.png", SystemDevice::Full);
        QVERIFY(!full.isEmpty());
        const Result r = cli({"run", ball_, "--plot-energy", full});
        QCOMPARE(r.status, 3);
        QVERIFY2(r.err.contains(": cannot write the plot: No space left on device"),
                 r.err.constData());
        QVERIFY(isStillDevice(full, SystemDevice::Full));
        QCOMPARE(strayStderrLine(r.err), QString());
    }

    void accuracyCsvOntoFullDeviceExitsThree() {
        const QString full = device("full-accuracy", SystemDevice::Full);
        QVERIFY(!full.isEmpty());
        const Result r =
            cli({"accuracy", ball_, "--integrators", "rk4", "--dt", "0.01", "--csv", full});
        QCOMPARE(r.status, 3);
        QVERIFY2(r.err.contains(
                     (full + ": cannot write the CSV file: No space left on device").toUtf8()),
                 r.err.constData());
        QVERIFY(isStillDevice(full, SystemDevice::Full));
    }

    void sceneCommandOntoFullDeviceExitsThree() {
        const QString full = device("full-scene", SystemDevice::Full);
        QVERIFY(!full.isEmpty());
        const Result r = cli({"scene", "pyramid", full});
        QCOMPARE(r.status, 3);
        QVERIFY2(r.err.contains(": cannot write the file: No space left on device"),
                 r.err.constData());
        QVERIFY(isStillDevice(full, SystemDevice::Full));
    }

    // A null device takes everything: exit 0, and it stays a device.
    void csvOntoNullDeviceIsWrittenInPlace() {
        const QString null = device("null", SystemDevice::Null);
        QVERIFY(!null.isEmpty());
        const Result r = cli({"run", ball_, "--csv", null, "--json"});
        QCOMPARE(r.status, 0);
        QVERIFY(isStillDevice(null, SystemDevice::Null));
    }

    // A FIFO gets the CSV and the plot through the pipe, and stays a FIFO.
    void csvAndPlotOntoFifoAreWrittenInPlace() {
        const QString csvPipe = fifo("rows.csv");
        QVERIFY(!csvPipe.isEmpty());
        FifoReader csvReader(csvPipe);
        const Result r = cli({"run", ball_, "--csv", csvPipe});
        const QByteArray rows = csvReader.take();
        QCOMPARE(r.status, 0);
        QVERIFY(isFifo(csvPipe));
        QVERIFY2(rows.startsWith("t,kinetic,potential,work_nc,drift,correction,constraint_error"),
                 rows.left(80).constData());
        QCOMPARE(rows.count('\n'), 12);  // header, t = 0 and 10 steps

        const QString plotPipe = fifo("plot.png");
        QVERIFY(!plotPipe.isEmpty());
        FifoReader plotReader(plotPipe);
        const Result p = cli({"run", ball_, "--plot-energy", plotPipe});
        const QByteArray png = plotReader.take();
        QCOMPARE(p.status, 0);
        QVERIFY(isFifo(plotPipe));
        QVERIFY(png.startsWith("\x89PNG"));
    }

    // Past a file-size limit: exit 3 with EFBIG's words, the earlier file whole, and no
    // temporary copy left behind.
    void csvPastFileSizeLimitKeepsTheEarlierFile() {
        QTemporaryDir dir;
        const QString csv = dir.filePath("out.csv");
        const QByteArray earlier = "an earlier file that must survive\n";
        QVERIFY(phasebox::testing::writeFile(dir, "out.csv", earlier) == csv);
        // 10,000 rows of about 80 bytes: far past 64 KiB.
        const Result r = cliLimited({"run", ball_, "--duration", "100", "--csv", csv}, 64 * 1024);
        QCOMPARE(r.status, 3);
        QCOMPARE(QString::fromUtf8(r.err).trimmed(),
                 QStringLiteral("phasebox-cli: error: %1: cannot write the CSV file: File too "
                                "large")
                     .arg(csv));
        QCOMPARE(readAll(csv), earlier);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"out.csv"});
    }

    void plotPastFileSizeLimitKeepsTheEarlierPlot() {
        QTemporaryDir dir;
        const QString png = dir.filePath("energy.png");
        const QByteArray earlier = "not a png, but the earlier file";
        QVERIFY(phasebox::testing::writeFile(dir, "energy.png", earlier) == png);
        const Result r = cliLimited({"run", ball_, "--plot-energy", png}, 4096);
        QCOMPARE(r.status, 3);
        QVERIFY2(r.err.contains((png + ": cannot write the plot: File too large").toUtf8()),
                 r.err.constData());
        QCOMPARE(readAll(png), earlier);
    }

    // Standard output is checked like any file.
    void standardOutputOntoFullDeviceExitsThree() {
        QProcess p;
        p.setStandardOutputFile(QStringLiteral("/dev/full"));  // written in place, never renamed
        p.start(QStringLiteral(PHASEBOX_CLI), {"run", ball_, "--json"});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 3);
        QCOMPARE(
            QString::fromUtf8(p.readAllStandardError()).trimmed(),
            QStringLiteral("phasebox-cli: error: cannot write to standard output: No space left on "
                           "device"));
    }

    // A reader that goes away (`| head`): a failed write (exit 3, with the reason), not a
    // silent death by SIGPIPE (exit 141).
    void standardOutputToAClosedPipeExitsThree() {
        QProcess p;
        p.start(QStringLiteral("bash"),
                {"-c", QStringLiteral("'%1' run '%2' --duration 100 --csv - | head -c 10 > "
                                      "/dev/null; exit ${PIPESTATUS[0]}")
                           .arg(QStringLiteral(PHASEBOX_CLI), ball_)});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 3);
        QCOMPARE(QString::fromUtf8(p.readAllStandardError()).trimmed(),
                 QStringLiteral("phasebox-cli: error: cannot write to standard output: Broken "
                                "pipe"));
    }

    // Plots need no display: a DISPLAY that cannot be reached does not abort them.
    void plotWithAnUnreachableDisplayIsWritten() {
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("QT_QPA_PLATFORM"));
        env.remove(QStringLiteral("WAYLAND_DISPLAY"));
        env.insert(QStringLiteral("DISPLAY"), QStringLiteral(":99"));
        p.setProcessEnvironment(env);
        const QString png = dir_.filePath("no-display.png");
        p.start(QStringLiteral(PHASEBOX_CLI), {"run", ball_, "--plot-energy", png});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 0);
        QCOMPARE(strayStderrLine(p.readAllStandardError()), QString());
        QVERIFY(QFileInfo(png).size() > 0);
    }

    void standardOutputPastFileSizeLimitExitsThree() {
        QTemporaryDir dir;
        const QString out = dir.filePath("stdout.csv");
        const Result r = cliLimited({"run", ball_, "--duration", "100", "--csv", "-"}, 4096, out);
        QCOMPARE(r.status, 3);
        QCOMPARE(QString::fromUtf8(r.err).trimmed(),
                 QStringLiteral("phasebox-cli: error: cannot write to standard output: File too "
                                "large"));
    }

    // An output that is the scene: refused before anything runs, the scene untouched.
    void outputThatIsTheSceneIsRefused_data() {
        QTest::addColumn<QString>("command");
        QTest::addColumn<QString>("option");
        QTest::addColumn<QString>("spelling");  // how the output names the scene
        for (const char* spelling : {"same", "dot-slash", "symlink", "hardlink"}) {
            QTest::newRow(qPrintable(QStringLiteral("run --csv %1").arg(spelling)))
                << "run"
                << "--csv" << spelling;
            QTest::newRow(qPrintable(QStringLiteral("accuracy --csv %1").arg(spelling)))
                << "accuracy"
                << "--csv" << spelling;
        }
        QTest::newRow("run --plot-energy") << "run"
                                           << "--plot-energy"
                                           << "same";
        QTest::newRow("run --plot-phase") << "run"
                                          << "--plot-phase"
                                          << "same";
        QTest::newRow("accuracy --plot") << "accuracy"
                                         << "--plot"
                                         << "same";
    }

    void outputThatIsTheSceneIsRefused() {
        QFETCH(QString, command);
        QFETCH(QString, option);
        QFETCH(QString, spelling);
        QTemporaryDir dir;
        // A scene whose name is also a plot's, so that the plot options reach the check.
        const QString scene = dir.filePath("lesson.svg");
        QVERIFY(phasebox::testing::writeFile(dir, "lesson.svg", kBall) == scene);
        QString output = scene;
        if (spelling == "dot-slash") output = dir.path() + "/./lesson.svg";
        if (spelling == "symlink") {
            output = dir.filePath("link.svg");
            QVERIFY(QFile::link(scene, output));
        }
        if (spelling == "hardlink") {
            output = dir.filePath("hard.svg");
            QCOMPARE(
                ::link(QFile::encodeName(scene).constData(), QFile::encodeName(output).constData()),
                0);
        }
        QStringList args{command, scene, "--duration", "100000"};
        if (option == "--plot-phase")
            args << option << "ball.x" << output;
        else
            args << option << output;
        const Result r = cli(args, 30000);
        QCOMPARE(r.status, 2);
        QCOMPARE(QString::fromUtf8(r.err).trimmed(),
                 QStringLiteral("phasebox-cli: error: %1 %2: that is the scene file being read; "
                                "writing it would destroy the scene. Choose another file")
                     .arg(option, output));
        QCOMPARE(readAll(scene), QByteArray(kBall));
        QVERIFY2(r.seconds < 10.0, "refused before the 10-million-step run started");
    }

    void twoOutputsOntoOneFileAreRefused() {
        const QString png = dir_.filePath("both.png");
        const Result r =
            cli({"run", ball_, "--plot-energy", png, "--plot-phase", "ball.y", png}, 30000);
        QCOMPARE(r.status, 2);
        QCOMPARE(QString::fromUtf8(r.err).trimmed(),
                 QStringLiteral("phasebox-cli: error: --plot-energy and --plot-phase both write "
                                "%1; give each its own file")
                     .arg(png));
        QVERIFY(!QFileInfo::exists(png));
    }

    // Issue #38: `run --csv /dev/stdout > out.csv` opened out.csv a second time at offset 0,
    // and the summary, written through standard output, overwrote the CSV's head. A path that
    // is standard output (by name, through /proc/self/fd/1, or the very file `>` opened) is
    // standard output: the CSV alone, whole, and no summary.
    void csvOntoStandardOutputByAnotherNameIsNotOverwritten_data() {
        QTest::addColumn<QString>("spelling");
        QTest::newRow("/dev/stdout") << "/dev/stdout";
        QTest::newRow("/proc/self/fd/1") << "/proc/self/fd/1";
        QTest::newRow("the file itself") << "file";
    }
    void csvOntoStandardOutputByAnotherNameIsNotOverwritten() {
        QFETCH(QString, spelling);
        const QString out = dir_.filePath("stdout.csv");
        const QString csv = spelling == "file" ? out : spelling;
        const Result r = cliToFile({"run", ball_, "--csv", csv}, out);
        QCOMPARE(r.status, 0);
        const QByteArray text = readAll(out);
        QVERIFY2(text.startsWith("t,kinetic,potential,work_nc,drift,correction,constraint_error,"),
                 text.left(200).constData());
        QVERIFY2(!text.contains("scene:"), "the summary went into the CSV");
        QCOMPARE(text.count('\n'), 12);  // the header, t = 0 and ten steps
    }

    // Two outputs on the one standard output (`--json` and `--csv /proc/self/fd/1`): refused.
    void twoOutputsOntoStandardOutputAreRefused() {
        const Result r = cli({"run", ball_, "--json", "--csv", "/proc/self/fd/1"}, 30000);
        QCOMPARE(r.status, 2);
        QCOMPARE(QString::fromUtf8(r.err).trimmed(),
                 QStringLiteral("phasebox-cli: error: --json and --csv /proc/self/fd/1 both write "
                                "to standard output; give --csv a file"));
    }

    // A symbolic link that leads to itself was replaced by a regular file (exit 0): refused
    // before anything runs, and the link stays.
    void outputThatIsASymlinkLoopIsRefused() {
        const QString loop = dir_.filePath("loop.csv");
        QFile::remove(loop);
        QCOMPARE(::symlink("loop.csv", QFile::encodeName(loop).constData()), 0);
        const Result r = cli({"run", ball_, "--csv", loop}, 30000);
        QCOMPARE(r.status, 2);
        QCOMPARE(QString::fromUtf8(r.err).trimmed(),
                 QStringLiteral("phasebox-cli: error: --csv %1: it is a loop of symbolic links "
                                "(too many levels); it would be replaced by a regular file")
                     .arg(loop));
        QVERIFY(QFileInfo(loop).isSymLink());
        const Result scene = cli({"scene", "pyramid", loop}, 30000);
        QCOMPARE(scene.status, 2);
        QVERIFY(QFileInfo(loop).isSymLink());
    }

    // Standard output appended to the scene (`>> scene.json`): the summary would be added to
    // the scene. Refused, the scene byte for byte.
    void standardOutputThatIsTheSceneIsRefused() {
        const QString scene = write("appended.json", kBall);
        for (const char* command : {"run", "accuracy", "info"}) {
            const Result r = cliToFile({QString::fromLatin1(command), scene}, scene, true);
            QCOMPARE(r.status, 2);
            QCOMPARE(QString::fromUtf8(r.err).trimmed(),
                     QStringLiteral("phasebox-cli: error: standard output is the scene file being "
                                    "read (%1); writing it would destroy the scene. Send the "
                                    "output elsewhere")
                         .arg(scene));
            QCOMPARE(readAll(scene), QByteArray(kBall));
        }
    }

    // `scene NAME ''` and `accuracy --csv ''`: an empty name is refused (exit 2).
    void emptyOutputNameIsRefused() {
        const Result scene = cli({"scene", "pyramid", ""}, 30000);
        QCOMPARE(scene.status, 2);
        QCOMPARE(QString::fromUtf8(scene.err).trimmed(),
                 QStringLiteral("phasebox-cli: error: scene FILE: the file name is empty; give a "
                                "file, or - for standard output"));
        const Result accuracy = cli({"accuracy", ball_, "--csv", ""}, 30000);
        QCOMPARE(accuracy.status, 2);
        const Result twice = cli({"accuracy", ball_, "--plot", "a.png", "--plot", "b.png"}, 30000);
        QCOMPARE(twice.status, 2);
        QCOMPARE(QString::fromUtf8(twice.err).trimmed(),
                 QStringLiteral("phasebox-cli: error: --plot given twice; each output is written "
                                "once, give it one file"));
    }

    // A disk that fills during a long run: the run stops at the failed write (exit 3 within
    // seconds), not at its end, a billion steps later.
    void csvOntoFullDeviceStopsALongRunPromptly() {
        const QString full = device("full-long", SystemDevice::Full);
        QVERIFY(!full.isEmpty());
        const Result r =
            cli({"run", ball_, "--dt", "0.001", "--duration", "1000000", "--csv", full}, 30000);
        QCOMPARE(r.status, 3);
        QCOMPARE(QString::fromUtf8(r.err).trimmed(),
                 QStringLiteral("phasebox-cli: error: %1: cannot write the CSV file: No space "
                                "left on device")
                     .arg(full));
    }

    // A FIFO, a device or a folder as the scene: refused at once (a FIFO with no writer used to
    // block the open for ever; /dev/zero would be read without end).
    void sceneThatIsNotAFileIsRefusedAtOnce_data() {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("what");
        QTest::newRow("fifo") << "fifo"
                              << "it is a FIFO (named pipe), not a scene file";
        QTest::newRow("device") << "device"
                                << "it is a device, not a scene file";
        QTest::newRow("folder") << "folder"
                                << "it is a folder";
    }

    void sceneThatIsNotAFileIsRefusedAtOnce() {
        QFETCH(QString, kind);
        QFETCH(QString, what);
        QString path;
        if (kind == "fifo") path = fifo("scene-fifo.json");
        if (kind == "device") path = QStringLiteral("/dev/zero");
        if (kind == "folder") path = dir_.path();
        QVERIFY(!path.isEmpty());
        for (const char* command : {"info", "run", "accuracy"}) {
            const Result r = cli({QString::fromLatin1(command), path}, 15000);
            QVERIFY2(r.status == 2, qPrintable(QStringLiteral("%1: status %2 (-1: it hung)")
                                                   .arg(QLatin1String(command))
                                                   .arg(r.status)));
            QCOMPARE(QString::fromUtf8(r.err).trimmed(),
                     QStringLiteral("phasebox-cli: error: %1: cannot read the file: %2")
                         .arg(path, what));
            QVERIFY(r.seconds < 10.0);
        }
    }

    // Qt's own warnings (the offscreen platform, XDG_RUNTIME_DIR) never reach standard error.
    void standardErrorCarriesOnlyPrefixedLines() {
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("XDG_RUNTIME_DIR"));
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        p.setProcessEnvironment(env);
        const QString png = dir_.filePath("quiet.png");
        p.start(QStringLiteral(PHASEBOX_CLI),
                {"run", ball_, "--plot-energy", png, "--plot-phase", "ball.y",
                 dir_.filePath("quiet-phase.svg"), "--json"});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        const QByteArray err = p.readAllStandardError();
        QCOMPARE(strayStderrLine(err), QString());
        QVERIFY(QFileInfo(png).size() > 0);
        // And with an error: still only our lines.
        const Result bad = cli({"run", dir_.filePath("missing.json"), "--plot-energy", png});
        QCOMPARE(bad.status, 2);
        QCOMPARE(strayStderrLine(bad.err), QString());
    }
};

QTEST_GUILESS_MAIN(TestCliOutputs)
#include "tst_cli_outputs.moc"
