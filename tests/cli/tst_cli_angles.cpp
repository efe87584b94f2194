// Angles a teacher can measure (issue #37), through the real binary: distance and angle with
// fixed points `X:Y` as arguments (CONTRACT §7), the vertex of angle(A,B,C) in the middle, and
// JOINT.angle, a pendulum's θ from straight down, whose period in `--json` is the elliptic
// closed form T = 4·√(L/g)·K(sin(θ0/2)) of a rod pendulum and of a hinged disk or box (a
// physical pendulum: L = I_pivot/(m·d)), and whose largest value is the release angle.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "CliTestSupport.h"

#include <cmath>
#include <numbers>

namespace {

using Result = phasebox::testing::CliResult;
constexpr double kG = 9.81;
constexpr double kPi = std::numbers::pi;

Result cli(const QStringList& args) {
    return phasebox::testing::runCli(args);
}

// The exact period of a pendulum of (equivalent) length L released from rest at θ0.
double ellipticPeriod(double length, double theta0) {
    return 4.0 * std::sqrt(length / kG) * std::comp_ellint_1(std::sin(0.5 * theta0));
}

QString number(double v) {
    return QString::number(v, 'g', 17);
}

// m = 1 kg on a spring of k = 4 N/m to the origin (rest length 0), released at x = 1 m, so
// x(t) = cos 2t, y = 0.
const char* kSpring = R"({
  "format": "phasebox-scene", "version": 1,
  "simulation": { "integrator": "rk4", "dt": 0.001, "duration": 1 },
  "particles": [ { "id": "ball", "position": [1, 0], "mass": 1 } ],
  "springs": [ { "a": "ball", "anchor": [0, 0], "stiffness": 4, "rest_length": 0 } ]
})";

// A pendulum released from rest at θ0 (counter-clockwise from straight down) about the pivot
// (0, 0): `body` is the JSON array and object of the swinging body, placed by the caller.
QByteArray pendulumScene(const QString& bodies, const QString& joint, double duration) {
    return QStringLiteral(R"({
  "format": "phasebox-scene", "version": 2,
  "simulation": { "integrator": "rk4", "dt": 0.0005, "duration": %1 },
  "effects": { "gravity": { "g": [0, -9.81] } },
  %2,
  "joints": [ %3 ]
})")
        .arg(number(duration), bodies, joint)
        .toUtf8();
}

struct Swing {
    double period = 0.0, min = 0.0, max = 0.0, first = 0.0, second = 0.0;
};

}  // namespace

class TestCliAngles : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;

    QString write(const QString& name, const QByteArray& text) {
        return phasebox::testing::writeFile(dir_, name, text);
    }

    // Runs the scene with the probe and reads its statistics (and the first two samples).
    Swing swing(const QString& name, const QByteArray& scene, const QString& probe) {
        Swing s;
        const QString path = write(name, scene);
        const Result r = cli({"run", path, "--json", "--probe", probe});
        if (r.status != 0) qWarning("%s", r.err.constData());
        const QJsonObject p = QJsonDocument::fromJson(r.out)["probes"][probe].toObject();
        s.period = p["period"].toDouble(std::nan(""));
        s.min = p["min"].toDouble(std::nan(""));
        s.max = p["max"].toDouble(std::nan(""));
        const Result rows =
            cli({"run", path, "--duration", "0.001", "--csv", "-", "--probe", probe});
        const QStringList lines = QString::fromUtf8(rows.out).split('\n', Qt::SkipEmptyParts);
        if (lines.size() >= 3) {
            s.first = lines[1].split(',').last().toDouble();
            s.second = lines[2].split(',').last().toDouble();
        }
        return s;
    }

    // The period against the closed form, the release angle as the largest value and its
    // mirror as the smallest (no energy lost), and the sign: θ falls from +θ0 after release.
    void checkSwing(const char* what, const Swing& s, double lengthEq, double theta0) {
        const double expected = ellipticPeriod(lengthEq, theta0);
        qInfo(
            "%s: period %.9f s, closed form %.9f s (relative error %.2e); max %.12f, "
            "theta0 %.12f, min %.12f",
            what, s.period, expected, s.period / expected - 1.0, s.max, theta0, s.min);
        // RK4 at dt = 0.5 ms over five periods: a period error of 1e-12 measured, held to 1e-8.
        QVERIFY(std::abs(s.period / expected - 1.0) < 1e-8);
        QVERIFY(std::abs(s.max - theta0) < 1e-12);
        QVERIFY(std::abs(s.min + theta0) < 1e-7);
        QVERIFY(std::abs(s.first - theta0) < 1e-12);
        QVERIFY(s.second < s.first);
    }

