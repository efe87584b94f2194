// Issue #38: what the app reads at start and shows cannot hang or exhaust it.
// - a settings file or a recovery sidecar that is a FIFO (the start blocked for ever) or a link
//   to /dev/zero (read until memory ran out) is removed with a message, never read;
// - a scene whose name and description are one word of a million characters loads and shows
//   at once, with a bounded window title;
// - a settings file saying speed=nan (or inf, negative, huge) does not stop Play;
// - a screenshot, or an export, onto the open scene's file (or a link to it) is refused.

#include "app/desktop/MainWindow.h"
#include "app/document/Autosave.h"
#include "app/io/SceneIO.h"
#include "physics/world/World.h"
#include "tests/gui/GuiTestSupport.h"

#include <QApplication>
#include <QDebug>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTreeWidget>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace phasebox;

namespace {

// The desktop app with its settings and data folders in dir.
QProcessEnvironment appEnvironment(const QTemporaryDir& dir) {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("QT_QPA_PLATFORM", "offscreen");
    env.insert("HOME", dir.path());
    env.insert("XDG_CONFIG_HOME", dir.filePath("config"));
    env.insert("XDG_DATA_HOME", dir.filePath("data"));
    return env;
}

QString settingsFile(const QTemporaryDir& dir) {
    return dir.filePath("config/Phasebox/Phasebox.conf");
}
QString recoveryDir(const QTemporaryDir& dir) {
    return dir.filePath("data/Phasebox/Phasebox/recovery");
}

// Starts the app (a window, as a user starts it) and waits for every one of the expected lines
// on its standard error; the app is then ended. Memory is bounded so that reading /dev/zero
// fails at once instead of filling the machine.
QString startAndWaitFor(const QTemporaryDir& dir, const QStringList& expected) {
    QProcess app;
    app.setProcessEnvironment(appEnvironment(dir));
    app.setChildProcessModifier([] {
        rlimit limit{};
        ::getrlimit(RLIMIT_AS, &limit);
        limit.rlim_cur = rlim_t(4) << 30;
        ::setrlimit(RLIMIT_AS, &limit);
    });
    app.start(QStringLiteral(PHASEBOX_DESKTOP), {"--canvas", "raster"});
    if (!app.waitForStarted(20000)) return QStringLiteral("not started");
    QByteArray err;
    QElapsedTimer clock;
    clock.start();
    auto allSeen = [&] {
        for (const QString& line : expected)
            if (!QString::fromUtf8(err).contains(line)) return false;
        return true;
    };
    while (!allSeen() && clock.elapsed() < 30000 && app.state() == QProcess::Running) {
        app.waitForReadyRead(200);
        err += app.readAllStandardError();
    }
    err += app.readAllStandardError();
    const bool ok = allSeen();
    app.kill();
    app.waitForFinished(10000);
    return ok ? QString()
              : QStringLiteral("standard error after %1 ms: %2")
                    .arg(clock.elapsed())
                    .arg(QString::fromUtf8(err.left(2000)));
}

SceneDesc savedScene() {
    return testing::freeScene();
}

// The folders of a start in dir, with an autosaved scene left by a crash; returns the path of
// its sidecar (not written).
QString prepareStart(const QTemporaryDir& dir) {
    QDir().mkpath(QFileInfo(settingsFile(dir)).path());
    QDir().mkpath(recoveryDir(dir));
    QString error;
    if (!SceneIO::save(savedScene(), Autosave::recoveryFilePath(recoveryDir(dir)), &error))
        qWarning() << error;
    return Autosave::sidecarFilePath(recoveryDir(dir));
}

}  // namespace

