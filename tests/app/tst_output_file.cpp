// OutputFile, the one writer of every file Phasebox writes (issue #20): a regular file is
// replaced only when the new one is complete, a failure (file-size limit, full device) is
// reported with the path and the system's reason and leaves the earlier file whole, a device
// or FIFO is written in place and never replaced by a regular file. Then the app's paths that
// use it: saving the document (which stays modified on failure), the autosave, the recorder's
// CSV export.

#include "app/document/Autosave.h"
#include "app/document/Document.h"
#include "app/io/OutputFile.h"
#include "app/io/SceneIO.h"
#include "app/sim/Recorder.h"
#include "tests/support/OutputTargets.h"

#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextStream>

#include <sys/resource.h>
#include <unistd.h>

using namespace phasebox;
using testing::FifoReader;
using testing::isStillDevice;
using testing::readAll;
using testing::SystemDevice;

namespace {

bool writePlain(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

// RLIMIT_FSIZE in this process for a scope (it binds root too); SIGXFSZ is OutputFile's to
// deal with, so it keeps whatever disposition the program has.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        ::getrlimit(RLIMIT_FSIZE, &saved_);
        rlimit limit = saved_;
        limit.rlim_cur = bytes;
        active_ = ::setrlimit(RLIMIT_FSIZE, &limit) == 0;
    }
    ~FileSizeLimit() { ::setrlimit(RLIMIT_FSIZE, &saved_); }
    bool active() const { return active_; }

private:
    rlimit saved_{};
    bool active_ = false;
};

QStringList filesIn(const QTemporaryDir& dir) {
    return QDir(dir.path()).entryList(QDir::Files | QDir::Hidden | QDir::System);
}

}  // namespace

