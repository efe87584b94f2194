// `--threads N` (CONTRACT §4): run, accuracy and render take it; every output but the timings
// is bit-identical for every N; N is an integer from 1 to 1024, anything else is refused with
// exit 2 and the option named.

#include "CliTestSupport.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace phasebox::testing;

namespace {

QByteArray pile() {
    return R"({"format": "phasebox-scene", "version": 2,
               "simulation": {"duration": 1},
               "effects": {"gravity": {}},
               "boxes": [{"id": "b0", "position": [0, 0.5], "size": [1, 1]},
                         {"id": "b1", "position": [0.2, 1.6], "size": [1, 1], "angle": 0.3},
                         {"id": "b2", "position": [-0.1, 2.8], "size": [1, 1]}],
               "disks": [{"id": "d0", "position": [1.5, 3], "radius": 0.4}],
               "planes": [{"id": "floor", "point": [0, 0], "normal": [0, 1]}]})";
}

// The report without what is measured in time.
QJsonObject withoutTimings(QJsonObject o) {
    for (const char* key : {"wall_seconds", "step_ms", "stages", "effects"}) o.remove(key);
    return o;
}

}  // namespace

class TestCliThreads : public QObject {
    Q_OBJECT

private slots:
    // The whole report but its timings, its JSON text byte for byte, and the CSV are the same
    // for 1, 2 and 4 workers: a small pile (its bottom box pressed by the ones on it) and the
    // 40-row pyramid, large enough that the workers share its contact stage.
    void everyWorkerCountGivesTheSameRun_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("duration");
        QTest::newRow("pile") << QString() << QString("1");
        QTest::newRow("pyramid40") << QString("pyramid40") << QString("0.25");
    }
    void everyWorkerCountGivesTheSameRun() {
        QFETCH(QString, scene);
        QFETCH(QString, duration);
        QTemporaryDir dir;
        QString path = dir.filePath("scene.json");
        if (scene.isEmpty()) {
            path = writeFile(dir, "pile.json", pile());
        } else {
            const CliResult made = runCli({"scene", scene, path});
            QVERIFY2(made.status == 0, made.err.constData());
        }
        const QString probe = scene.isEmpty() ? "contact_force(b0)" : "contact_force(r0c0)";
        QJsonObject first;
        QByteArray firstJson, firstCsv;
        for (const char* n : {"1", "2", "4"}) {
            const CliResult json = runCli(
                {"run", path, "--json", "--duration", duration, "--probe", probe, "--threads", n});
            QVERIFY2(json.status == 0, json.err.constData());
            const QJsonObject report = withoutTimings(QJsonDocument::fromJson(json.out).object());
            // A contact scene: the bottom box carries the ones above it.
            QVERIFY(report.value("probes")
                        .toObject()
                        .value(probe)
                        .toObject()
                        .value("final")
                        .toDouble() > 0.0);
            QVERIFY(report.contains("objects"));
            QVERIFY(!report.contains("threads"));
            const QByteArray text = QJsonDocument(report).toJson(QJsonDocument::Compact);
            const CliResult csv =
                runCli({"run", path, "--csv", "-", "--duration", duration, "--threads", n});
            QCOMPARE(csv.status, 0);
            if (first.isEmpty()) {
                first = report;
                firstJson = text;
                firstCsv = csv.out;
                continue;
            }
            QCOMPARE(report, first);
            QCOMPARE(text, firstJson);
            QCOMPARE(csv.out, firstCsv);
        }
    }

    void badCountsAreRefused_data() {
        QTest::addColumn<QString>("command");
        QTest::addColumn<QString>("count");
        QTest::addColumn<QString>("message");
        for (const char* command : {"run", "accuracy", "render"}) {
            QTest::addRow("%s 0", command) << command << "0"
                                           << "--threads: must be >= 1";
            QTest::addRow("%s 1025", command) << command << "1025"
                                              << "--threads: must be >= 1";
            QTest::addRow("%s two", command) << command << "two"
                                             << "--threads: must be an integer";
            QTest::addRow("%s empty", command) << command << ""
                                               << "--threads: must be an integer";
        }
    }
    void badCountsAreRefused() {
        QFETCH(QString, command);
        QFETCH(QString, count);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString scene = writeFile(dir, "pile.json", pile());
        QStringList args{command, scene, "--threads", count};
        if (command == QLatin1String("render")) args << "--out" << dir.filePath("clip.gif");
        const CliResult r = runCli(args);
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.contains(message.toUtf8()), r.err.constData());
        QVERIFY(!QFile::exists(dir.filePath("clip.gif")));
    }

    void accuracyAndRenderTakeACount() {
        QTemporaryDir dir;
        const QString scene = writeFile(dir, "pile.json", pile());
        const CliResult a = runCli({"accuracy", scene, "--integrators", "symplectic_euler", "--dt",
                                    "0.02", "--duration", "0.2", "--threads", "2", "--csv", "-"});
        QCOMPARE(a.status, 0);
        const CliResult r =
            runCli({"render", scene, "--out", dir.filePath("clip.gif"), "--duration", "0.2",
                    "--fps", "10", "--size", "80x60", "--threads", "2"});
        QVERIFY2(r.status == 0, r.err.constData());
        QVERIFY(QFile::exists(dir.filePath("clip.gif")));
    }
};

QTEST_GUILESS_MAIN(TestCliThreads)
#include "tst_cli_threads.moc"
