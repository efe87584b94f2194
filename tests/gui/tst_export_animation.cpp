// File > Export Animation (CONTRACT.md §8): the clip's frames are the canvas's own drawing (its
// first frame decoded is the canvas's picture of that moment, up to the GIF's palette), it has
// round(duration·fps) frames of the chosen size, Cancel in the progress dialog stops it and
// leaves no file, an unknown extension is refused with the formats, and the app keeps running.

#include "MainWindowTestSupport.h"
#include "app/desktop/AnimationExport.h"
#include "app/desktop/MainWindow.h"
#include "ui/canvas/SceneView.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLineEdit>
#include <QProcess>
#include <QProgressDialog>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <cmath>

using namespace phasebox;
using namespace phasebox::testing::parts;

namespace {

const char* kScene = R"({
  "format": "phasebox-scene", "version": 1, "name": "bounce",
  "simulation": { "integrator": "symplectic_euler", "dt": 0.01, "duration": 1 },
  "effects": { "gravity": {} },
  "particles": [ { "id": "ball", "position": [0, 1], "radius": 0.1, "restitution": 0.8 } ],
  "boxes": [ { "id": "crate", "position": [1, 0.5], "size": [0.4, 0.3] } ],
  "planes": [ { "id": "ground", "point": [0, 0], "normal": [0, 1] } ]
})";

QJsonObject probeStream(const QString& path) {
    QProcess p;
    p.start(QStringLiteral("ffprobe"),
            {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
             "stream=codec_name,width,height,nb_read_frames", "-of", "json", path});
    if (!p.waitForFinished(60000) || p.exitCode() != 0) return {};
    return QJsonDocument::fromJson(p.readAllStandardOutput())
        .object()["streams"]
        .toArray()
        .first()
        .toObject();
}

// Frame n of a clip, decoded by ffmpeg into a PNG.
QImage decodedFrame(const QString& clip, int n, const QString& png) {
    QProcess p;
    p.start(QStringLiteral("ffmpeg"),
            {"-v", "error", "-y", "-i", clip, "-vf", QStringLiteral("select=eq(n\\,%1)").arg(n),
             "-vframes", "1", png});
    if (!p.waitForFinished(60000) || p.exitCode() != 0) return {};
    return QImage(png).convertToFormat(QImage::Format_RGB32);
}

}  // namespace

class TestExportAnimation : public QObject {
    Q_OBJECT

private:
    QTemporaryDir dir_;

