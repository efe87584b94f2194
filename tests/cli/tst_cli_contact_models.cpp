// phasebox-cli and the contact models (CONTRACT §6): --contact-model, the scene keys and their
// refusals, info's report of the penalty stiffness, and a stiff penalty contact reported as
// diverged with the stability advisor's largest stable step.

#include "CliTestSupport.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace phasebox::testing;

namespace {

// A 1 kg ball of radius 0.1 m above a plane at y = 0; `simulation` and `effects` are spliced in.
QByteArray ballScene(const QByteArray& simulation, const QByteArray& effects, double y = 0.2,
                     double vy = 0.0) {
    return R"({"format": "phasebox-scene", "version": 2,
               "simulation": {)" +
           simulation + R"(},
               "effects": {)" +
           effects + R"(},
               "particles": [{"id": "ball", "position": [0, )" +
           QByteArray::number(y) + R"(], "velocity": [0, )" + QByteArray::number(vy) +
           R"(], "radius": 0.1, "restitution": 0, "friction": 0}],
               "planes": [{"point": [0, 0], "normal": [0, 1], "restitution": 0, "friction": 0}]})";
}

// Boxes of 0.5 m standing one on another on a floor at y = 0 (one box: a box on the floor), with
// the contact model given.
QByteArray towerScene(int boxes, const QByteArray& model) {
    QByteArray list;
    for (int i = 0; i < boxes; ++i)
        list += (i ? ", " : "") + QByteArray(R"({"id": "b)") + QByteArray::number(i) +
                R"(", "position": [0, )" + QByteArray::number(0.25 + 0.5 * i) +
                R"(], "size": [0.5, 0.5]})";
    return R"({"format": "phasebox-scene", "version": 2,
               "simulation": {"contact_model": ")" +
           model + R"("}, "effects": {"gravity": {}}, "boxes": [)" + list + R"(],
               "planes": [{"id": "floor", "point": [0, 0], "normal": [0, 1]}]})";
}

}  // namespace

class TestCliContactModels : public QObject {
    Q_OBJECT

private slots:
    void stiffPenaltyDivergesWithTheAdvisorsStep() {
        // k = 1e7 on a 1 kg ball: ω = 3162 rad/s, so symplectic Euler at 1/60 (ω·h = 53) blows
        // up; the report gives the advisor's largest stable sub-step, 1/ω = 0.000316 s.
        QTemporaryDir dir;
        const QString scene =
            writeFile(dir, "stiff.json",
                      ballScene(R"("contact_model": "penalty", "contact_stiffness": 1e7)",
                                R"("gravity": {})"));
        const CliResult r = runCli({"run", scene, "--duration", "2"});
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.contains("diverged") && r.err.contains("0.000316"), r.err.constData());
        QVERIFY(r.err.startsWith("phasebox-cli: "));
        QCOMPARE(r.err.count('\n'), 1);