private slots:
    void pointArgumentsAreFixedPoints() {
        const QString spring = write("spring.json", kSpring);
        const QStringList probes = {"distance(ball, -1.5:2e-1)", "distance(0:0,ball)",
                                    "angle(0:0,0:1.5,ball)",     "angle(1:0,0:0,0:1)",
                                    "angle(0:1,0:0,+1:0)",       "angle(1:0,0:0,-1:-0)"};
        QStringList args = {"run", spring, "--csv", "-", "--every", "100"};
        for (const QString& p : probes) args << "--probe" << p;
        const Result r = cli(args);
        QCOMPARE(r.status, 0);
        QVERIFY2(r.err.isEmpty(), r.err.constData());
        const QStringList lines = QString::fromUtf8(r.out).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1 + 11);  // t = 0, every 0.1 s, the end
        for (int i = 1; i < lines.size(); ++i) {
            const QStringList v = lines[i].split(',');
            const double t = v[0].toDouble(), x = v[7].toDouble(), y = v[8].toDouble();
            // RK4 at dt = 1 ms follows x = cos 2t to well below a micrometre.
            QVERIFY(std::abs(x - std::cos(2.0 * t)) < 1e-9);
            QVERIFY(std::abs(y) < 1e-15);
            const int c = 11;  // the probes' first column
            QVERIFY(std::abs(v[c].toDouble() - std::hypot(x + 1.5, y - 0.2)) < 1e-12);
            QVERIFY(std::abs(v[c + 1].toDouble() - std::hypot(x, y)) < 1e-12);
            // The vertex is the middle argument: at (0, 1.5), from straight down to the ball,
            // counter-clockwise positive when the ball is to the right.
            QVERIFY(std::abs(v[c + 2].toDouble() - std::atan2(x, 1.5)) < 1e-12);
            QCOMPARE(v[c + 3].toDouble(), 0.5 * kPi);
            QCOMPARE(v[c + 4].toDouble(), -0.5 * kPi);
            QCOMPARE(v[c + 5].toDouble(), kPi);  // −π is reported as π: (−π, π]
        }
        // At t = 0 the ball is at (1, 0): the closed forms outright.
        const QStringList first = lines[1].split(',');
        QCOMPARE(first[11].toDouble(), std::hypot(2.5, 0.2));
        QCOMPARE(first[13].toDouble(), std::atan2(1.0, 1.5));

        // What is neither an id nor a point is refused, naming both readings.
        for (const char* bad : {"distance(ball,1:)", "distance(ball,1:2:3)", "distance(ball,x:1)",
                                "angle(ball,0:0)", "contact_force(0:0)"}) {
            const Result refused = cli({"run", spring, "--probe", bad});
            QCOMPARE(refused.status, 2);
            QVERIFY2(refused.err.contains("unknown probe"), bad);
        }
        const Result named = cli({"run", spring, "--probe", "distance(ball,nowhere)"});
        QVERIFY2(named.err.contains("no object \"nowhere\" (nor a point X:Y in metres)"),
                 named.err.constData());
    }

    void rodPendulumAngleHasTheEllipticPeriod() {
        for (const double degrees : {30.0, 90.0}) {
            const double theta0 = degrees * kPi / 180.0, length = 1.5;
            const QString bob =
                QStringLiteral(R"("particles": [ { "id": "bob", "position": [%1, %2] } ])")
                    .arg(number(length * std::sin(theta0)), number(-length * std::cos(theta0)));
            const QString rod =
                QStringLiteral(R"({ "id": "rod", "type": "rod", "a": "bob", "anchor": [0, 0] })");
            const QByteArray scene = pendulumScene(bob, rod, 5.0 * ellipticPeriod(length, theta0));
            checkSwing(qPrintable(QStringLiteral("rod %1 deg").arg(degrees)),
                       swing("rod.json", scene, "rod.angle"), length, theta0);
        }
    }

    void hingedBodiesSwingAsPhysicalPendulums() {
        // A disk (I = m·r²/2) and a box (I = m·(w² + h²)/12) hinged to the world at a distance
        // d from their centres: L = I_pivot/(m·d) = (I + m·d²)/(m·d).
        struct Body {
            const char* name;
            QString json;
            double inertiaPerMass, d, degrees;
        };
        const double d = 0.8;
        const Body bodies[] = {
            {"disk",
             R"("disks": [ { "id": "body", "position": [%1, %2], "radius": 0.3, "mass": 2, "angle": %3 } ])",
             0.5 * 0.3 * 0.3, d, 30.0},
            {"box",
             R"("boxes": [ { "id": "body", "position": [%1, %2], "size": [0.4, 1.2], "angle": %3 } ])",
             (0.4 * 0.4 + 1.2 * 1.2) / 12.0, d, 90.0},
        };
        for (const Body& b : bodies) {
            const double theta0 = b.degrees * kPi / 180.0;
            const QString json = QString(b.json).arg(
                number(b.d * std::sin(theta0)), number(-b.d * std::cos(theta0)), number(theta0));
            const QString hinge = QStringLiteral(
                R"({ "id": "pivot", "type": "hinge", "a": "body", "anchor": [0, 0] })");
            const double lengthEq = (b.inertiaPerMass + b.d * b.d) / b.d;
            const QByteArray scene =
                pendulumScene(json, hinge, 5.0 * ellipticPeriod(lengthEq, theta0));
            checkSwing(b.name, swing(QStringLiteral("%1.json").arg(b.name), scene, "pivot.angle"),
                       lengthEq, theta0);
        }
    }

    void hingedDiskOscillatesForTheAdvisorAndTheLab() {
        // A disk (r = 0.3 m) hinged at d = 0.8 m from its centre: small swings have
        // ω² = m·g·d/I_pivot = g/L, L = (r²/2 + d²)/d; `info` names that mode, and the accuracy
        // study measures against the physical pendulum's closed form, RK4 at fourth order.
        const double d = 0.8, theta0 = kPi / 6.0, lengthEq = (0.5 * 0.3 * 0.3 + d * d) / d;
        const QString disk =
            QStringLiteral(
                R"("disks": [ { "id": "body", "position": [%1, %2], "radius": 0.3, "mass": 2 } ])")
                .arg(number(d * std::sin(theta0)), number(-d * std::cos(theta0)));
        const QString path = write(
            "advised.json",
            pendulumScene(
                disk, R"({ "id": "pivot", "type": "hinge", "a": "body", "anchor": [0, 0] })", 2.0));
        const Result info = cli({"info", path});
        QCOMPARE(info.status, 0);
        const QString text = QString::fromUtf8(info.out);
        const QString omega = QString::number(std::sqrt(kG / lengthEq), 'g', 4);
        QVERIFY2(text.contains(QStringLiteral("stiffest mode omega = %1 rad/s").arg(omega)),
                 qPrintable(text));
        QVERIFY(!text.contains("nothing in the scene oscillates"));

        const Result lab =
            cli({"accuracy", path, "--integrators", "rk4", "--dt", "0.01,0.005", "--json"});
        QCOMPARE(lab.status, 0);
        const QJsonObject study = QJsonDocument::fromJson(lab.out).object();
        QCOMPARE(study["reference"].toString(), QStringLiteral("exact: physical pendulum"));
        const QJsonArray rows = study["records"].toArray();
        QCOMPARE(rows.size(), 2);
        const double order = rows[1].toObject()["order"].toDouble();
        qInfo("rk4 against the physical pendulum: errors %.3e, %.3e m, order %.2f",
              rows[0].toObject()["position_error"].toDouble(),
              rows[1].toObject()["position_error"].toDouble(), order);
        QVERIFY(std::abs(order - 4.0) < 0.3);
    }

    void jointAngleSignAndTheOtherForms() {
        // Released on the left: θ0 = −45°, the swing's smallest value; a rope like a rod while
        // taut; between two bodies a hinge reads θb − θa from load.
        const QByteArray scene = R"({
  "format": "phasebox-scene", "version": 2,
  "simulation": { "integrator": "rk4", "dt": 0.001, "duration": 0.01 },
  "effects": { "gravity": { "g": [0, -9.81] } },
  "particles": [ { "id": "left", "position": [-1, -1] }, { "id": "up", "position": [3, 1] } ],
  "boxes": [ { "id": "arm", "position": [6, 0], "size": [1, 0.2] },
             { "id": "hand", "position": [7, 0], "size": [1, 0.2], "angle": 0.25 } ],
  "joints": [ { "id": "rope", "type": "rope", "a": "left", "anchor": [0, 0] },
              { "id": "top", "type": "rod", "a": "up", "anchor": [3, 0] },
              { "id": "elbow", "type": "hinge", "a": "arm", "b": "hand", "anchor": [6.5, 0] },
              { "id": "w", "type": "weld", "a": "hand" } ]
})";
        const QString path = write("forms.json", scene);
        const Result r = cli({"run", path, "--duration", "0.001", "--csv", "-", "--probe",
                              "rope.angle", "--probe", "top.angle", "--probe", "elbow.angle"});
        QCOMPARE(r.status, 0);
        const QStringList first = QString::fromUtf8(r.out).split('\n')[1].split(',');
        QCOMPARE(first[first.size() - 3].toDouble(), -0.25 * kPi);
        QCOMPARE(first[first.size() - 2].toDouble(), kPi);  // straight up: π, not −π
        QCOMPARE(first[first.size() - 1].toDouble(), 0.0);  // the joint angle at load
        const Result weld = cli({"run", path, "--probe", "w.angle"});
        QCOMPARE(weld.status, 2);
        QVERIFY2(weld.err.contains("\"w\" is not a hinge, rod or rope"), weld.err.constData());
        const Result help = cli({"run", "--help"});
        QVERIFY(help.out.contains("JOINT.angle"));
        QVERIFY(help.out.contains("X:Y"));
    }
};

QTEST_GUILESS_MAIN(TestCliAngles)
#include "tst_cli_angles.moc"