class TestStartupRobustness : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    // Item 1: a FIFO would block the start until someone writes to it.
    void fifoSettingsAndSidecarAreRemovedNotRead() {
        QTemporaryDir dir;
        const QString sidecar = prepareStart(dir);
        QCOMPARE(::mkfifo(QFile::encodeName(settingsFile(dir)).constData(), 0600), 0);
        QCOMPARE(::mkfifo(QFile::encodeName(sidecar).constData(), 0600), 0);
        const QString failure =
            startAndWaitFor(dir, {"not a settings file", "not a recovery file"});
        // Whatever happened, nothing may stay blocked on the FIFOs: a writer that opens and
        // closes them ends a read waiting there.
        for (const QString& fifo : {settingsFile(dir), sidecar}) {
            const int fd = ::open(QFile::encodeName(fifo).constData(), O_WRONLY | O_NONBLOCK);
            if (fd >= 0) ::close(fd);
        }
        QVERIFY2(failure.isEmpty(), qPrintable(failure));
        QVERIFY(!QFileInfo::exists(settingsFile(dir)) ||
                QFileInfo(settingsFile(dir)).isFile());  // removed (the app may write a new one)
        QVERIFY(!QFileInfo::exists(sidecar));
        // The scene itself is kept for the recovery.
        QVERIFY(QFileInfo(Autosave::recoveryFilePath(recoveryDir(dir))).isFile());
    }

    // Item 1: /dev/zero has no end; read whole, it ended the app with std::bad_alloc.
    void linksToDevZeroAreRemovedNotRead() {
        QTemporaryDir dir;
        const QString sidecar = prepareStart(dir);
        QVERIFY(QFile::link(QStringLiteral("/dev/zero"), settingsFile(dir)));
        QVERIFY(QFile::link(QStringLiteral("/dev/zero"), sidecar));
        const QString failure =
            startAndWaitFor(dir, {"not a settings file", "not a recovery file"});
        QVERIFY2(failure.isEmpty(), qPrintable(failure));
        QVERIFY(!QFileInfo(sidecar).isSymLink());
        QVERIFY(!QFileInfo(settingsFile(dir)).isSymLink());
        QVERIFY(QFileInfo::exists(QStringLiteral("/dev/zero")));  // the link went, not its target
    }

    // Item 1, in the library: the recovery's sidecar and scene are never opened when they are
    // not regular files, and a sidecar past its bound is not read.
    void findRecoveryReadsOnlyBoundedRegularFiles() {
        QTemporaryDir dir;
        const QString recovery = dir.filePath("recovery");
        QVERIFY(QDir().mkpath(recovery));
        QString error;
        QVERIFY2(SceneIO::save(savedScene(), Autosave::recoveryFilePath(recovery), &error),
                 qPrintable(error));
        QVERIFY(QFile::link(QStringLiteral("/dev/zero"), Autosave::sidecarFilePath(recovery)));
        QStringList problems;
        const auto found = Autosave::findRecovery(recovery, &problems);
        QVERIFY(found.has_value());
        QVERIFY(found->originalPath.isEmpty());
        QCOMPARE(problems.size(), 1);
        QVERIFY2(problems.first().contains("a device"), qPrintable(problems.first()));
        // A regular sidecar over 64 KiB is not ours: not read, said so.
        QFile big(Autosave::sidecarFilePath(recovery));
        QVERIFY(big.open(QIODevice::WriteOnly));
        big.write(QByteArray(100 * 1024, ' '));
        big.close();
        problems.clear();
        QVERIFY(Autosave::findRecovery(recovery, &problems).has_value());
        QCOMPARE(problems.size(), 1);
        QVERIFY2(problems.first().contains("larger than"), qPrintable(problems.first()));
        // The scene a FIFO: removed, nothing found.
        QVERIFY(QFile::remove(Autosave::recoveryFilePath(recovery)));
        QCOMPARE(
            ::mkfifo(QFile::encodeName(Autosave::recoveryFilePath(recovery)).constData(), 0600), 0);
        problems.clear();
        QVERIFY(!Autosave::findRecovery(recovery, &problems).has_value());
        QVERIFY(!QFileInfo::exists(Autosave::recoveryFilePath(recovery)));
        QVERIFY2(problems.join(' ').contains("FIFO"), qPrintable(problems.join(' ')));
    }

    // Item 2: one word of a million characters as the name and as the description.
    void aMillionCharacterNameShowsAtOnce() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        SceneDesc scene = testing::freeScene();
        scene.name = std::string(1'000'000, 'w');
        scene.description = std::string(1'000'000, 'd');
        scene.particles[0].id = std::string(100'000, 'p');
        scene.springs[0].a = scene.particles[0].id;
        QElapsedTimer clock;
        clock.start();
        QString error;
        QVERIFY2(w.document().loadFromDesc(scene, {}, &error), qPrintable(error));
        w.refreshNow();
        QApplication::processEvents();
        QVERIFY2(clock.elapsed() < 1000, qPrintable(QString::number(clock.elapsed())));
        QVERIFY2(w.windowTitle().size() < 400, qPrintable(w.windowTitle().left(100)));
        QVERIFY(w.windowTitle().contains(QChar(0x2026)));
        const auto* notes = w.findChild<QTextBrowser*>(QStringLiteral("notes"));
        QVERIFY(notes);
        QVERIFY(notes->toPlainText().size() < 100'000);
        const auto* tree = w.findChild<QTreeWidget*>(QStringLiteral("objects"));
        QVERIFY(tree);
        for (QTreeWidgetItemIterator it(const_cast<QTreeWidget*>(tree)); *it; ++it)
            QVERIFY((*it)->text(0).size() <= 1000);
        // The scene keeps its full name: a save writes it whole.
        QCOMPARE(w.document().setup().name.size(), std::size_t(1'000'000));
    }

    // Item 3: every number read from the settings is checked.
    void badSpeedInTheSettingsKeepsPlayRunning_data() {
        QTest::addColumn<QString>("speed");
        for (const char* s : {"nan", "inf", "-inf", "-1", "0", "1e308", "fast"})
            QTest::newRow(s) << QString::fromLatin1(s);
    }
    void badSpeedInTheSettingsKeepsPlayRunning() {
        QFETCH(QString, speed);
        {
            QSettings settings;
            settings.setValue(QStringLiteral("simulation/speed"), speed);
            settings.setValue(QStringLiteral("window/geometry"), QByteArray(100'000, 'g'));
            settings.sync();
        }
        MainWindow w;
        QCOMPARE(w.controller().speed(), 1.0);
        QVERIFY(w.width() >= 320 && w.width() <= 16384);
        w.show();
        QVERIFY(w.openFile(QStringLiteral(":/scenes/demo.phasebox.json"), true));
        const double before = w.document().world().time();
        w.controller().play();
        QTest::qWait(400);
        w.controller().pause();
        QVERIFY2(w.document().world().time() > before + 0.05,
                 qPrintable(QString::number(w.document().world().time())));
        QSettings().clear();
    }

    // Item 4: the picture must not replace the scene it shows.
    void screenshotOntoTheSceneIsRefused() {
        QTemporaryDir dir;
        const QString scene = dir.filePath("lesson.json");
        QString error;
        QVERIFY2(SceneIO::save(savedScene(), scene, &error), qPrintable(error));
        QFile original(scene);
        QVERIFY(original.open(QIODevice::ReadOnly));
        const QByteArray bytes = original.readAll();
        original.close();
        QVERIFY(QFile::link(scene, dir.filePath("link.png")));
        QVERIFY(QFile::link(scene, dir.filePath("link.json")));
        const QList<QStringList> cases{
            {scene, scene},
            {dir.filePath("./lesson.json"), scene},
            {dir.filePath("link.png"), scene},
            {scene, dir.filePath("link.json")},
        };
        for (const QStringList& c : cases) {
            QProcess app;
            app.setProcessEnvironment(appEnvironment(dir));
            app.start(QStringLiteral(PHASEBOX_DESKTOP), {"--screenshot", c[0], c[1]});
            QVERIFY(app.waitForFinished(60000));
            const QByteArray err = app.readAllStandardError();
            QVERIFY2(app.exitCode() == 2, qPrintable(c.join(' ') + ": " + err));
            QVERIFY2(err.contains("open scene's file"), err.constData());
            QFile after(scene);
            QVERIFY(after.open(QIODevice::ReadOnly));
            QCOMPARE(after.readAll(), bytes);
        }
    }

    // Item 4: the app's exports are refused onto the open scene's file too.
    void exportsOntoTheOpenSceneAreRefused() {
        QTemporaryDir dir;
        const QString scene = dir.filePath("lesson.png");  // a scene may have any name
        QString error;
        QVERIFY2(SceneIO::save(savedScene(), scene, &error), qPrintable(error));
        QVERIFY(QFile::link(scene, dir.filePath("link.png")));
        MainWindow w;
        QVERIFY2(w.openFile(scene, true, &error), qPrintable(error));
        for (const QString& target : {scene, dir.filePath("link.png")}) {
            QVERIFY(!w.exportCanvas(target, &error));
            QVERIFY2(error.contains("open scene's file"), qPrintable(error));
            QVERIFY(!w.exportPlot(ui::PlotsPanel::Plot::Energy, target, &error));
            QVERIFY2(error.contains("open scene's file"), qPrintable(error));
        }
        QVERIFY(SceneIO::load(scene).ok());
        QVERIFY(w.exportCanvas(dir.filePath("other.png"), &error));
    }
};

QTEST_MAIN(TestStartupRobustness)
#include "tst_startup_robustness.moc"