    void open(MainWindow& w) {
        const QString scene = dir_.filePath(QStringLiteral("bounce.json"));
        QFile f(scene);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(kScene);
        f.close();
        w.resize(900, 650);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openFile(scene, true));
        // The canvas frames the scene once the window's layout has settled.
        QTest::qWait(100);
        w.refreshNow();
    }

    static AnimationExport* exporter(MainWindow& w) {
        return w.findChild<AnimationExport*>(QStringLiteral("animationExport"));
    }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(dir_.isValid());
    }

    void theFileMenuHasIt() {
        MainWindow w;
        QAction* a = w.action(QStringLiteral("exportAnimation"));
        QVERIFY(a);
        QVERIFY(a->text().contains(QLatin1String("Animation")));
    }

    // File > Export Animation as a user goes through it: the dialog's fields, then Export.
    void theDialogExports() {
        MainWindow w;
        open(w);
        const QString path = dir_.filePath(QStringLiteral("dialog.mp4"));
        bool filled = false;
        QTimer::singleShot(0, &w, [&] {
            auto* dialog = qobject_cast<AnimationExportDialog*>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            dialog->findChild<QLineEdit*>(QStringLiteral("clipPath"))->setText(path);
            dialog->findChild<QDoubleSpinBox*>(QStringLiteral("clipDuration"))->setValue(0.25);
            dialog->findChild<QSpinBox*>(QStringLiteral("clipFps"))->setValue(8);
            dialog->findChild<QSpinBox*>(QStringLiteral("clipWidth"))->setValue(200);
            dialog->findChild<QSpinBox*>(QStringLiteral("clipHeight"))->setValue(150);
            dialog->findChild<QCheckBox*>(QStringLiteral("clipPlots"))->setChecked(false);
            filled = true;
            dialog->accept();
        });
        w.action(QStringLiteral("exportAnimation"))->trigger();
        QVERIFY(filled);
        const QJsonObject stream = probeStream(path);
        QCOMPARE(stream["codec_name"].toString(), QStringLiteral("h264"));
        QCOMPARE(stream["width"].toInt(), 200);
        QCOMPARE(stream["nb_read_frames"].toString(), QStringLiteral("2"));
    }

    void framesAreTheCanvasDrawing() {
        MainWindow w;
        open(w);
        AnimationExport* e = exporter(w);
        QVERIFY(e);
        ClipOptions o = e->defaults();
        o.duration = 0.3;
        o.fps = 10;
        o.size = QSize(320, 240);
        const QString path = dir_.filePath(QStringLiteral("clip.gif"));
        const ClipResult r = e->exportClip(path, o);
        QCOMPARE(r.status, ClipResult::Written);
        QCOMPARE(r.frames, 3);
        const QJsonObject stream = probeStream(path);
        QCOMPARE(stream["codec_name"].toString(), QStringLiteral("gif"));
        QCOMPARE(stream["width"].toInt(), 320);
        QCOMPARE(stream["nb_read_frames"].toString(), QStringLiteral("3"));
        // The first frame is t = 0, the state the open scene shows: the canvas's own picture
        // (through the same view).
        QCOMPARE(canvasOf(w)->view().pixelsPerMetre(), o.view->pixelsPerMetre());
        const QImage canvas =
            canvasOf(w)->renderImage(QSize(320, 240), true).convertToFormat(QImage::Format_RGB32);
        const QImage first = decodedFrame(path, 0, dir_.filePath(QStringLiteral("f0.png")));
        QCOMPARE(first.size(), canvas.size());
        long long far = 0;
        double sum = 0.0;
        for (int y = 0; y < canvas.height(); ++y)
            for (int x = 0; x < canvas.width(); ++x) {
                const QRgb a = canvas.pixel(x, y), b = first.pixel(x, y);
                const int d =
                    std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                              std::abs(qBlue(a) - qBlue(b))});
                sum += d;
                far += d > 16;
            }
        const double pixels = double(canvas.width()) * canvas.height();
        // giflib's quantiser keeps 5 bits a channel, so flat colours move by a few levels; a
        // different view or a later state moves whole shapes (hundreds of pixels far off).
        QVERIFY2(sum / pixels < 4.0, qPrintable(QString::number(sum / pixels)));
        QVERIFY2(far < pixels / 2000, qPrintable(QString::number(far)));
    }

    void mp4WithPlots() {
        MainWindow w;
        open(w);
        ClipOptions o = exporter(w)->defaults();
        o.duration = 0.5;
        o.fps = 8;
        o.size = QSize(480, 240);
        o.plots = true;
        const QString path = dir_.filePath(QStringLiteral("plots.mp4"));
        QCOMPARE(exporter(w)->exportClip(path, o).status, ClipResult::Written);
        const QJsonObject stream = probeStream(path);
        QCOMPARE(stream["codec_name"].toString(), QStringLiteral("h264"));
        QCOMPARE(stream["nb_read_frames"].toString(), QStringLiteral("4"));
        QCOMPARE(stream["height"].toInt(), 240);
    }

    void cancelLeavesNoFile() {
        MainWindow w;
        open(w);
        ClipOptions o = exporter(w)->defaults();
        o.duration = 30;
        o.size = QSize(160, 120);
        QTemporaryDir work;
        const QString path = work.filePath(QStringLiteral("long.mp4"));
        int cancelled = 0;
        QTimer timer;
        connect(&timer, &QTimer::timeout, &w, [&] {
            if (auto* progress = w.findChild<QProgressDialog*>(QStringLiteral("animationProgress"));
                progress && progress->value() >= 3) {
                progress->cancel();
                ++cancelled;
            }
        });
        timer.start(10);
        w.controller().play();
        const ClipResult r = exporter(w)->exportClip(path, o);
        QVERIFY2(w.controller().isRunning(), "the live run goes on after the export");
        w.controller().pause();
        QCOMPARE(r.status, ClipResult::Cancelled);
        QVERIFY(cancelled > 0);
        QVERIFY(r.frames < 900);
        QVERIFY2(QDir(work.path()).isEmpty(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden),
                 "a partial clip or its temporary file was left");
        // The app goes on: the live run steps.
        QVERIFY(w.controller().advance(0.1));
    }

    void unwritableFileIsReportedAndTheAppGoesOn() {
        MainWindow w;
        open(w);
        ClipOptions o = exporter(w)->defaults();
        o.duration = 0.2;
        o.size = QSize(64, 48);
        const QString path = dir_.filePath(QStringLiteral("gone/clip.mp4"));
        const ClipResult r = exporter(w)->exportClip(path, o);
        QCOMPARE(r.status, ClipResult::WriteFailed);
        QVERIFY2(r.message.contains(path), qPrintable(r.message));
        QVERIFY(!QFile::exists(dir_.filePath(QStringLiteral("gone"))));
        QVERIFY(w.controller().advance(0.1));
    }

    void unknownFormatIsRefused() {
        MainWindow w;
        open(w);
        const QString path = dir_.filePath(QStringLiteral("clip.webm"));
        const ClipResult r = exporter(w)->exportClip(path, exporter(w)->defaults());
        QCOMPARE(r.status, ClipResult::WriteFailed);
        QVERIFY2(
            r.message.contains(QLatin1String(".mp4")) && r.message.contains(QLatin1String(".gif")),
            qPrintable(r.message));
        QVERIFY(!QFile::exists(path));
    }
};

QTEST_MAIN(TestExportAnimation)
#include "tst_export_animation.moc"
