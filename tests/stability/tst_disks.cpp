// Rigid disks (CONTRACT §6, issue 16): a disk turns, so it rolls. Closed forms of the lecture's
// rigid-body chapter, under symplectic Euler, RK4 and implicit Euler at the format's defaults.

#include "physics/scene/BuildWorld.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace phasebox;

namespace {

constexpr double kG = 9.81;
constexpr double kRadius = 0.5;

void addIntegrators() {
    QTest::addColumn<QString>("integrator");
    for (const char* name : {"symplectic_euler", "rk4", "implicit_euler"})
        QTest::newRow(name) << QString(name);
}

// A disk of radius r resting on a plane through the origin tilted by theta (down the slope is
// −x), both with friction mu (the contact's is √(μ·μ) = μ).
SceneDesc diskOnIncline(const QString& integrator, double theta, double mu) {
    SceneDesc s;
    s.simulation.integrator = integrator.toStdString();
    s.effects.gravity = GravityDesc{};
    PlaneDesc plane;
    plane.normal = {-std::sin(theta), std::cos(theta)};
    plane.friction = mu;
    s.planes.push_back(plane);
    DiskDesc disk;
    disk.radius = kRadius;
    disk.position = {kRadius * plane.normal[0], kRadius * plane.normal[1]};
    disk.friction = mu;
    s.disks.push_back(disk);
    return s;
}

void steps(World& world, int count) {
    for (int k = 0; k < count; ++k) QVERIFY(world.step());
}

}  // namespace

