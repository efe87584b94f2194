// Autosave: a modified document is written to the recovery file on the timer and loads back
// as the same scene; an unmodified one writes nothing; discard() removes the file; the next
// start finds it with the path of the file it came from.

#include "app/document/Autosave.h"
#include "app/document/Document.h"
#include "app/io/SceneIO.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace phasebox;

namespace {
constexpr int kIntervalMs = 50;

ParticleDesc ball(const char* id, double x) {
    ParticleDesc p;
    p.id = id;
    p.position = {x, 1.0};
    return p;
}
}  // namespace

class TestAutosave : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;

    QString scenePath() const { return dir_.filePath(QStringLiteral("lesson.phasebox.json")); }
    QString recoveryDir(const char* name) const { return dir_.filePath(QLatin1String(name)); }

    // A document loaded from a saved file, so that it has an original path and starts clean.
    void openSaved(Document& doc) {
        QString error;
        QVERIFY2(doc.save(scenePath(), &error), qPrintable(error));
        QVERIFY2(doc.load(scenePath(), &error), qPrintable(error));
        QVERIFY(!doc.isModified());
    }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(dir_.isValid());
    }

    void defaultFolderIsUnderAppData() {
        QCoreApplication::setApplicationName(QStringLiteral("phasebox-autosave-test"));
        const QString expected =
            QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/recovery";
        QCOMPARE(Autosave::defaultRecoveryDir(), expected);
        // Test mode keeps the tests out of the user's real folders.
        QVERIFY2(expected.contains(QStringLiteral(".qttest")), qPrintable(expected));
    }

    void modifiedDocumentIsWrittenAndLoadsBackIdentical() {
        Document doc;
        openSaved(doc);
        const QString folder = recoveryDir("modified");
        Autosave autosave(doc, folder, kIntervalMs);
        QSignalSpy written(&autosave, &Autosave::autosaved);
        QVERIFY(doc.addObject(ball("ball", 0.5)));
        QVERIFY(doc.isModified());

        QVERIFY(written.wait(5000));  // the timer, not a direct call
        const QString recovery = Autosave::recoveryFilePath(folder);
        QCOMPARE(written.takeFirst().at(0).toString(), recovery);
        const SceneLoadResult loaded = SceneIO::load(recovery);
        QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
        QCOMPARE(SceneIO::serialize(*loaded.scene), SceneIO::serialize(doc.setup()));
        QVERIFY(autosave.lastError().isEmpty());

        // No further change, no further write.
        const QDateTime stamp = QFileInfo(recovery).lastModified();
        QTest::qWait(4 * kIntervalMs);
        QCOMPARE(written.count(), 0);
        QCOMPARE(QFileInfo(recovery).lastModified(), stamp);

        // The next change is written again, and replaces the first autosave.
        QVERIFY(doc.addObject(ball("second", 1.5)));
        QVERIFY(written.wait(5000));
        const SceneLoadResult again = SceneIO::load(recovery);
        QVERIFY2(again.ok(), qPrintable(again.errorText()));
        QCOMPARE(again.scene->particles.size(), std::size_t(2));
        autosave.discard();
    }

    void unmodifiedDocumentWritesNothing() {
        Document doc;
        openSaved(doc);
        const QString folder = recoveryDir("unmodified");
        Autosave autosave(doc, folder, kIntervalMs);
        QSignalSpy written(&autosave, &Autosave::autosaved);
        QTest::qWait(5 * kIntervalMs);
        QCOMPARE(written.count(), 0);
        QVERIFY(!autosave.autosaveNow());
        QVERIFY(!QFileInfo::exists(Autosave::recoveryFilePath(folder)));
        QVERIFY(!Autosave::findRecovery(folder));
    }

    void discardRemovesTheRecovery() {
        Document doc;
        openSaved(doc);
        const QString folder = recoveryDir("discard");
        Autosave autosave(doc, folder, kIntervalMs);
        QVERIFY(doc.addObject(ball("ball", 0.5)));
        QVERIFY(autosave.autosaveNow());
        QVERIFY(QFileInfo::exists(Autosave::recoveryFilePath(folder)));
        QVERIFY(QFileInfo::exists(Autosave::sidecarFilePath(folder)));
        autosave.discard();
        QVERIFY(!QFileInfo::exists(Autosave::recoveryFilePath(folder)));
        QVERIFY(!QFileInfo::exists(Autosave::sidecarFilePath(folder)));
        QVERIFY(!Autosave::findRecovery(folder));
        // And the timer is stopped: later edits leave no file behind after a clean exit.
        QVERIFY(doc.addObject(ball("late", 2.0)));
        QTest::qWait(4 * kIntervalMs);
        QVERIFY(!QFileInfo::exists(Autosave::recoveryFilePath(folder)));
    }

    void savingRemovesTheRecovery() {
        // Once the work is safely in its file, an older autosave must not be offered.
        Document doc;
        openSaved(doc);
        const QString folder = recoveryDir("saved");
        Autosave autosave(doc, folder, kIntervalMs);
        QVERIFY(doc.addObject(ball("ball", 0.5)));
        QVERIFY(autosave.autosaveNow());
        QString error;
        QVERIFY2(doc.save(scenePath(), &error), qPrintable(error));
        QVERIFY(!Autosave::findRecovery(folder));
    }

    void findRecoveryAfterACrash() {
        const QString folder = recoveryDir("crash");
        const QDateTime before = QDateTime::currentDateTimeUtc().addSecs(-1);
        {
            // The session "crashes": the autosave is never discarded (the objects' destructors
            // do not remove anything; a real crash would not even run them).
            Document doc;
            openSaved(doc);
            Autosave autosave(doc, folder, kIntervalMs);
            QVERIFY(doc.addObject(ball("unsaved", 3.0)));
            QVERIFY(autosave.autosaveNow());
        }
        const std::optional<RecoveryInfo> found = Autosave::findRecovery(folder);
        QVERIFY(found);
        QCOMPARE(found->originalPath, scenePath());
        QCOMPARE(found->recoveryFile, Autosave::recoveryFilePath(folder));
        QVERIFY(found->savedAt >= before);
        QVERIFY(found->savedAt <= QDateTime::currentDateTimeUtc().addSecs(1));
        // The next start loads it like any scene.
        Document next;
        QString error;
        QVERIFY2(next.load(found->recoveryFile, &error), qPrintable(error));
        QCOMPARE(next.setup().particles.back().id, std::string("unsaved"));

        // Without its sidecar the scene is still found, with no original path.
        QVERIFY(QFile::remove(Autosave::sidecarFilePath(folder)));
        const std::optional<RecoveryInfo> bare = Autosave::findRecovery(folder);
        QVERIFY(bare);
        QVERIFY(bare->originalPath.isEmpty());
        QVERIFY(bare->savedAt.isValid());
        QVERIFY(Autosave::removeRecovery(folder));
        QVERIFY(!Autosave::findRecovery(folder));
    }

    void failedAutosaveIsReported() {
        // A recovery "folder" that is a regular file cannot be created, even by root.
        const QString blocker = dir_.filePath(QStringLiteral("blocker"));
        {
            QFile file(blocker);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write("not a folder");
        }
        Document doc;
        openSaved(doc);
        Autosave autosave(doc, blocker + "/recovery", kIntervalMs);
        QSignalSpy failed(&autosave, &Autosave::autosaveFailed);
        QVERIFY(doc.addObject(ball("ball", 0.5)));
        QVERIFY(!autosave.autosaveNow());
        QCOMPARE(failed.count(), 1);
        QVERIFY2(autosave.lastError().contains(blocker), qPrintable(autosave.lastError()));
        autosave.discard();
    }
};

QTEST_GUILESS_MAIN(TestAutosave)
#include "tst_autosave.moc"
