// The stability advisor against the step sizes at which methods are seen to blow up.

#include "PhysicsTestSupport.h"
#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/scene/BuildWorld.h"
#include "tests/support/SceneBuilders.h"

#include <QTest>

#include <algorithm>
#include <cctype>
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
        s.particles.push_back(testing::particle("second", {0.3, 0.1}));
        s.springs.push_back(testing::bodySpring("ball", "second", 100.0, 0.0));
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

    void neverRecommendsAMethodUnstableAtTheStep_data() {
        QTest::addColumn<double>("k");
        QTest::addColumn<QString>("integrator");
        // ω·h from 0.5 to 170 at dt 1/60: below, near and far past every explicit limit.
        for (double k : {900.0, 9e3, 3e4, 1e5, 1e6, 1e8})
            for (const char* m : {"explicit_euler", "midpoint", "symplectic_euler", "rk4"})
                QTest::newRow(qPrintable(QString("k %1, %2").arg(k).arg(m))) << k << QString(m);
    }
    void neverRecommendsAMethodUnstableAtTheStep() {
        // Issue 19: a stiff spring under explicit Euler was told to use symplectic Euler, which
        // then blew up. Every method the advice names must be one its own limits call stable at
        // this step with a margin, and that must hold when the advice is followed: each
        // recommended method keeps the spring bounded for 600 steps.
        QFETCH(double, k);
        QFETCH(QString, integrator);
        const double dt = 1.0 / 60.0;
        auto world = buildWorld(spring(k, 1.0, integrator.toStdString(), dt)).world;
        const StabilityAdvice a = adviseStability(*world);
        for (const StepLimit& limit : a.recommended) QVERIFY(limit.maxDt >= 1.25 * dt);
        for (const StepLimit& limit : a.limits) {
            // Named as a word ("implicit_euler," but not inside "implicit_euler_x").
            bool named = false;
            const std::string name(limit.integrator);
            for (std::size_t at = a.message.find(name); at != std::string::npos;
                 at = a.message.find(name, at + 1)) {
                const std::size_t end = at + name.size();
                const bool wordEnd = end == a.message.size() ||
                                     !(std::isalnum(static_cast<unsigned char>(a.message[end])) ||
                                       a.message[end] == '_');
                const bool wordStart = at == 0 || a.message[at - 1] == ' ';
                named = named || (wordStart && wordEnd && name != integrator.toStdString());
            }
            const bool recommended =
                std::any_of(a.recommended.begin(), a.recommended.end(),
                            [&](const StepLimit& r) { return r.integrator == limit.integrator; });
            QVERIFY2(!named || recommended, a.message.c_str());
            if (recommended)
                QVERIFY2(staysBounded(spring(k, 1.0, std::string(limit.integrator), dt), 600),
                         std::string(limit.integrator).c_str());
        }
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