class TestDisks : public QObject {
    Q_OBJECT

private slots:
    void rollsOrSlidesDownAnIncline_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<double>("mu");
        for (const char* name : {"symplectic_euler", "rk4", "implicit_euler"})
            for (double mu : {0.5, 0.05})
                QTest::newRow(qPrintable(QString("%1 mu %2").arg(name).arg(mu)))
                    << QString(name) << mu;
    }
    void rollsOrSlidesDownAnIncline() {
        // On a 20° incline a disk rolls without slipping at a = ⅔·g·sin θ when μ ≥ ⅓·tan θ
        // (0.121), and slides at a = g·(sin θ − μ·cos θ) with α = 2μ·g·cos θ / r below it.
        QFETCH(QString, integrator);
        QFETCH(double, mu);
        const double theta = 20.0 * std::numbers::pi / 180.0;
        auto world = buildWorld(diskOnIncline(integrator, theta, mu)).world;
        const Vec2 down(-std::cos(theta), -std::sin(theta));
        steps(*world, 30);  // the contact settles
        const double v0 = world->bodyVelocity(0).dot(down), w0 = world->bodyAngularVelocity(0);
        const double t = 1.0;
        steps(*world, 60);
        // From velocities: every method integrates a constant acceleration's velocity exactly,
        // whereas positions carry each method's O(h) offset.
        const double a = (world->bodyVelocity(0).dot(down) - v0) / t;
        const double alpha = (world->bodyAngularVelocity(0) - w0) / t;
        const bool rolls = mu >= std::tan(theta) / 3.0;
        const double expected = rolls ? 2.0 / 3.0 * kG * std::sin(theta)
                                      : kG * (std::sin(theta) - mu * std::cos(theta));
        const double expectedAlpha =
            rolls ? expected / kRadius : 2.0 * mu * kG * std::cos(theta) / kRadius;
        const double slip =
            world->bodyVelocity(0).dot(down) - world->bodyAngularVelocity(0) * kRadius;
        qInfo("%s, mu %.2f: a = %.5f (expected %.5f), alpha = %.4f (expected %.4f), slip %.3g m/s",
              qPrintable(integrator), mu, a, expected, alpha, expectedAlpha, slip);
        QVERIFY2(std::abs(a / expected - 1.0) < 0.005, qPrintable(QString::number(a)));
        QVERIFY2(std::abs(alpha / expectedAlpha - 1.0) < 0.005, qPrintable(QString::number(alpha)));
        // Rolling: the contact point keeps still but for the soft contact's creep (0.3% of
        // the speed measured); sliding: it slips at (a − α·r)·t and more.
        const double speed = world->bodyVelocity(0).dot(down);
        if (rolls)
            QVERIFY2(std::abs(slip) < 0.01 * speed, qPrintable(QString::number(slip)));
        else
            QVERIFY2(slip > 0.5 * speed, qPrintable(QString::number(slip)));
    }

    void skidsThenRolls_data() { addIntegrators(); }
    void skidsThenRolls() {
        // Thrown sliding with no spin on level ground, friction brakes it and spins it up until
        // it rolls, after t = v0/(3μg), at ⅔·v0 (momentum about the contact point is kept).
        QFETCH(QString, integrator);
        const double mu = 0.3, v0 = 3.0;
        SceneDesc s = diskOnIncline(integrator, 0.0, mu);
        s.disks[0].velocity = {v0, 0.0};
        auto world = buildWorld(s).world;
        const double tStar = v0 / (3.0 * mu * kG), vStar = 2.0 * v0 / 3.0;
        double rolledAt = -1.0;
        for (int k = 0; k < 120; ++k) {
            QVERIFY(world->step());
            const double slip =
                world->bodyVelocity(0).x() + world->bodyAngularVelocity(0) * kRadius;
            if (rolledAt < 0.0 && std::abs(slip) < 0.01 * vStar) rolledAt = world->time();
        }
        qInfo("%s: rolls from t = %.4f s (expected %.4f), at %.5f m/s (expected %.5f)",
              qPrintable(integrator), rolledAt, tStar, world->bodyVelocity(0).x(), vStar);
        const double dt = world->settings().dt;
        QVERIFY2(rolledAt >= tStar - dt && rolledAt <= tStar + 2.0 * dt,
                 qPrintable(QString::number(rolledAt)));
        QVERIFY2(std::abs(world->bodyVelocity(0).x() / vStar - 1.0) < 0.002,
                 qPrintable(QString::number(world->bodyVelocity(0).x())));
    }

    void spinsFreelyWithItsEnergy_data() { addIntegrators(); }
    void spinsFreelyWithItsEnergy() {
        // With nothing to touch, ½·I·ω² with I = ½·m·r² is its whole kinetic energy, kept.
        QFETCH(QString, integrator);
        SceneDesc s;
        s.simulation.integrator = integrator.toStdString();
        DiskDesc disk;
        disk.position = {0.0, 0.0};
        disk.radius = 0.3;
        disk.density = 2.0;
        disk.angularVelocity = 5.0;
        s.disks.push_back(disk);
        auto world = buildWorld(s).world;
        const double m = 2.0 * std::numbers::pi * 0.09, inertia = 0.5 * m * 0.09;
        QCOMPARE(world->energy().kinetic, 0.5 * inertia * 25.0);
        steps(*world, 600);
        QCOMPARE(world->bodyAngularVelocity(0), 5.0);
        QVERIFY(std::abs(world->bodyAngle(0) - 50.0) < 1e-9);
        QCOMPARE(world->energy().kinetic, 0.5 * inertia * 25.0);
    }

    void rollsWithItsBooksFlat_data() { addIntegrators(); }
    void rollsWithItsBooksFlat() {
        // Rolling at 2 m/s on level ground it needs no friction: it keeps its speed and its turn,
        // and the contact, whose point does not move, books nothing: every line of the ledger
        // stays flat. (Its contact point measured as a point of the rim, which rises by
        // r·(1 − cos Δθ) as the disk turns, let the disk fall a little every step; the solver
        // caught it again and booked ½·m·g²·h a second, 0.63 J/s, of correction against as much
        // drift under symplectic Euler.)
        QFETCH(QString, integrator);
        SceneDesc s = diskOnIncline(integrator, 0.0, 0.6);
        const double v = 2.0;
        s.disks[0].velocity = {v, 0.0};
        s.disks[0].angularVelocity = -v / kRadius;
        auto world = buildWorld(s).world;
        const double kinetic = world->energy().kinetic;
        steps(*world, 300);
        const EnergyLedger& e = world->energy();
        qInfo(
            "%s: after 5 s v %.9f m/s, w %.9f rad/s; correction %.3g J, work_nc %.3g J, "
            "drift %.3g J, kinetic %.9f J",
            qPrintable(integrator), world->bodyVelocity(0).x(), world->bodyAngularVelocity(0),
            e.correction, e.workNc, e.drift, e.kinetic);
        QVERIFY2(std::abs(world->bodyVelocity(0).x() - v) < 1e-3 * v,
                 qPrintable(QString::number(world->bodyVelocity(0).x())));
        QVERIFY2(std::abs(e.kinetic - kinetic) < 1e-4 * kinetic,
                 qPrintable(QString::number(e.kinetic)));
        // A thousandth of a joule on its 2.36 J: the soft contact's settling under the disk's
        // weight (7.7 N over some 17 µm) and nothing that grows with the distance rolled.
        for (const double booked : {e.correction, e.workNc, e.drift})
            QVERIFY2(std::abs(booked) < 1e-3, qPrintable(QString::number(booked)));
    }

    void restsOnABoxAndOnAnother_data() { addIntegrators(); }
    void restsOnABoxAndOnAnother() {
        // A disk on a box on the ground, and a disk on that disk's top held by two boxes: every
        // body within 2 cm of its start after 10 s (issue 16's stacks).
        QFETCH(QString, integrator);
        SceneDesc s = diskOnIncline(integrator, 0.0, 0.6);
        s.disks.clear();
        BoxDesc box;
        box.position = {0.0, 0.5};
        s.boxes.push_back(box);
        DiskDesc disk;
        disk.radius = kRadius;
        disk.position = {0.0, 1.0 + kRadius};
        s.disks.push_back(disk);
        for (double x : {1.8, 3.2}) {  // faces at 2.3 and 2.7: a 0.4 m notch
            BoxDesc side;
            side.position = {x, 0.5};
            s.boxes.push_back(side);
        }
        DiskDesc cradled;  // resting on the two boxes' inner top corners
        cradled.radius = kRadius;
        cradled.position = {2.5, 1.0 + std::sqrt(kRadius * kRadius - 0.2 * 0.2)};
        s.disks.push_back(cradled);
        auto world = buildWorld(s).world;
        steps(*world, 600);
        double worst = 0.0;
        for (int i = 0; i < static_cast<int>(world->rigidBodies().size()); ++i)
            worst =
                std::max(worst, (world->bodyPosition(i) - world->rigidBodies()[i].position).norm());
        qInfo("%s: largest displacement after 10 s %.4f m", qPrintable(integrator), worst);
        QVERIFY2(worst < 0.02, qPrintable(QString::number(worst)));
    }
};

QTEST_APPLESS_MAIN(TestDisks)
#include "tst_disks.moc"