class TestOutputFile : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;

    // A device that behaves as /dev/full or /dev/null, named name (testing::makeDevice).
    QString device(const QString& name, SystemDevice kind) {
        const QString path = dir_.filePath(name);
        QFile::remove(path);
        return testing::makeDevice(path, kind) ? path : QString();
    }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(dir_.isValid());
    }

    void regularFileIsReplacedWhole() {
        QTemporaryDir dir;
        const QString path = dir.filePath("out.txt");
        QVERIFY(writePlain(path, "old"));
        OutputFile file(path);
        QVERIFY(file.open());
        QVERIFY(!file.inPlace());
        QTextStream(file.device()) << "new contents\n";
        QCOMPARE(readAll(path), QByteArray("old"));  // nothing changes before commit
        QVERIFY2(file.commit(), qPrintable(file.error()));
        QCOMPARE(readAll(path), QByteArray("new contents\n"));
        QCOMPARE(filesIn(dir), QStringList{"out.txt"});
    }

    // A write past the file-size limit: QSaveFile alone commits the truncated copy.
    void failedWriteKeepsTheEarlierFile() {
        QTemporaryDir dir;
        const QString path = dir.filePath("scene.json");
        QVERIFY(writePlain(path, "the earlier file"));
        QString error;
        bool ok = true;
        {
            FileSizeLimit limit(4096);
            QVERIFY(limit.active());
            ok = OutputFile::writeAll(path, QByteArray(100000, 'x'), &error);
        }
        QVERIFY(!ok);
        QCOMPARE(error, path + QStringLiteral(": cannot write the file: File too large"));
        QCOMPARE(readAll(path), QByteArray("the earlier file"));
        QCOMPARE(filesIn(dir), QStringList{"scene.json"});
    }

    void failedStreamedWriteKeepsTheEarlierFile() {
        QTemporaryDir dir;
        const QString path = dir.filePath("rows.csv");
        QVERIFY(writePlain(path, "a,b\n1,2\n"));
        OutputFile file(path, QStringLiteral("the CSV file"));
        bool committed = true;
        {
            FileSizeLimit limit(8192);
            QVERIFY(file.open());
            QTextStream out(file.device());
            for (int i = 0; i < 10000; ++i) out << i << ",0.125\n";
            out.flush();
            committed = file.commit();
        }
        QVERIFY(!committed);
        QCOMPARE(file.error(),
                 path + QStringLiteral(": cannot write the CSV file: File too large"));
        QCOMPARE(readAll(path), QByteArray("a,b\n1,2\n"));
        QCOMPARE(filesIn(dir), QStringList{"rows.csv"});
    }

    void deviceIsWrittenInPlace() {
        const QString full = device("full", SystemDevice::Full);
        const QString null = device("null", SystemDevice::Null);
        QVERIFY(!full.isEmpty() && !null.isEmpty());
        QString error;
        QVERIFY(!OutputFile::writeAll(full, "some bytes", &error));
        QCOMPARE(error, full + QStringLiteral(": cannot write the file: No space left on device"));
        QVERIFY2(isStillDevice(full, SystemDevice::Full),
                 "the device was replaced by a regular file");
        QVERIFY2(OutputFile::writeAll(null, QByteArray(100000, 'x'), &error), qPrintable(error));
        QVERIFY(isStillDevice(null, SystemDevice::Null));
        OutputFile file(null);
        QVERIFY(file.open());
        QVERIFY(file.inPlace());
    }

    void fifoIsWrittenInPlace() {
        const QString fifo = dir_.filePath("pipe");
        QVERIFY(testing::makeFifo(fifo));
        FifoReader reader(fifo);
        QString error;
        const bool ok = OutputFile::writeAll(fifo, "through the pipe\n", &error);
        const QByteArray received = reader.take();
        QVERIFY2(ok, qPrintable(error));
        QCOMPARE(received, QByteArray("through the pipe\n"));
        QVERIFY(testing::isFifo(fifo));
    }

    void folderIsRefused() {
        QString error;
        QVERIFY(!OutputFile::writeAll(dir_.path(), "x", &error));
        QCOMPARE(error, dir_.path() + QStringLiteral(": cannot write the file: it is a folder"));
    }

    // A NUL ends a name for the system: "a\0b.csv" would write "a" (found by fuzz_cli_outputs).
    void nameWithNulIsRefused() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a")) + QChar(u'\0') + QStringLiteral("b");
        QString error;
        QVERIFY(!OutputFile::writeAll(path, "x", &error));
        QCOMPARE(error, path + QStringLiteral(": cannot write the file: the name holds a NUL "
                                              "character"));
        QCOMPARE(filesIn(dir), QStringList());
    }

    void sameFileSeesLinksAndSpellings() {
        QTemporaryDir dir;
        const QString a = dir.filePath("a.json"), b = dir.filePath("b.json");
        QVERIFY(writePlain(a, "a") && writePlain(b, "b"));
        QVERIFY(OutputFile::sameFile(a, a));
        QVERIFY(OutputFile::sameFile(a, dir.path() + "/./a.json"));
        QVERIFY(QFile::link(a, dir.filePath("link.json")));
        QVERIFY(OutputFile::sameFile(a, dir.filePath("link.json")));
        QCOMPARE(::link(QFile::encodeName(a).constData(),
                        QFile::encodeName(dir.filePath("hard.json")).constData()),
                 0);
        QVERIFY(OutputFile::sameFile(dir.filePath("hard.json"), a));
        QVERIFY(!OutputFile::sameFile(a, b));
        QVERIFY(!OutputFile::sameFile(a, dir.filePath("missing.json")));
        QVERIFY(!OutputFile::sameFile(a, QStringLiteral("-")));
    }

    // The app's Save: a failure says why, and the document stays modified (the work is not
    // marked as saved).
    void documentSaveOntoFullDeviceStaysModified() {
        const QString full = device("full.phasebox.json", SystemDevice::Full);
        QVERIFY(!full.isEmpty());
        Document doc;
        ParticleDesc p;
        p.id = "ball";
        QVERIFY(doc.addObject(p));
        QVERIFY(doc.isModified());
        QString error;
        QVERIFY(!doc.save(full, &error));
        QCOMPARE(error, full + QStringLiteral(": cannot write the file: No space left on device"));
        QVERIFY(doc.isModified());
        QVERIFY(doc.filePath() != full);
        QVERIFY(isStillDevice(full, SystemDevice::Full));
    }

    // The autosave reports a failed write with the reason (and keeps trying later).
    void autosaveOntoFullDeviceReportsWhy() {
        QTemporaryDir recovery;
        const QString file = Autosave::recoveryFilePath(recovery.path());
        QVERIFY(testing::makeDevice(file, SystemDevice::Full));
        Document doc;
        Autosave autosave(doc, recovery.path(), 3600000);
        QSignalSpy failed(&autosave, &Autosave::autosaveFailed);
        ParticleDesc p;
        p.id = "ball";
        QVERIFY(doc.addObject(p));
        QVERIFY(!autosave.autosaveNow());
        QCOMPARE(failed.size(), 1);
        QCOMPARE(autosave.lastError(),
                 file + QStringLiteral(": cannot write the file: No space left on device"));
        QVERIFY(isStillDevice(file, SystemDevice::Full));
    }

    void recorderCsvPastFileSizeLimitFails() {
        QTemporaryDir dir;
        const QString path = dir.filePath("energy.csv");
        QVERIFY(writePlain(path, "earlier"));
        Recorder recorder;
        QString error;
        bool ok = true;
        {
            FileSizeLimit limit(1);
            ok = recorder.writeEnergyCsv(path, &error);
        }
        QVERIFY(!ok);
        QCOMPARE(error, path + QStringLiteral(": cannot write the CSV file: File too large"));
        QCOMPARE(readAll(path), QByteArray("earlier"));
    }
};

QTEST_GUILESS_MAIN(TestOutputFile)
#include "tst_output_file.moc"
