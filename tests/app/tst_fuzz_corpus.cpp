// Replays the scene-loader fuzzer's seed corpus (tests/fuzz/corpus) and every crash reproducer
// kept from it (tests/fuzz/regressions) through the fuzzer's own check, without libFuzzer: a
// bug the fuzzer found once stays found in every CI run.

#include "tests/fuzz/SceneLoaderCheck.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QTest>

class TestFuzzCorpus : public QObject {
    Q_OBJECT

private slots:
    void replay_data() {
        QTest::addColumn<QString>("path");
        const QString root = QStringLiteral(PHASEBOX_SOURCE_DIR) + QStringLiteral("/tests/fuzz/");
        int count = 0;
        for (const char* folder : {"corpus", "regressions"}) {
            QDirIterator it(root + QLatin1String(folder), QDir::Files | QDir::Hidden);
            QStringList files;
            while (it.hasNext()) {
                const QString file = it.next();
                if (!file.endsWith(QLatin1String("/README.md"))) files << file;
            }
            files.sort();  // the same row order on every machine
            for (const QString& file : files) {
                QTest::newRow(qPrintable(QLatin1String(folder) + QLatin1Char('/') +
                                         QFileInfo(file).fileName()))
                    << file;
                ++count;
            }
        }
        // The seeds hold at least the built-in scenes; an empty list means a wrong path.
        if (count < 10)
            qFatal("tst_fuzz_corpus: only %d files found under %s", count, qPrintable(root));
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
