// phasebox-cli render (CONTRACT.md §8): the clips are probed with ffprobe (Debian's ffmpeg) for
// their codec, frame count, duration and size; a GIF's delays add up to the duration; an
// unknown extension is refused with the formats (exit 2); a write that fails (a missing folder,
// a full device) exits 3 and Ctrl-C exits 130, both leaving no partial file and an earlier file
// whole; a FIFO is written in place.

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include "CliTestSupport.h"
#include "tests/support/OutputTargets.h"

#include <csignal>

namespace {

using phasebox::testing::CliResult;
using phasebox::testing::runCli;
using phasebox::testing::writeFile;

// A ball bouncing on the ground beside a spring oscillator: something moves in every frame.
const char* kScene = R"({
  "format": "phasebox-scene", "version": 1, "name": "bounce",
  "simulation": { "integrator": "symplectic_euler", "dt": 0.01, "duration": 1 },
  "effects": { "gravity": {} },
  "particles": [ { "id": "ball", "position": [0, 1], "radius": 0.1, "restitution": 0.8 },
                 { "id": "bob", "position": [1.5, 0.5], "radius": 0.08 } ],
  "planes": [ { "id": "ground", "point": [0, 0], "normal": [0, 1] } ],
  "springs": [ { "a": "bob", "anchor": [1.5, 1.5], "stiffness": 40, "rest_length": 0.6 } ]
})";

// ffprobe's JSON for the first video stream, its frames counted by decoding them.
QJsonObject probe(const QString& path) {
    QProcess p;
    p.start(QStringLiteral("ffprobe"),
            {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
             "stream=codec_name,width,height,nb_read_frames,duration:format=duration,format_name",
             "-of", "json", path});
    if (!p.waitForFinished(60000) || p.exitCode() != 0) return {};
    return QJsonDocument::fromJson(p.readAllStandardOutput()).object();
}

// The sum of the packets' durations in seconds (a GIF's delays).
double packetSeconds(const QString& path, int* packets) {
    QProcess p;
    p.start(QStringLiteral("ffprobe"), {"-v", "error", "-select_streams", "v:0", "-show_entries",
                                        "packet=duration_time", "-of", "csv=p=0", path});
    if (!p.waitForFinished(60000) || p.exitCode() != 0) return -1.0;
    double sum = 0.0;
    *packets = 0;
    for (const QByteArray& line : p.readAllStandardOutput().split('\n'))
        if (!line.trimmed().isEmpty()) {
            sum += line.trimmed().toDouble();
            ++*packets;
        }
    return sum;
}

QStringList entries(const QString& dir) {
    return QDir(dir).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden |
                               QDir::System);
}

}  // namespace

