// The live error estimate (World::estimateLocalError, step doubling at the current state)
// against the true local error of one step, which the harmonic oscillator gives in closed
// form; and the guarantee that estimating never changes the run.

#include "PhysicsTestSupport.h"

#include <QTest>

#include <cmath>

using namespace phasebox;
using namespace phasebox::testing;

class TestErrorEstimate : public QObject {
    Q_OBJECT

private slots:
    // Explicit Euler on x'' = −x from (1, 0): one step of h lands at x = 1 against cos h, a
    // local error h²/2 + O(h⁴); two half steps land at 1 − h²/4, so the doubling estimate
    // (1 − (1 − h²/4)) / (1 − 1/2) is h²/2 exactly.
    void explicitEulerEstimateIsExact() {
        const double h = 0.01;
        auto world = build(oscillatorScene("explicit_euler", h, {1.0, 0.0}, {0.0, 0.0}));
        // To round-off: the difference 1 − (1 − h²/4) cancels all but 4 of 16 digits.
        QVERIFY(std::abs(world->estimateLocalError() - h * h / 2.0) <= 1e-9 * h * h);
    }

    // For every fixed-step method, the estimate is the true local error to leading order: one
    // step from a generic state compared with the exact solution over h.
    void estimateMatchesTheTrueLocalError_data() {
        QTest::addColumn<QString>("integrator");
        for (const Theory& t : kFixedStep) QTest::newRow(t.name) << QString(t.name);
    }
    void estimateMatchesTheTrueLocalError() {
        QFETCH(QString, integrator);
        const double h = 0.02;
        const Eigen::Vector2d x0(0.8, -0.3), v0(0.4, 0.9);
        auto world = build(oscillatorScene(integrator.toStdString(), h, x0, v0));
        const double estimate = world->estimateLocalError();
        QVERIFY(world->step());
        // Exact: x(h) = x0·cos h + v0·sin h for ω = 1.
        const Eigen::Vector2d exact = x0 * std::cos(h) + v0 * std::sin(h);
        const Eigen::Vector2d got(world->positions()[0], world->positions()[1]);
        const double truth = (got - exact).lpNorm<Eigen::Infinity>();
        // Leading order only: the next term is a factor h (or h² for symmetric methods) smaller.
        QVERIFY2(estimate > 0.5 * truth && estimate < 2.0 * truth,
                 qPrintable(QString("%1: estimate %2, true local error %3")
                                .arg(integrator)
                                .arg(estimate)
                                .arg(truth)));
    }

    // Estimating after every step leaves the run bit for bit as it was: the clock, the state,
    // the ledger and the force-evaluation count — for the adaptive and implicit methods too,
    // whose integrators keep state between steps.
    void estimatingNeverChangesTheRun_data() {
        QTest::addColumn<QString>("integrator");
        for (const Theory& t : kFixedStep) QTest::newRow(t.name) << QString(t.name);
        QTest::newRow("rk45") << QStringLiteral("rk45");
        QTest::newRow("adaptive_euler") << QStringLiteral("adaptive_euler");
    }
    void estimatingNeverChangesTheRun() {
        QFETCH(QString, integrator);
        const SceneDesc scene = keplerScene(integrator.toStdString(), 0.01, 0.5);
        auto plain = build(scene);
        auto watched = build(scene);
        for (int k = 0; k < 200; ++k) {
            QVERIFY(plain->step());
            QVERIFY(watched->step());
            QVERIFY(watched->estimateLocalError() >= 0.0);
        }
        QVERIFY(plain->positions() == watched->positions());
        QVERIFY(plain->velocities() == watched->velocities());
        QCOMPARE(plain->time(), watched->time());
        QCOMPARE(plain->forceEvaluations(), watched->forceEvaluations());
        QCOMPARE(plain->energy().drift, watched->energy().drift);
    }

    // The estimate grows as the step grows, by the method's order plus one.
    void estimateScalesWithTheOrder() {
        for (const char* name : {"explicit_euler", "midpoint", "rk4"}) {
            const double h = 0.04;
            auto coarse = build(oscillatorScene(name, h, {0.8, -0.3}, {0.4, 0.9}));
            auto fine = build(oscillatorScene(name, h / 2, {0.8, -0.3}, {0.4, 0.9}));
            const double ratio = coarse->estimateLocalError() / fine->estimateLocalError();
            const int order = coarse->integrator().info().order;
            const double expected = std::pow(2.0, order + 1);
            QVERIFY2(std::abs(std::log2(ratio) - std::log2(expected)) < 0.2,
                     qPrintable(
                         QString("%1: ratio %2, expected %3").arg(name).arg(ratio).arg(expected)));
        }
    }
    // A joint that turns fast makes the world take sub-steps of its own (World::
    // jointSubstepsForFrame): a 1 kg particle on a 1 m rod, swung at 15 rad/s, turns 0.25 rad
    // in a frame of 1/60 s, and the joints take 3 sub-steps. The estimate is of the sub-step
    // the run takes: the same as for a world told to take those 3 sub-steps itself, whose
    // frame is the very same arithmetic. (It once estimated one step of the whole frame, and
    // showed 4.5 m for a heavy chain that velocity Verlet held to micrometres.)
    void estimateIsOfTheJointsSubstep() {
        const auto pendulum = [](int substeps) {
            SceneDesc scene;
            scene.simulation = simulation("velocity_verlet", 1.0 / 60.0);
            scene.simulation.substeps = substeps;
            scene.effects.gravity = GravityDesc{};
            ParticleDesc bob;
            bob.id = "bob";
            bob.position = {0.0, -1.0};
            bob.velocity = {15.0, 0.0};
            scene.particles.push_back(bob);
            JointDesc rod;
            rod.type = JointType::Rod;
            rod.a = "bob";
            rod.anchor = Point2{0.0, 0.0};
            scene.joints.push_back(rod);
            return build(scene);
        };
        auto own = pendulum(1);
        auto told = pendulum(3);
        QVERIFY(own->step());
        QVERIFY(told->step());
        QCOMPARE(own->forceEvaluations(), told->forceEvaluations());
        QCOMPARE(own->positions(), told->positions());
        const double estimate = own->estimateLocalError();
        qInfo("joints' 3 sub-steps: estimate %.3e m, told 3 sub-steps: %.3e m", estimate,
              told->estimateLocalError());
        QCOMPARE(estimate, told->estimateLocalError());
    }
};

QTEST_GUILESS_MAIN(TestErrorEstimate)
#include "tst_error_estimate.moc"
