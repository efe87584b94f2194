// phasebox-cli and sleeping (CONTRACT §6): `--json` reports `sleeping`, the number of bodies
// asleep at the end (0 with sleeping off), jointed ones included; a version 1 file that asks for
// sleep is read as version 2.

#include "CliTestSupport.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace phasebox::testing;

namespace {

// Two 0.5 m boxes resting one on the other on a floor, a third one sliding along the floor far
// to the side, and a ball swinging on a spring; `sleep` spliced into simulation.
QByteArray scene(const QByteArray& sleep) {
    return R"({"format": "phasebox-scene", "version": 2,
               "simulation": {)" +
           sleep + R"(},
               "effects": {"gravity": {}},
               "boxes": [{"id": "b0", "position": [0, 0.25], "size": [0.5, 0.5]},
                         {"id": "b1", "position": [0, 0.75], "size": [0.5, 0.5]},
                         {"id": "slider", "position": [20, 0.25], "size": [0.5, 0.5],
                          "velocity": [3, 0], "friction": 0}],
               "particles": [{"id": "bob", "position": [-5, 2], "radius": 0}],
               "springs": [{"a": "bob", "anchor": [-4, 3], "stiffness": 100}],
               "planes": [{"id": "floor", "point": [0, 0], "normal": [0, 1], "friction": 0}]})";
}

QJsonObject runJson(const QString& path, const QStringList& extra = {}) {
    const CliResult r = runCli(QStringList{"run", path, "--duration", "3", "--json"} + extra);
    if (r.status != 0) qWarning("%s", r.err.constData());
    return QJsonDocument::fromJson(r.out).object();
}

}  // namespace

class TestCliSleeping : public QObject {
    Q_OBJECT

private slots:
    void jsonReportsTheBodiesAsleep() {
        QTemporaryDir dir;
        // The stack sleeps; the slider and the swinging bob do not.
        const QJsonObject on = runJson(writeFile(dir, "on.json", scene(R"("sleep": true)")));
        QVERIFY(on.contains("sleeping"));
        QCOMPARE(on["sleeping"].toInt(), 2);
        QCOMPARE(on["diverged"].toBool(), false);
        // Off (explicitly or by default) nothing sleeps, and the key is still there.
        for (const QByteArray& off : {QByteArray(R"("sleep": false)"), QByteArray()}) {
            const QJsonObject report = runJson(writeFile(dir, "off.json", scene(off)));
            QVERIFY(report.contains("sleeping"));
            QCOMPARE(report["sleeping"].toInt(), 0);
        }
        // A switch of method on the command line is made before the run: it sleeps the same.
        const QJsonObject rk4 = runJson(dir.filePath("on.json"), {"--integrator", "rk4"});
        QCOMPARE(rk4["sleeping"].toInt(), 2);
    }

    // Bodies asleep with their joints count as well: three links hanging at rest from a hinge.
    void jointedSleepersAreCounted() {
        QTemporaryDir dir;
        const QByteArray chain = R"({"format": "phasebox-scene", "version": 2,
               "simulation": {"sleep": true}, "effects": {"gravity": {}},
               "boxes": [{"id": "l0", "position": [0, -0.25], "size": [0.1, 0.5]},
                         {"id": "l1", "position": [0, -0.75], "size": [0.1, 0.5]},
                         {"id": "l2", "position": [0, -1.25], "size": [0.1, 0.5]}],
               "joints": [{"type": "hinge", "a": "l0", "anchor": [0, 0]},
                          {"type": "hinge", "a": "l1", "b": "l0", "anchor": [0, -0.5]},
                          {"type": "hinge", "a": "l2", "b": "l1", "anchor": [0, -1]}]})";
        const QJsonObject report = runJson(writeFile(dir, "chain.json", chain));
        QCOMPARE(report["sleeping"].toInt(), 3);
    }

    void versionOneFileWithSleepIsReadAsVersionTwo() {
        QTemporaryDir dir;
        QByteArray v1 = scene(R"("sleep": true)");
        v1.replace(R"("version": 2)", R"("version": 1)");
        const QJsonObject report = runJson(writeFile(dir, "v1.json", v1));
        QCOMPARE(report["sleeping"].toInt(), 2);
    }
};

QTEST_GUILESS_MAIN(TestCliSleeping)
#include "tst_cli_sleeping.moc"
