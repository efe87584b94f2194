// The stability advisor against the step sizes at which methods are seen to blow up.

#include "PhysicsTestSupport.h"
#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/scene/BuildWorld.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace phasebox;

namespace {

// m on a zero-rest-length spring of stiffness k to the origin, 0.1 m away: F = −k·x exactly, a
// linear oscillator with ω = √(k/m) (a spring with a rest length is nonlinear when stretched
// far, which would cap a blow-up).
SceneDesc spring(double k, double m, const std::string& integrator, double dt) {
    return testing::oscillatorScene(integrator, dt, {0.1, 0.0}, {0.0, 0.0}, k, m);
}

// Whether `steps` steps stay bounded (no divergence and |x − 1| below 100× the start).
bool staysBounded(const SceneDesc& scene, int steps) {
    auto world = buildWorld(scene).world;
    for (int i = 0; i < steps; ++i) {
        if (!world->step()) return false;
        if (world->particlePosition(0).norm() > 10.0) return false;
    }
    return true;
}

}  // namespace

class TestStabilityAdvisor : public QObject {
    Q_OBJECT

private slots:
    void omegaOfASpringIsSqrtKOverM() {
        auto world = buildWorld(spring(400.0, 4.0, "symplectic_euler", 0.01)).world;
        const StabilityAdvice a = adviseStability(*world);
        QVERIFY(std::abs(a.omegaMax - 10.0) < 1e-6);
    }

    void omegaOfTwoMassesIsTheHighNormalMode() {
        // Anchor –k– m –k– m (zero rest lengths): ω² = (3 ± √5)/2 · k/m; the advisor must
        // find the higher one.
        SceneDesc s = spring(100.0, 1.0, "symplectic_euler", 0.01);
        ParticleDesc p2;
        p2.id = "second";
        p2.position = {0.3, 0.1};
        p2.radius = 0.0;
        s.particles.push_back(p2);
        SpringDesc sp;
        sp.a = "ball";
        sp.b = "second";
        sp.stiffness = 100.0;
        sp.restLength = 0.0;
        s.springs.push_back(sp);
        auto world = buildWorld(s).world;
        const double expected = std::sqrt((3.0 + std::sqrt(5.0)) / 2.0 * 100.0);
        QVERIFY(std::abs(adviseStability(*world).omegaMax - expected) < 1e-3 * expected);
    }

    void predictedLimitIsTheObservedBlowUp_data() {
        QTest::addColumn<QString>("integrator");
        QTest::newRow("symplectic_euler") << "symplectic_euler";
        QTest::newRow("velocity_verlet") << "velocity_verlet";
        QTest::newRow("rk4") << "rk4";
    }
    void predictedLimitIsTheObservedBlowUp() {
        // ω = 10 rad/s. 3% below the predicted limit the method runs 3,000 steps bounded; 3%
        // above it blows up (and the world reports it).
        QFETCH(QString, integrator);
        const std::string name = integrator.toStdString();
        auto world = buildWorld(spring(100.0, 1.0, name, 0.01)).world;
        const StabilityAdvice advice = adviseStability(*world);
        double limit = 0.0;
        for (const StepLimit& l : advice.limits)
            if (l.integrator == name) limit = l.maxDt;
        QVERIFY(limit > 0.0 && std::isfinite(limit));
        QVERIFY(std::abs(limit * 10.0 - stabilityBound(name)) < 1e-6);
        QVERIFY(staysBounded(spring(100.0, 1.0, name, 0.97 * limit), 3000));
        QVERIFY(!staysBounded(spring(100.0, 1.0, name, 1.03 * limit), 3000));
    }

    void explicitEulerHasNoStableStep() {
        auto world = buildWorld(spring(100.0, 1.0, "explicit_euler", 0.001)).world;
        const StabilityAdvice a = adviseStability(*world);
        QVERIFY(!a.currentStable);
        for (const StepLimit& l : a.limits)
            if (l.integrator == "explicit_euler" || l.integrator == "midpoint" ||
                l.integrator == "heun")
                QCOMPARE(l.maxDt, 0.0);
            else if (l.integrator == "implicit_euler")
                QVERIFY(std::isinf(l.maxDt));
    }

    void warnsPastTheLimitAndSaysWhatToDo() {
        auto world = buildWorld(spring(1e6, 1.0, "symplectic_euler", 1.0 / 60.0)).world;
        const StabilityAdvice a = adviseStability(*world);
        QVERIFY(!a.currentStable);
        QVERIFY(a.message.find("sub-steps") != std::string::npos);
        QVERIFY(a.message.find("implicit") != std::string::npos);
    }

    void gravityAloneNeedsNoAdvice() {
        SceneDesc s;
        s.effects.gravity = GravityDesc{};
        s.particles.push_back({});
        auto world = buildWorld(s).world;
        const StabilityAdvice a = adviseStability(*world);
        QCOMPARE(a.omegaMax, 0.0);
        QVERIFY(a.currentStable);
    }
};

QTEST_APPLESS_MAIN(TestStabilityAdvisor)
#include "tst_stability_advisor.moc"
