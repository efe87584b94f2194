// phasebox-cli end to end: every command, option, output and exit code of CONTRACT.md §4,
// run as a user would, through the real binary.

#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "CliTestSupport.h"
#include "app/io/SceneIO.h"
#include "physics/scene/SceneLibrary.h"

#include <cmath>

namespace {

using Result = phasebox::testing::CliResult;

Result cli(const QStringList& args) {
    return phasebox::testing::runCli(args);
}

// A unit harmonic oscillator: m = 1 on a spring k = 1 to the origin, x(0) = 1.
const char* kOscillator = R"({
  "format": "phasebox-scene", "version": 1, "name": "oscillator",
  "simulation": { "integrator": "rk4", "dt": 0.01, "duration": 3.14159265358979 },
  "particles": [ { "id": "ball", "position": [1, 0], "mass": 1 } ],
  "springs": [ { "a": "ball", "anchor": [0, 0], "stiffness": 1, "rest_length": 0 } ]
})";

// k = 1e6 with m = 1 at dt = 1/60: ω·h ≈ 16.7, far past every explicit method's limit.
const char* kStiff = R"({
  "format": "phasebox-scene", "version": 1, "name": "stiff spring",
  "simulation": { "integrator": "explicit_euler", "dt": 0.016666666666666666, "duration": 10 },
  "particles": [ { "id": "bob", "position": [0, -1.1], "mass": 1 } ],
  "springs": [ { "a": "bob", "anchor": [0, 0], "stiffness": 1e6, "rest_length": 1 } ],
  "effects": { "gravity": {} }
})";

const char* kMixed = R"({
  "format": "phasebox-scene", "version": 1, "name": "mixed",
  "simulation": { "integrator": "symplectic_euler", "dt": 0.02, "duration": 1 },
  "effects": { "gravity": {}, "drag": { "linear": 0.1 } },
  "particles": [ { "id": "p", "position": [0, 0], "velocity": [1, 2] } ],
  "boxes": [ { "id": "crate", "position": [2, 0], "size": [1, 0.5], "angular_velocity": 1 } ],
  "cloths": [ { "id": "flag", "origin": [5, 0], "size": [1, 1], "resolution": [3, 3],
                "stiffness": { "structural": 100, "shear": 10, "bend": 1 } } ]
})";

}  // namespace

class TestCli : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;

    QString write(const QString& name, const char* text) {
        return phasebox::testing::writeFile(dir_, name, text);
    }