class TestCliRender : public QObject {
    Q_OBJECT

private:
    QTemporaryDir dir_;
    QString scene_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        scene_ = writeFile(dir_, QStringLiteral("bounce.json"), kScene);
        QProcess ffprobe;
        ffprobe.start(QStringLiteral("ffprobe"), {"-version"});
        QVERIFY2(ffprobe.waitForFinished(30000) && ffprobe.exitCode() == 0,
                 "ffprobe (Debian's ffmpeg) is needed by this suite; scripts/test.sh installs it");
    }

    void mp4IsH264WithItsFramesDurationAndSize() {
        const QString out = dir_.filePath(QStringLiteral("clip.mp4"));
        const CliResult r = runCli({"render", scene_, "--out", out, "--duration", "1", "--fps",
                                    "12", "--size", "160x120"});
        QCOMPARE(r.status, 0);
        QVERIFY2(r.err.isEmpty(), r.err.constData());
        const QJsonObject info = probe(out);
        const QJsonObject stream = info["streams"].toArray().first().toObject();
        QCOMPARE(stream["codec_name"].toString(), QStringLiteral("h264"));
        QCOMPARE(stream["width"].toInt(), 160);
        QCOMPARE(stream["height"].toInt(), 120);
        QCOMPARE(stream["nb_read_frames"].toString(), QStringLiteral("12"));
        QCOMPARE(stream["duration"].toString().toDouble(), 1.0);
        QVERIFY(info["format"].toObject()["format_name"].toString().contains(QLatin1String("mp4")));
    }

    void gifDelaysAddUpToTheDuration() {
        // 1.02 s at 30 fps: round(30.6) = 31 frames whose 102 hundredths alternate 3 and 4.
        const QString out = dir_.filePath(QStringLiteral("clip.gif"));
        const CliResult r = runCli({"render", scene_, "--out", out, "--from", "0.2", "--duration",
                                    "1.02", "--fps", "30", "--size", "120x90"});
        QCOMPARE(r.status, 0);
        const QJsonObject stream = probe(out)["streams"].toArray().first().toObject();
        QCOMPARE(stream["codec_name"].toString(), QStringLiteral("gif"));
        QCOMPARE(stream["width"].toInt(), 120);
        QCOMPARE(stream["height"].toInt(), 90);
        QCOMPARE(stream["nb_read_frames"].toString(), QStringLiteral("31"));
        int packets = 0;
        const double seconds = packetSeconds(out, &packets);
        QCOMPARE(packets, 31);
        QVERIFY2(std::abs(seconds - 1.02) < 0.005, qPrintable(QString::number(seconds)));
    }

    void plotsBesideTheCanvas() {
        const QString out = dir_.filePath(QStringLiteral("plots.gif"));
        const CliResult r = runCli({"render", scene_, "--out", out, "--duration", "0.2", "--fps",
                                    "10", "--size", "400x200", "--plots"});
        QCOMPARE(r.status, 0);
        const QJsonObject stream = probe(out)["streams"].toArray().first().toObject();
        QCOMPARE(stream["nb_read_frames"].toString(), QStringLiteral("2"));
        QCOMPARE(stream["width"].toInt(), 400);
    }

    void divergedRunIsDrawnToTheEndAndExits1() {
        QTemporaryDir work;
        const QString scene = writeFile(work, QStringLiteral("blow.json"), R"({
          "format": "phasebox-scene", "version": 1, "name": "blow-up",
          "simulation": { "integrator": "explicit_euler", "dt": 0.01, "duration": 1 },
          "particles": [ { "id": "bob", "position": [1, 0] } ],
          "springs": [ { "a": "bob", "anchor": [0, 0], "stiffness": 10000, "rest_length": 0.5 } ]
        })");
        const QString out = work.filePath(QStringLiteral("blow.gif"));
        const CliResult r = runCli(
            {"render", scene, "--out", out, "--duration", "1", "--fps", "10", "--size", "64x48"});
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.startsWith("phasebox-cli: diverged: "), r.err.constData());
        QVERIFY(r.err.contains("\"bob\""));
        const QJsonObject stream = probe(out)["streams"].toArray().first().toObject();
        QCOMPARE(stream["nb_read_frames"].toString(), QStringLiteral("10"));
    }

    void unknownExtensionIsRefusedWithTheFormats() {
        const QString out = dir_.filePath(QStringLiteral("clip.avi"));
        const CliResult r = runCli({"render", scene_, "--out", out});
        QCOMPARE(r.status, 2);
        QVERIFY(r.err.startsWith("phasebox-cli: error: "));
        QVERIFY2(r.err.contains(".mp4") && r.err.contains(".gif"), r.err.constData());
        QVERIFY(!QFileInfo::exists(out));
    }

    void badOptionsAreRefused() {
        const QString out = dir_.filePath(QStringLiteral("bad.mp4"));
        for (const QStringList& extra :
             {QStringList{"--size", "161x120"}, QStringList{"--size", "big"},
              QStringList{"--fps", "0"}, QStringList{"--duration", "0"},
              QStringList{"--from", "-1"}, QStringList{"--duration", "0.01", "--fps", "10"}}) {
            const CliResult r = runCli(QStringList{"render", scene_, "--out", out} + extra);
            QVERIFY2(r.status == 2, qPrintable(extra.join(' ')));
        }
        QVERIFY(!QFileInfo::exists(out));
        QCOMPARE(runCli({"render", scene_}).status, 2);
        QCOMPARE(runCli({"render", scene_, "--out", scene_}).status, 2);
    }

    void unwritableOutputExits3AndLeavesNothing() {
        const QString out = dir_.filePath(QStringLiteral("missing/clip.gif"));
        const CliResult r = runCli({"render", scene_, "--out", out, "--duration", "0.1"});
        QCOMPARE(r.status, 3);
        QVERIFY2(r.err.contains(out.toUtf8()), r.err.constData());
        QVERIFY(!QFileInfo::exists(dir_.filePath(QStringLiteral("missing"))));
    }

    void fullDeviceExits3() {
        // A device is written in place (CONTRACT §8); one that is full fails the write.
        const QString full = dir_.filePath(QStringLiteral("full.mp4"));
        QVERIFY(phasebox::testing::makeDevice(full, phasebox::testing::SystemDevice::Full));
        const CliResult r = runCli({"render", scene_, "--out", full, "--duration", "0.2", "--fps",
                                    "10", "--size", "64x48"});
        QCOMPARE(r.status, 3);
        QVERIFY2(r.err.contains("No space left on device"), r.err.constData());
        QVERIFY(phasebox::testing::isStillDevice(full, phasebox::testing::SystemDevice::Full));
        QFile::remove(full);
    }

    void fifoIsWrittenInPlace() {
        const QString pipe = dir_.filePath(QStringLiteral("pipe.gif"));
        QVERIFY(phasebox::testing::makeFifo(pipe));
        phasebox::testing::FifoReader reader(pipe);
        const CliResult r = runCli({"render", scene_, "--out", pipe, "--duration", "0.2", "--fps",
                                    "10", "--size", "64x48"});
        const QByteArray bytes = reader.take();
        QCOMPARE(r.status, 0);
        QVERIFY(phasebox::testing::isFifo(pipe));
        QVERIFY(bytes.startsWith("GIF89a"));
        QVERIFY(bytes.endsWith(';'));
        QFile::remove(pipe);
    }

    void interruptExits130AndKeepsTheEarlierFile() {
        QTemporaryDir work;
        const QString out = work.filePath(QStringLiteral("long.gif"));
        QFile earlier(out);
        QVERIFY(earlier.open(QIODevice::WriteOnly));
        earlier.write("earlier");
        earlier.close();
        QProcess p;
        // 90,000 frames of 1280x720: minutes of work, stopped a second in (the temporary file
        // may be unnamed, O_TMPFILE, so there is nothing to wait for on the disk).
        p.start(QStringLiteral(PHASEBOX_CLI), {"render", scene_, "--out", out, "--duration", "3000",
                                               "--fps", "30", "--size", "1280x720"});
        QVERIFY(p.waitForStarted());
        QTest::qWait(1000);
        QCOMPARE(p.state(), QProcess::Running);
        ::kill(static_cast<pid_t>(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 130);
        QVERIFY(p.readAllStandardError().contains("interrupted"));
        QCOMPARE(entries(work.path()), QStringList{QStringLiteral("long.gif")});
        QCOMPARE(phasebox::testing::readAll(out), QByteArray("earlier"));
    }
};

QTEST_GUILESS_MAIN(TestCliRender)
#include "tst_cli_render.moc"