        // Implicit Euler rests the ball on the plane, sunk by m·g/k.
        const CliResult implicit =
            runCli({"run", scene, "--duration", "2", "--integrator", "implicit_euler", "--json"});
        QCOMPARE(implicit.status, 0);
        const QJsonObject ball =
            QJsonDocument::fromJson(implicit.out).object()["objects"].toObject()["ball"].toObject();
        const double y = ball["position"].toArray()[1].toDouble();
        const double vy = ball["velocity"].toArray()[1].toDouble();
        QVERIFY2(std::abs(y - (0.1 - 9.81 / 1e7)) < 1e-6, qPrintable(QString::number(y, 'g', 10)));
        QVERIFY(std::abs(vy) < 1e-6);
    }

    void contactModelOptionSwitchesTheResponse() {
        // The same scene under each model, chosen on the command line: the ball thrown down at
        // 2 m/s with no gravity and e = 0 stops dead under impulse and kinematic and leaves at
        // e·v under a damped penalty, e = exp(−ζπ/√(1 − ζ²)).
        QTemporaryDir dir;
        const double k = 1e4, m = 1.0, zeta = 0.2, v = 2.0;
        const double c = zeta * 2.0 * std::sqrt(k * m);
        const QString scene =
            writeFile(dir, "ball.json",
                      ballScene(R"("integrator": "rk4", "dt": 0.0001, "contact_stiffness": 1e4, )"
                                R"("contact_damping": )" +
                                    QByteArray::number(c, 'g', 17),
                                "", 0.11, -v));
        const auto finalVy = [&](const char* model) {
            const CliResult r =
                runCli({"run", scene, "--duration", "0.1", "--contact-model", model, "--json"});
            if (r.status != 0) qWarning("%s", r.err.constData());
            return QJsonDocument::fromJson(r.out)
                .object()["objects"]
                .toObject()["ball"]
                .toObject()["velocity"]
                .toArray()[1]
                .toDouble();
        };
        const double e = std::exp(-zeta * std::numbers::pi / std::sqrt(1.0 - zeta * zeta));
        const double penalty = finalVy("penalty");
        qInfo("penalty exit speed %.5f m/s, e*v = %.5f m/s", penalty, e * v);
        // The step that straddles the touch samples the kink in the force: an error of order
        // ω·h (0.01 here) times a fraction of v, the only one that does not shrink as h⁴.
        QVERIFY(std::abs(penalty - e * v) <= 2e-3 * v);
        QVERIFY(std::abs(finalVy("kinematic")) < 1e-9);
        QVERIFY(std::abs(finalVy("impulse")) < 1e-3);
    }

    void unknownModelIsRefusedWithTheList() {
        QTemporaryDir dir;
        const QString scene = writeFile(dir, "ball.json", ballScene("", ""));
        const CliResult r = runCli({"run", scene, "--contact-model", "springy"});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.contains("unknown contact model \"springy\"; known: impulse, penalty, "
                                "kinematic"),
                 r.err.constData());
    }

    void badSceneValuesAreRefusedWithTheirPath_data() {
        QTest::addColumn<QByteArray>("simulation");
        QTest::addColumn<QByteArray>("message");
        QTest::newRow("model") << QByteArray(R"("contact_model": "springy")")
                               << QByteArray("simulation.contact_model");
        QTest::newRow("stiffness 0") << QByteArray(R"("contact_stiffness": 0)")
                                     << QByteArray("simulation.contact_stiffness: must be > 0");
        QTest::newRow("stiffness < 0") << QByteArray(R"("contact_stiffness": -5)")
                                       << QByteArray("simulation.contact_stiffness: must be > 0");
        QTest::newRow("damping < 0") << QByteArray(R"("contact_damping": -1)")
                                     << QByteArray("simulation.contact_damping: must be >= 0");
    }
    void badSceneValuesAreRefusedWithTheirPath() {
        QFETCH(QByteArray, simulation);
        QFETCH(QByteArray, message);
        QTemporaryDir dir;
        const QString scene = writeFile(dir, "bad.json", ballScene(simulation, ""));
        const CliResult r = runCli({"run", scene});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.contains(message), r.err.constData());
        if (simulation.contains("springy"))
            QVERIFY2(r.err.contains("impulse") && r.err.contains("kinematic"), r.err.constData());
    }

    void accuracyLabRunsOnAPenaltyScene() {
        // The work-precision study of a stiff, damped penalty bounce (k = 1e4, ζ = 0.1): every
        // method's error against the rk45 reference shrinks as dt does (over the default six
        // halvings by at least ten), the note says why no order is given, and the diagram is
        // drawn.
        QTemporaryDir dir;
        const QString scene =
            writeFile(dir, "bounce.json",
                      ballScene(R"("contact_model": "penalty", "contact_stiffness": 1e4, )"
                                R"("contact_damping": 20, "dt": 0.01, "duration": 1)",
                                R"("gravity": {})", 0.6));
        const QString plot = dir.filePath("wp.png");
        const CliResult r = runCli({"accuracy", scene, "--json", "--integrators",
                                    "symplectic_euler,velocity_verlet,rk4", "--plot", plot});
        QCOMPARE(r.status, 0);
        QVERIFY(QFile::exists(plot));
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QVERIFY(o["contacts"].toBool());
        QVERIFY2(o["note"].toString().startsWith("penalty contacts"),
                 qPrintable(o["note"].toString()));
        const QJsonArray records = o["records"].toArray();
        QCOMPARE(records.size(), 3 * 6);
        for (int m = 0; m < 3; ++m) {
            const QJsonObject coarse = records[6 * m].toObject(),
                              fine = records[6 * m + 5].toObject();
            qInfo("%s: error %.3g at dt %.3g, %.3g at dt %.3g",
                  qPrintable(coarse["integrator"].toString()), coarse["position_error"].toDouble(),
                  coarse["dt"].toDouble(), fine["position_error"].toDouble(),
                  fine["dt"].toDouble());
            QVERIFY(fine["position_error"].toDouble() < 0.1 * coarse["position_error"].toDouble());
            QVERIFY(fine["energy_drift"].toDouble() < 0.1 * coarse["energy_drift"].toDouble());
        }
    }

    void infoReportsThePenaltyStiffness() {
        // Automatic: the lightest body (1 kg) gets ω·h = 0.5 at dt 1/60: k = (0.5·60)² = 900.
        QTemporaryDir dir;
        const QString scene =
            writeFile(dir, "ball.json", ballScene(R"("contact_model": "penalty")", ""));
        const CliResult r = runCli({"info", scene});
        QCOMPARE(r.status, 0);
        QVERIFY2(r.out.contains("contacts:    penalty, stiffness 900 N/m per point (automatic"),
                 r.out.constData());
    }

    // Issue 37: kinematic contacts cannot hold a stack; info and run say so in plain words, and
    // say nothing for a box alone on the floor or for a tower under impulse contacts.
    void kinematicContactsOnAStackAreWarnedOf() {
        QTemporaryDir dir;
        const QString tower = writeFile(dir, "tower.json", towerScene(4, "kinematic"));
        const QString single = writeFile(dir, "single.json", towerScene(1, "kinematic"));
        const QString impulse = writeFile(dir, "impulse.json", towerScene(4, "impulse"));
        const QByteArray warning = "Kinematic contacts cannot hold a stack";

        const CliResult info = runCli({"info", tower});
        QCOMPARE(info.status, 0);
        QVERIFY2(info.out.contains("warning:     " + warning) &&
                     info.out.contains("Use impulse contacts"),
                 info.out.constData());
        const CliResult run = runCli({"run", tower, "--duration", "0.5"});
        QCOMPARE(run.status, 0);
        QVERIFY2(run.err.startsWith("phasebox-cli: warning: " + warning), run.err.constData());
        QCOMPARE(run.err.count('\n'), 1);
        // The option counts as the scene's key does.
        const CliResult chosen =
            runCli({"run", impulse, "--duration", "0.5", "--contact-model", "kinematic"});
        QVERIFY2(chosen.err.contains(warning), chosen.err.constData());

        for (const QString& scene : {single, impulse}) {
            const CliResult quietInfo = runCli({"info", scene});
            QCOMPARE(quietInfo.status, 0);
            QVERIFY2(!quietInfo.out.contains(warning), quietInfo.out.constData());
            const CliResult quietRun = runCli({"run", scene, "--duration", "0.5"});
            QCOMPARE(quietRun.status, 0);
            QVERIFY2(quietRun.err.isEmpty(), quietRun.err.constData());
        }
    }
};

QTEST_GUILESS_MAIN(TestCliContactModels)
#include "tst_cli_contact_models.moc"
