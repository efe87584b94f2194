// Replays the scene-loader fuzzer's seed corpus (tests/fuzz/corpus) and every crash reproducer
// kept from it (tests/fuzz/regressions) through the fuzzer's own check, without libFuzzer: a
// bug the fuzzer found once stays found in every CI run. Likewise the open-and-save fuzzer's
// (tests/fuzz/corpus-files, regressions-files). The command-line output fuzzer's corpus needs a
// QApplication and is replayed by tests/cli/tst_fuzz_cli_corpus.cpp.

#include "tests/fuzz/SceneFilesCheck.h"
#include "tests/fuzz/SceneLoaderCheck.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

namespace {

// Every file of the given folders under tests/fuzz/, sorted, as rows "folder/name".
int addFuzzRows(std::initializer_list<const char*> folders) {
    const QString root = QStringLiteral(PHASEBOX_SOURCE_DIR) + QStringLiteral("/tests/fuzz/");
    int count = 0;
    for (const char* folder : folders) {
        QDirIterator it(root + QLatin1String(folder), QDir::Files | QDir::Hidden);
        QStringList files;
        while (it.hasNext()) {
            const QString file = it.next();
            if (!file.endsWith(QLatin1String("/README.md"))) files << file;
        }
        files.sort();  // the same row order on every machine
        for (const QString& file : files) {
            QTest::newRow(
                qPrintable(QLatin1String(folder) + QLatin1Char('/') + QFileInfo(file).fileName()))
                << file;
            ++count;
        }
    }
    return count;
}

QByteArray readFile(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

}  // namespace

class TestFuzzCorpus : public QObject {
    Q_OBJECT

    int opened_ = 0, refused_ = 0;

private slots:
    void replay_data() {
        QTest::addColumn<QString>("path");
        const int count = addFuzzRows({"corpus", "regressions"});
        // The seeds hold at least the built-in scenes; an empty list means a wrong path.
        if (count < 10) qFatal("tst_fuzz_corpus: only %d scene-loader files found", count);
    }

    void replay() {
        QFETCH(QString, path);
        QFile file(path);
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(path + ": " + file.errorString()));
        const QByteArray bytes = file.readAll();
        const QString broken = phasebox::fuzz::checkSceneLoaderInput(
            reinterpret_cast<const std::uint8_t*>(bytes.constData()),
            static_cast<std::size_t>(bytes.size()));
        QVERIFY2(broken.isEmpty(), qPrintable(broken));
    }

    // The app's open and save paths (issue #20): a FIFO, device or folder is refused at once,
    // a refused file leaves the document as it was, an accepted one saves and opens again, a
    // failed save keeps the document modified.
    void replayOpenAndSave_data() {
        QTest::addColumn<QString>("path");
        if (addFuzzRows({"corpus-files", "regressions-files"}) < 8)
            qFatal("tst_fuzz_corpus: too few open-and-save seeds found");
    }

    void replayOpenAndSave() {
        QFETCH(QString, path);
        const QByteArray bytes = readFile(path);
        QTemporaryDir work;
        QVERIFY(work.isValid());
        bool accepted = false;
        const QString broken = phasebox::fuzz::checkSceneFilesInput(
            reinterpret_cast<const std::uint8_t*>(bytes.constData()),
            static_cast<std::size_t>(bytes.size()), work.filePath(QStringLiteral("files")),
            &accepted);
        QVERIFY2(broken.isEmpty(), qPrintable(broken));
        (accepted ? opened_ : refused_) += 1;
    }

    // The seeds take both paths: some open (and are saved), some are refused.
    void openAndSaveSeedsTakeBothPaths() {
        QVERIFY2(opened_ >= 3 && refused_ >= 5,
                 qPrintable(QStringLiteral("%1 opened, %2 refused").arg(opened_).arg(refused_)));
    }

    // The built-in scenes among the seeds are accepted: the check above would pass for a
    // loader that refused everything with a message.
    void builtInScenesAreAccepted() {
        const QDir scenes(QStringLiteral(PHASEBOX_SOURCE_DIR) +
                          QStringLiteral("/resources/scenes"));
        const QStringList names = scenes.entryList({QStringLiteral("*.json")}, QDir::Files);
        QVERIFY(!names.isEmpty());
        for (const QString& name : names) {
            const QString seed =
                QStringLiteral(PHASEBOX_SOURCE_DIR) + QStringLiteral("/tests/fuzz/corpus/") + name;
            const phasebox::SceneLoadResult loaded = phasebox::SceneIO::load(seed);
            QVERIFY2(loaded.ok(), qPrintable(seed + QStringLiteral(": ") + loaded.errorText()));
        }
    }
};

QTEST_GUILESS_MAIN(TestFuzzCorpus)
#include "tst_fuzz_corpus.moc"
