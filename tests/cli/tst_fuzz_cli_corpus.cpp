// Replays the command-line output fuzzer's seeds (tests/fuzz/corpus-cli) and every reproducer
// kept from it (tests/fuzz/regressions-cli) through the fuzzer's own check
// (tests/fuzz/CliOutputCheck.h), without libFuzzer, in every CI run: outputs onto files, full
// and null devices, folders, missing folders, the scene itself and standard output.

#include "tests/fuzz/CliOutputCheck.h"

#include <QDirIterator>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

class TestFuzzCliCorpus : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;
    QSet<int> statuses_;

private slots:
    void replay_data() {
        QTest::addColumn<QString>("path");
        const QString root = QStringLiteral(PHASEBOX_SOURCE_DIR) + QStringLiteral("/tests/fuzz/");
        int count = 0;
        for (const char* folder : {"corpus-cli", "regressions-cli"}) {
            QDirIterator it(root + QLatin1String(folder), QDir::Files | QDir::Hidden);
            QStringList files;
            while (it.hasNext()) {
                const QString file = it.next();
                if (!file.endsWith(QLatin1String("/README.md"))) files << file;
            }
            files.sort();
            for (const QString& file : files) {
                QTest::newRow(qPrintable(QLatin1String(folder) + QLatin1Char('/') +
                                         QFileInfo(file).fileName()))
                    << file;
                ++count;
            }
        }
        if (count < 10)
            qFatal("tst_fuzz_cli_corpus: only %d files found under %s", count, qPrintable(root));
    }

    void replay() {
        QFETCH(QString, path);
        QVERIFY(dir_.isValid());
        QFile file(path);
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(path + ": " + file.errorString()));
        const QByteArray bytes = file.readAll();
        phasebox::fuzz::CliWorkspace workspace(dir_.filePath(QStringLiteral("work")));
        int status = -1;
        const QString broken = phasebox::fuzz::checkCliOutputInput(
            reinterpret_cast<const std::uint8_t*>(bytes.constData()),
            static_cast<std::size_t>(bytes.size()), workspace, &status);
        QVERIFY2(broken.isEmpty(), qPrintable(broken));
        statuses_.insert(status);
    }

    // The seeds reach every outcome: written (0), refused (2), failed to write (3). A seed
    // list that only ever hit bad input would check nothing of the writing.
    void seedsReachEveryOutcome() {
        for (const int status : {0, 2, 3})
            QVERIFY2(statuses_.contains(status),
                     qPrintable(QStringLiteral("no seed exits %1").arg(status)));
    }
};

QTEST_MAIN(TestFuzzCliCorpus)
#include "tst_fuzz_cli_corpus.moc"