private slots:
    void integratorsListsAllTen() {
        const Result r = cli({"integrators"});
        QCOMPARE(r.status, 0);
        const QStringList lines = QString::fromUtf8(r.out).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 11);  // header + 10
        const QStringList names{
            "explicit_euler",  "symplectic_euler", "midpoint",          "heun",           "rk4",
            "velocity_verlet", "implicit_euler",   "implicit_midpoint", "adaptive_euler", "rk45"};
        for (int i = 0; i < names.size(); ++i)
            QCOMPARE(lines[i + 1].split(' ', Qt::SkipEmptyParts).first(), names[i]);
        QVERIFY(lines[5].contains(" 4 ") && lines[5].contains("explicit"));   // rk4
        QVERIFY(lines[7].contains("implicit") && lines[7].contains(" no "));  // implicit_euler
        QVERIFY(lines[2].contains(" yes "));                                  // symplectic_euler
    }

    void infoNamesEffectsAndObjects() {
        const Result r = cli({"info", write("mixed.json", kMixed)});
        QCOMPARE(r.status, 0);
        const QString text = QString::fromUtf8(r.out);
        QVERIFY2(text.contains("effects that will run: gravity drag springs contacts"),
                 qPrintable(text));
        QVERIFY(text.contains("symplectic_euler"));
        QVERIFY(text.contains("0.02"));
        QVERIFY(text.contains("cloths     1 (9 nodes"));
    }

    // Issue #38: info counted disks and polygons as boxes and never mentioned joints.
    void infoCountsDisksPolygonsAndJointsApart() {
        const Result r = cli({"info", write("shapes.json", R"({
  "format": "phasebox-scene", "version": 2, "name": "shapes",
  "particles": [ { "id": "p", "position": [0, 3] } ],
  "boxes": [ { "id": "b", "position": [0, 0], "size": [1, 1] },
             { "id": "floor", "position": [0, -5], "size": [10, 1], "static": true } ],
  "disks": [ { "id": "d1", "position": [2, 0], "radius": 0.5 },
             { "id": "d2", "position": [4, 0], "radius": 0.5, "static": true },
             { "id": "d3", "position": [6, 0], "radius": 0.5 } ],
  "polygons": [ { "id": "tri", "position": [8, 0], "vertices": [[0, 0], [1, 0], [0, 1]] } ],
  "joints": [ { "type": "rod", "a": "p", "b": "b" }, { "type": "hinge", "a": "d1", "anchor": [2, 1] } ]
})")});
        QVERIFY2(r.status == 0, r.err.constData());
        const QString text = QString::fromUtf8(r.out);
        QVERIFY2(text.contains("  boxes      2 (1 static)\n"), qPrintable(text));
        QVERIFY2(text.contains("  disks      3 (1 static)\n"), qPrintable(text));
        QVERIFY2(text.contains("  polygons   1 (0 static)\n"), qPrintable(text));
        QVERIFY2(text.contains("  joints     2\n"), qPrintable(text));
    }

    void runJsonHasEveryField() {
        const Result r = cli({"run", write("mixed.json", kMixed), "--json"});
        QCOMPARE(r.status, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        for (const char* key : {"integrator", "dt", "substeps", "steps", "sim_time", "wall_seconds",
                                "step_ms", "energy", "diverged", "effects", "objects"})
            QVERIFY2(o.contains(key), key);
        QCOMPARE(o["integrator"].toString(), QString("symplectic_euler"));
        QCOMPARE(o["steps"].toInt(), 50);
        QCOMPARE(o["sim_time"].toDouble(), 1.0);
        QCOMPARE(o["diverged"].toBool(), false);
        for (const char* key : {"median", "mean", "max"})
            QVERIFY(o["step_ms"].toObject().contains(key));
        for (const char* key :
             {"initial", "kinetic", "potential", "work_nc", "drift", "max_abs_drift", "correction"})
            QVERIFY(o["energy"].toObject().contains(key));
        QStringList effects;
        for (const QJsonValue& e : o["effects"].toArray()) {
            effects << e.toObject()["name"].toString();
            QVERIFY(e.toObject()["ms_per_step"].toDouble() >= 0.0);
        }
        // A box and disks that can touch: the contact stage runs and reports its cost too.
        QCOMPARE(effects, (QStringList{"gravity", "drag", "springs", "contacts"}));
        const QJsonObject objects = o["objects"].toObject();
        QCOMPARE(objects.size(), 1 + 1 + 9);  // cloth nodes included
        QVERIFY(objects.contains("flag[2,1]"));
        const QJsonObject crate = objects["crate"].toObject();
        QVERIFY(crate.contains("angle") && crate.contains("angular_velocity"));
        QCOMPARE(crate["position"].toArray().size(), 2);
        QVERIFY(!objects["p"].toObject().contains("angle"));
        // Drag did work, and it is booked: work_nc < 0.
        QVERIFY(o["energy"].toObject()["work_nc"].toDouble() < 0.0);
    }

    void runJsonReportsTheStagesOfTheStep_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("stages");
        // Nothing can touch on the oscillator: no collide, no contact solve.
        QTest::newRow("oscillator")
            << QString("oscillator") << QStringList{"integrate", "ledger", "guard"};
        QTest::newRow("box pyramid")
            << QString("pyramid")
            << QStringList{"integrate", "collide", "solve contacts", "ledger", "guard"};
    }

    void runJsonReportsTheStagesOfTheStep() {
        QFETCH(QString, scene);
        QFETCH(QStringList, stages);
        const QString path =
            scene == "oscillator"
                ? write("oscillator.json", kOscillator)
                : QStringLiteral(PHASEBOX_SOURCE_DIR "/resources/scenes/box-pyramid.phasebox.json");
        const Result r = cli({"run", path, "--json", "--duration", "2"});
        QCOMPARE(r.status, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QStringList names;
        double sum = 0.0;
        for (const QJsonValue& s : o["stages"].toArray()) {
            names << s.toObject()["name"].toString();
            const double ms = s.toObject()["ms_per_step"].toDouble();
            QVERIFY(ms >= 0.0);
            sum += ms;
        }
        // In the order they run (CONTRACT.md §7).
        QCOMPARE(names, stages);
        // Their sum is the mean step, less only the clock reads around World::step(). On the
        // oscillator a step is a microsecond, where those reads are a tenth of it: allow 20%
        // and a microsecond.
        const double mean = o["step_ms"].toObject()["mean"].toDouble();
        QVERIFY2(std::abs(sum - mean) <= 0.2 * mean + 1e-3,
                 qPrintable(QString("stages %1 ms, mean step %2 ms").arg(sum).arg(mean)));
    }

    void runMatchesTheExactOscillator() {
        // rk4 at dt = 0.01 over half a period: x(π) = −1 to ~1e-9.
        const Result r = cli({"run", write("osc.json", kOscillator), "--json"});
        QCOMPARE(r.status, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        const double t = o["sim_time"].toDouble();
        const QJsonArray x = o["objects"].toObject()["ball"].toObject()["position"].toArray();
        QVERIFY(std::abs(x[0].toDouble() - std::cos(t)) < 1e-8);
        QVERIFY(std::abs(o["energy"].toObject()["drift"].toDouble()) < 1e-9);
    }

    void runOverridesSettings() {
        const Result r = cli({"run", write("osc.json", kOscillator), "--json", "--integrator",
                              "heun", "--dt", "0.05", "--substeps", "2", "--duration", "1"});
        QCOMPARE(r.status, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o["integrator"].toString(), QString("heun"));
        QCOMPARE(o["dt"].toDouble(), 0.05);
        QCOMPARE(o["substeps"].toInt(), 2);
        QCOMPARE(o["steps"].toInt(), 20);
    }

    void csvHeaderRowsAndEvery() {
        const QString csv = dir_.filePath("out.csv");
        const Result r = cli({"run", write("mixed.json", kMixed), "--csv", csv, "--every", "7"});
        QCOMPARE(r.status, 0);
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(
            lines.first(),
            QString(
                "t,kinetic,potential,work_nc,drift,correction,constraint_error,p.x,p.y,p.vx,p.vy,"
                "crate.x,crate.y,crate.angle,crate.vx,crate.vy,crate.omega"));
        // 50 steps: t = 0, every 7th step (7 … 49), and the end (50).
        QCOMPARE(lines.size(), 1 + 1 + 7 + 1);
        QCOMPARE(lines[1].split(',').first(), QString("0"));
        QCOMPARE(lines.last().split(',').first().toDouble(), 1.0);
        QCOMPARE(lines[2].split(',').size(), 17);
        // The first row holds the initial state exactly.
        QCOMPARE(lines[1].split(',')[9].toDouble(), 1.0);   // p.vx
        QCOMPARE(lines[1].split(',')[10].toDouble(), 2.0);  // p.vy
    }

    void csvTrackChoosesObjects() {
        const Result r =
            cli({"run", write("mixed.json", kMixed), "--csv", "-", "--track", "flag[1,1],crate"});
        QCOMPARE(r.status, 0);
        const QString header = QString::fromUtf8(r.out).section('\n', 0, 0);
        // A node id holds a comma, so its columns are quoted (RFC 4180) and the header still has
        // one field per value of a row.
        QCOMPARE(header, QString("t,kinetic,potential,work_nc,drift,correction,constraint_error,"
                                 "\"flag[1,1].x\",\"flag[1,1].y\","
                                 "\"flag[1,1].vx\",\"flag[1,1].vy\",crate.x,crate.y,crate.angle,"
                                 "crate.vx,crate.vy,crate.omega"));
        const QString firstRow = QString::fromUtf8(r.out).section('\n', 1, 1);
        QCOMPARE(firstRow.count(','), 7 + 4 + 6 - 1);
        const Result bad = cli({"run", write("mixed.json", kMixed), "--track", "nobody"});
        QCOMPARE(bad.status, 2);
        QVERIFY(bad.err.contains("unknown object id \"nobody\""));
    }

    void plotsArePictures() {
        const QString png = dir_.filePath("energy.png"), svg = dir_.filePath("phase.svg");
        const Result r = cli({"run", write("osc.json", kOscillator), "--plot-energy", png,
                              "--plot-phase", "ball.x", svg});
        QCOMPARE(r.status, 0);
        QImage image(png);
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), QSize(1000, 600));
        QFile f(svg);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        QVERIFY(text.contains("<svg"));
        QVERIFY(text.contains("</svg>"));
        const Result bad =
            cli({"run", write("osc.json", kOscillator), "--plot-phase", "ball.angle", svg});
        QCOMPARE(bad.status, 2);
    }

    void stiffSpringDivergesUnderExplicitEuler() {
        const Result r = cli({"run", write("stiff.json", kStiff), "--json"});
        QCOMPARE(r.status, 1);
        const QString err = QString::fromUtf8(r.err);
        QVERIFY2(err.contains("diverged at t = ") && err.contains("\"bob\""), qPrintable(err));
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o["diverged"].toBool(), true);
        QVERIFY(o["sim_time"].toDouble() < 10.0);
        // The last good state was kept: finite, not NaN.
        const QJsonArray x = o["objects"].toObject()["bob"].toObject()["position"].toArray();
        QVERIFY(std::isfinite(x[0].toDouble()) && std::isfinite(x[1].toDouble()));
        QVERIFY(o["objects"].toObject()["bob"].toObject()["position"].toArray()[1].isDouble());
    }

    void stiffSpringStaysBoundedUnderImplicitEuler() {
        const Result r =
            cli({"run", write("stiff.json", kStiff), "--json", "--integrator", "implicit_euler"});
        QCOMPARE(r.status, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o["sim_time"].toDouble(), 10.0);
        const QJsonObject e = o["energy"].toObject();
        QVERIFY(e["kinetic"].toDouble() + e["potential"].toDouble() <=
                e["initial"].toDouble() + 1e-9);
    }

    void clothBlowUpIsReported() {
        // The 40 x 40 cloth of tests/stability/tst_cloth.cpp (stiffness 2e4, dt = 1/60) under
        // symplectic Euler: the run stops with status 1 and names a cloth node.
        const QString path = dir_.filePath("cloth.json");
        QString error;
        QVERIFY2(phasebox::SceneIO::save(phasebox::scenes::cloth(40, 2e4), path, &error),
                 qPrintable(error));
        const Result r = cli({"run", path, "--integrator", "symplectic_euler", "--duration", "2"});
        QCOMPARE(r.status, 1);
        const QString err = QString::fromUtf8(r.err);
        QVERIFY2(err.contains("diverged at t = ") && err.contains("cloth["), qPrintable(err));
    }

    void badInputExitsTwo_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("no command") << QStringList{} << "usage";
        QTest::newRow("unknown command") << QStringList{"fly"} << "unknown command \"fly\"";
        QTest::newRow("missing file")
            << QStringList{"run", "/nonexistent/x.json"} << "/nonexistent/x.json";
        QTest::newRow("unknown option")
            << QStringList{"run", "SCENE", "--fast"} << "unknown option \"--fast\"";
        QTest::newRow("dt zero") << QStringList{"run", "SCENE", "--dt", "0"} << "--dt: must be > 0";
        QTest::newRow("dt text") << QStringList{"run", "SCENE", "--dt", "abc"}
                                 << "--dt: must be a number";
        QTest::newRow("substeps") << QStringList{"run", "SCENE", "--substeps", "0"} << "--substeps";
        QTest::newRow("integrator") << QStringList{"run", "SCENE", "--integrator", "rk5"}
                                    << "unknown integrator \"rk5\"; known: explicit_euler";
        QTest::newRow("info no scene") << QStringList{"info"} << "usage";
    }
    void badInputExitsTwo() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        args.replaceInStrings("SCENE", write("osc.json", kOscillator));
        const Result r = cli(args);
        QCOMPARE(r.status, 2);
        QVERIFY2(QString::fromUtf8(r.err).contains(message), r.err.constData());
    }

    void invalidSceneExitsTwoWithPath() {
        const QString path = write("bad.json", R"({"format": "phasebox-scene", "version": 1,
            "particles": [ { "position": [0, 0], "mass": -1 } ] })");
        const Result r = cli({"run", path});
        QCOMPARE(r.status, 2);
        const QString err = QString::fromUtf8(r.err);
        QVERIFY2(err.startsWith("phasebox-cli: error: "), qPrintable(err));
        QVERIFY2(
            err.contains(path) && err.contains("particles[0].mass") && err.contains("must be > 0"),
            qPrintable(err));
        const Result syntax =
            cli({"info", write("syntax.json", "{\n  \"format\": \"phasebox-scene\",\n  oops\n}")});
        QCOMPARE(syntax.status, 2);
        QVERIFY2(syntax.err.contains("syntax.json:3:"), syntax.err.constData());
    }

    void demoSceneRuns() {
        const Result r =
            cli({"run", QStringLiteral(PHASEBOX_SOURCE_DIR "/resources/scenes/demo.phasebox.json"),
                 "--duration", "2"});
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.contains("drift:"));
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
