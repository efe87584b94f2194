// The energy ledger at contacts (CONTRACT §2 and §6): what position correction adds or
// removes is `correction`, never work_nc; e = 1 is exactly elastic at the format's defaults;
// and no step size makes a ball rise above the height it fell from.

#include "../physics/PhysicsTestSupport.h"
#include "physics/integrators/Integrator.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"

#include <QTest>

#include <cmath>
#include <string>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

void addIntegrators() {
    QTest::addColumn<QString>("integrator");
    for (const char* name : {"symplectic_euler", "velocity_verlet", "rk4", "implicit_euler"})
        QTest::newRow(name) << QString(name);
}

}  // namespace

class TestContactEnergy : public QObject {
    Q_OBJECT

private slots:
    void pushOutIsBookedAsCorrection_data() { addIntegrators(); }
    void pushOutIsBookedAsCorrection() {
        // A 1 kg box set d = 5 cm into the floor is pushed out to rest on it: the push raises
        // its potential energy by m·g·d, and that is the solver's correction, not physical
        // work.
        QFETCH(QString, integrator);
        SceneDesc scene = atDefaults(scenes::tower(1), qPrintable(integrator));
        const double d = 0.05, m = 1.0, g = 9.81;
        scene.boxes[0].position = {0.0, 0.5 - d};
        auto world = buildWorld(scene).world;
        for (int k = 0; k < 120; ++k) QVERIFY(world->step());
        const EnergyLedger& e = world->energy();
        qInfo("%s: correction %.4f J (m·g·d = %.4f J), work_nc %.2e J, drift %.2e J",
              qPrintable(integrator), e.correction, m * g * d, e.workNc, e.drift);
        QVERIFY(std::abs(world->bodyPosition(0).y() - 0.5) < 0.005);
        // The push ends within the soft contact's sag (under a millimetre here) of d, and its
        // m·g·d is correction. (Under symplectic and implicit Euler a resting box also gets
        // back, each step, the ½·m·g²·h² that the method's step took, which shows as drift:
        // that too is the solver's, so correction holds at least the push.)
        QVERIFY2(e.correction > 0.95 * m * g * d, qPrintable(QString::number(e.correction)));
        // The box ends at rest on the floor: all it gained is the push's m·g·d, and a contact
        // never does positive work, so nothing of it is in work_nc.
        const double gained = e.kinetic + e.potential - e.initial;
        QVERIFY2(std::abs(gained - m * g * d) < 0.05 * m * g * d,
                 qPrintable(QString::number(gained)));
        QVERIFY(e.workNc <= 1e-12);
    }

