// Stacks that load a contact far beyond its bodies' own weight, at the format's defaults: a
// heavy box on a light one comes to rest and its books stay flat, and a tall tower takes the
// inner sub-steps its load needs from its first step instead of sinking first.

#include "../physics/PhysicsTestSupport.h"
#include "physics/contacts/ContactStage.h"
#include "physics/integrators/Integrator.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

// The ten methods by their names.
QStringList integrators() {
    QStringList names;
    for (const IntegratorInfo& info : integratorRegistry())
        names << QString::fromLatin1(info.name.data(), info.name.size());
    return names;
}

}  // namespace

class TestHeavyStacks : public QObject {
    Q_OBJECT

private slots:
    void heavyBoxOnALightOneComesToRest_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<double>("ratio");
        QTest::addColumn<int>("frameRate");
        for (const QString& name : integrators())
            for (double ratio : {50.0, 100.0, 200.0})
                for (int frameRate : {60, 30, 20})
                    QTest::newRow(
                        qPrintable(QString("%1 1:%2 dt 1/%3").arg(name).arg(ratio).arg(frameRate)))
                        << name << ratio << frameRate;
    }
    void heavyBoxOnALightOneComesToRest() {
        // A 2 m box 50 to 200 times heavier than the 0.5 m box it stands on, from rest, at
        // frames of 1/60 (the format's default) to 1/20 s. It
        // settles on the soft contacts (within 10 s: explicit Euler, whose positions lag its
        // velocities, swings longest) and then lies still, so no energy line moves after. (Before:
        // the heavy box bounced on the light one for ever at up to 0.17 m/s, and correction and
        // work_nc grew by tens of joules a second; with the contact's stiffening capped at 4×,
        // still under symplectic and implicit Euler at 1/30 and 1/20 s, at up to 0.4 m/s.)
        QFETCH(QString, integrator);
        QFETCH(double, ratio);
        QFETCH(int, frameRate);
        SceneDesc scene = atDefaults(scenes::bigOnSmall(ratio), integrator.toStdString());
        scene.simulation.dt = 1.0 / frameRate;
        auto world = buildWorld(scene).world;
        const int tenSeconds = 10 * frameRate;
        for (int k = 0; k < tenSeconds; ++k) QVERIFY(world->step());
        const EnergyLedger settled = world->energy();
        double fastest = 0.0;
        for (int k = 0; k < tenSeconds; ++k) {
            QVERIFY(world->step());
            fastest = std::max(fastest, world->velocities().cwiseAbs().maxCoeff());
        }
        const EnergyLedger& e = world->energy();
        const double moved = std::abs(e.correction - settled.correction) +
                             std::abs(e.workNc - settled.workNc) +
                             std::abs(e.drift - settled.drift);
        // The heavy box's weight on the light one, over its 1 m fall to the floor: the scale
        // of its energy.
        const double scale = ratio * 9.81 * 1.0;
        qInfo("%s, 1:%g, dt 1/%d: fastest %.2e m/s over 10 to 20 s, books moved %.2e J",
              qPrintable(integrator), ratio, frameRate, fastest, moved);
        QVERIFY2(fastest < 1e-6, qPrintable(QString::number(fastest)));
        // Lying still, symplectic and explicit Euler still trade about 1e-8 J a step between
        // correction and drift at dt 1/30 (a push-out of some 30 pm and the method's answer to
        // it): 1e-7 of the scale over 10 s bounds that, and the bouncing moved hundreds of J.
        QVERIFY2(moved < 1e-7 * scale, qPrintable(QString::number(moved)));
    }

    void towerTakesItsSubstepsFromTheStart_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<int>("count");
        for (const QString& name : integrators())
            for (int count : {30, 40, 100, 200})
                QTest::newRow(qPrintable(QString("%1, %2 boxes").arg(name).arg(count)))
                    << name << count;
    }
    void towerTakesItsSubstepsFromTheStart() {
        // A column of 1 m boxes, from rest. Its contacts sink by their load over their
        // stiffness, summed down the column; the solver takes enough inner sub-steps that this
        // sag stays within what its height allows at rest (allowedSag(): kSagTarget, a
        // thousandth of the height above 40 m). Loaded at once, a spring sinks at most twice its
        // rest sink, so the top may sink up to twice that while it settles. Before, the first
        // step knew no load and took the base count, which rose 30 steps at a time while the
        // tower sank into its contacts and was pushed back out: under symplectic Euler the
        // 40-box tower sank 18.8 cm, the 100-box one moved 2.6 m, and the 200-box one flew
        // apart (its top 48 m above its start after 10 s). The count taken from the weights in
        // the first step is the one the solved loads keep.
        QFETCH(QString, integrator);
        QFETCH(int, count);
        auto world = buildWorld(atDefaults(scenes::tower(count), integrator.toStdString())).world;
        const int top = count - 1;
        const double y0 = world->bodyPosition(top).y();
        const double allowed = ContactSolver::allowedSag(y0);
        QVERIFY(world->step());
        const int first = world->contacts()->solver().lastSubsteps();
        double deepest = 0.0;
        for (int k = 1; k < 600; ++k) {
            QVERIFY(world->step());
            deepest = std::max(deepest, y0 - world->bodyPosition(top).y());
        }
        const double rest = y0 - world->bodyPosition(top).y();
        const int last = world->contacts()->solver().lastSubsteps();
        qInfo(
            "%s, %d boxes: %d inner sub-steps first, %d after 10 s; the top sank %.4f m at "
            "most, rests %.4f m down (allowed %.3f m)",
            qPrintable(integrator), count, first, last, deepest, rest, allowed);
        QCOMPARE(first, last);
        QVERIFY(first > ContactSolver::innerSubsteps(1.0 / 60.0, ContactSettings{}));
        QVERIFY2(deepest < 2.0 * allowed, qPrintable(QString::number(deepest)));
        QVERIFY2(rest < allowed, qPrintable(QString::number(rest)));
    }
};

QTEST_APPLESS_MAIN(TestHeavyStacks)
#include "tst_heavy_stacks.moc"