    void contactsNeverDoPositiveWork_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<QString>("scene");
        for (const char* name : {"symplectic_euler", "velocity_verlet", "rk4", "implicit_euler"}) {
            QTest::newRow(qPrintable(QString("%1 pyramid").arg(name)))
                << QString(name) << "pyramid";
            QTest::newRow(qPrintable(QString("%1 bouncing ball").arg(name)))
                << QString(name) << "ball";
            QTest::newRow(qPrintable(QString("%1 dominoes").arg(name)))
                << QString(name) << "dominoes";
        }
    }
    void contactsNeverDoPositiveWork() {
        // Friction, restitution and the normal force only take energy out: work_nc of a scene
        // whose only non-conservative forces are contacts never rises, whatever the solver or
        // the integrator does (what a solver puts in is correction).
        QFETCH(QString, integrator);
        QFETCH(QString, scene);
        const SceneDesc desc = scene == "pyramid" ? scenes::pyramid(10)
                               : scene == "ball"  ? scenes::ballDrop(1.0, 0.8)
                                                  : scenes::dominoes(10);
        auto world = buildWorld(atDefaults(desc, qPrintable(integrator))).world;
        double previous = world->energy().workNc;
        for (int k = 0; k < 300; ++k) {
            QVERIFY(world->step());
            QVERIFY2(world->energy().workNc <= previous + 1e-12,
                     qPrintable(QString("step %1: work_nc rose from %2 to %3 J")
                                    .arg(k)
                                    .arg(previous)
                                    .arg(world->energy().workNc)));
            previous = world->energy().workNc;
        }
    }

    void elasticGasKeepsItsEnergyAtDefaults_data() { addIntegrators(); }
    void elasticGasKeepsItsEnergyAtDefaults() {
        // e = 1, μ = 0 disks at speeds up to 3 m/s in a box, with no restitution threshold set:
        // every collision, however slow, is elastic, so the kinetic energy stays.
        QFETCH(QString, integrator);
        auto world = buildWorld(atDefaults(scenes::elasticGas(200), qPrintable(integrator))).world;
        const double e0 = world->energy().kinetic;
        double worst = 0.0;
        for (int k = 0; k < 600; ++k) {
            QVERIFY(world->step());
            worst = std::max(worst, std::abs(world->energy().kinetic - e0) / e0);
        }
        qInfo("%s: largest relative change of kinetic energy over 10 s = %.2e",
              qPrintable(integrator), worst);
        QVERIFY(worst < 1e-3);
    }

    void ballNeverRisesAboveItsDropHeight_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<double>("dt");
        for (const char* name : {"symplectic_euler", "velocity_verlet", "rk4", "implicit_euler"})
            for (double dt : {1.0, 0.25, 1.0 / 60.0})
                QTest::newRow(qPrintable(QString("%1 dt %2").arg(name).arg(dt)))
                    << QString(name) << dt;
    }
    void ballNeverRisesAboveItsDropHeight() {
        // e = 0.5 from 1 m: however large the step, the ball never climbs above 1 m and the
        // mechanical energy never exceeds what it started with.
        QFETCH(QString, integrator);
        QFETCH(double, dt);
        SceneDesc scene = atDefaults(scenes::ballDrop(1.0, 0.5), qPrintable(integrator));
        scene.simulation.dt = dt;
        auto world = buildWorld(scene).world;
        const double radius = world->particles()[0].radius;
        const double e0 = world->energy().kinetic + world->energy().potential;
        double highest = 0.0, most = -1e300;
        const int steps = static_cast<int>(std::ceil(20.0 / dt));
        for (int k = 0; k < steps; ++k) {
            QVERIFY(world->step());
            highest = std::max(highest, world->particlePosition(0).y() - radius);
            most = std::max(most, world->energy().kinetic + world->energy().potential);
        }
        qInfo("%s at dt %g: highest %.4f m, energy at most %.4f J of %.4f J",
              qPrintable(integrator), dt, highest, most, e0);
        QVERIFY2(highest <= 1.0 + 1e-9, qPrintable(QString::number(highest)));
        QVERIFY(most <= e0 + 1e-9 * std::abs(e0));
    }

    void inelasticLandingIsWork_data() {
        QTest::addColumn<QString>("integrator");
        for (const IntegratorInfo& info : integratorRegistry())
            QTest::newRow(std::string(info.name).c_str())
                << QString::fromStdString(std::string(info.name));
    }
    void inelasticLandingIsWork() {
        // e = 0 from 1 m: the ball lands dead, and all it had at the touch, m·g·h, is the
        // contact's work. The speculative contact lets it close its last gap in the sub-step it
        // lands, and relax stops it there: that stop is the impact, not a push-out, so none of it
        // is correction. (Booked as push-out, 0.061 to 0.075 J of the 9.81 J went to correction
        // under seven of these methods; where it lands decides whether a sub-step closes a gap,
        // and dropped from 0.9 m 0.136 J did under RK4.) The books are read at the step it stops
        // in: in the next one symplectic and backward Euler's step lets the resting ball sink by
        // g·h² before any force is held, ½·m·g²·h² (0.013 J) of drift that the solver gives back
        // as correction.
        QFETCH(QString, integrator);
        SceneDesc scene = atDefaults(scenes::ballDrop(1.0, 0.0), qPrintable(integrator));
        auto world = buildWorld(scene).world;
        const double m = scene.particles[0].mass, g = 9.81, h = 1.0;
        int steps = 0;
        while (world->kineticEnergy() > 1e-9 || steps == 0) {
            QVERIFY(world->step());
            QVERIFY(++steps < 120);  // it lands after 0.45 s
        }
        const EnergyLedger& e = world->energy();
        qInfo(
            "%s: stopped at %.3f s, work_nc %.5f J (m·g·h = %.5f J), correction %.2e J, drift "
            "%.2e J",
            qPrintable(integrator), world->time(), e.workNc, m * g * h, e.correction, e.drift);
        QVERIFY2(std::abs(e.correction) < 1e-3 * m * g * h,
                 qPrintable(QString::number(e.correction)));
        // The energy the ball had at the touch is the work, but for the method's own error in
        // the fall, which is drift (symplectic Euler's 0.36 J here).
        QVERIFY(std::abs(e.workNc + e.drift + m * g * h) < 1e-3 * m * g * h);
    }

    void noMassRatioLaunchesAnything_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<double>("ratio");
        for (const char* name : {"symplectic_euler", "velocity_verlet", "rk4", "implicit_euler"})
            for (double ratio : {1e3, 1e6, 1e9})
                QTest::newRow(qPrintable(QString("%1 1:%2").arg(name).arg(ratio)))
                    << QString(name) << ratio;
    }
    void noMassRatioLaunchesAnything() {
        // Issue 15: a 2 m box up to 1e9 times heavier than the 0.5 m box it rests on, from
        // rest. The light box may be crushed out from under it, but nothing is launched
        // (before: the light box left at 1e11 m/s) and the energy never exceeds the start.
        QFETCH(QString, integrator);
        QFETCH(double, ratio);
        auto world =
            buildWorld(atDefaults(scenes::bigOnSmall(ratio), qPrintable(integrator))).world;
        const double e0 = world->energy().kinetic + world->energy().potential;
        double fastest = 0.0, most = -1e300;
        for (int k = 0; k < 600; ++k) {
            QVERIFY(world->step());
            for (int i = 0; i < 2; ++i) fastest = std::max(fastest, world->bodyVelocity(i).norm());
            most = std::max(most, world->energy().kinetic + world->energy().potential);
        }
        qInfo("%s, 1:%g: fastest %.3f m/s, energy at most %.6g J of %.6g J", qPrintable(integrator),
              ratio, fastest, most, e0);
        QVERIFY2(fastest < 5.0, qPrintable(QString::number(fastest)));
        QVERIFY2(most <= e0 * (1.0 + 1e-9), qPrintable(QString::number(most - e0)));
    }
};

QTEST_APPLESS_MAIN(TestContactEnergy)
#include "tst_contact_energy.moc"
