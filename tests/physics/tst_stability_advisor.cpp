// The stability advisor against the step sizes at which methods are seen to blow up.

#include "PhysicsTestSupport.h"
#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
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

// Two boxes under kinematic contacts and gravity g, placed at a and b, on a plane under the
// first one (its normal against g).
SceneDesc twoBoxes(Point2 a, Point2 b, Point2 g, double rotate = 0.0) {
    SceneDesc scene;
    scene.simulation.contactModel = ContactModel::Kinematic;
    scene.effects.gravity = GravityDesc{g};
    for (const auto& [id, at] : {std::pair{"lower", a}, std::pair{"upper", b}}) {
        BoxDesc box;
        box.id = id;
        box.position = at;
        box.size = {1.0, 1.0};
        box.angle = rotate;
        scene.boxes.push_back(box);
    }
    PlaneDesc floor;
    const double norm = std::hypot(g[0], g[1]);
    floor.normal = {-g[0] / norm, -g[1] / norm};
    floor.point = {a[0] + 0.5 * g[0] / norm, a[1] + 0.5 * g[1] / norm};
    scene.planes.push_back(floor);
    return scene;
}

std::string warningFor(const SceneDesc& scene) {
    return contactModelWarning(*buildWorld(scene).world);
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

    // The advisor's remedy is accepted (issue #38): a 64 x 64 cloth at 2e4 N/m needs 159
    // sub-steps under symplectic Euler (185 with bench_cloth's 10% margin), and the format's
    // bound on sub-steps times the scene's size refused it past 71 when every object counted
    // alike; the bound counts time now (SceneLimits::kMaxSubstepWork). Every method the advisor
    // gives a finite step for takes that many sub-steps with a 10% margin.
    void advisedSubstepsOfALargeClothAreAccepted() {
        const SceneDesc cloth = scenes::cloth(64, 2e4);
        const StabilityAdvice advice = adviseStability(*buildWorld(cloth).world);
        int checked = 0;
        for (const StepLimit& limit : advice.limits) {
            if (!(limit.maxDt > 0.0) || !std::isfinite(limit.maxDt)) continue;
            SceneDesc s = cloth;
            s.simulation.integrator = std::string(limit.integrator);
            s.simulation.substeps =
                static_cast<int>(std::ceil(1.1 * cloth.simulation.dt / limit.maxDt));
            const std::vector<SceneIssue> issues = validateScene(s);
            qInfo("%s: %d sub-steps, %s", s.simulation.integrator.c_str(), s.simulation.substeps,
                  issues.empty() ? "accepted" : issues.front().message.c_str());
            QVERIFY(issues.empty());
            ++checked;
        }
        QVERIFY(checked > 0);
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

    // Issue 37: kinematic contacts cannot hold a stack, and the advisor says so when a dynamic
    // body rests on another along gravity (within a tenth of the smaller height), whichever way
    // gravity points; not for bodies side by side, apart, without gravity or under impulses.
    void kinematicContactsUnderAStackAreWarnedOf() {
        const Point2 down{0.0, -9.81}, left{-9.81, 0.0};
        const std::string stacked = warningFor(twoBoxes({0.0, 0.5}, {0.2, 1.5}, down));
        QVERIFY2(stacked.find("Kinematic contacts cannot hold a stack (\"upper\" rests on "
                              "\"lower\")") == 0,
                 stacked.c_str());
        QVERIFY(stacked.find("Use impulse contacts") != std::string::npos);
        QVERIFY(!warningFor(twoBoxes({0.0, 0.5}, {0.05, 1.58}, down)).empty());     // a small gap
        QVERIFY(!warningFor(twoBoxes({0.5, 0.0}, {1.5, 0.0}, left)).empty());       // sideways g
        QVERIFY(!warningFor(twoBoxes({0.0, 0.5}, {0.0, 1.5}, down, 0.3)).empty());  // turned

        QVERIFY(warningFor(twoBoxes({0.0, 0.5}, {1.0, 0.5}, down)).empty());  // side by side
        QVERIFY(warningFor(twoBoxes({0.0, 0.5}, {0.0, 2.0}, down)).empty());  // 0.5 m apart
        QVERIFY(warningFor(twoBoxes({0.0, 0.5}, {1.2, 1.5}, down)).empty());  // not above it
        SceneDesc impulse = twoBoxes({0.0, 0.5}, {0.0, 1.5}, down);
        impulse.simulation.contactModel = ContactModel::Impulse;
        QVERIFY(warningFor(impulse).empty());
        SceneDesc weightless = twoBoxes({0.0, 0.5}, {0.0, 1.5}, down);
        weightless.effects.gravity.reset();
        QVERIFY(warningFor(weightless).empty());
        // The advice carries it.
        auto world = buildWorld(twoBoxes({0.0, 0.5}, {0.0, 1.5}, down)).world;
        QCOMPARE(adviseStability(*world).contactWarning, contactModelWarning(*world));
    }
};

QTEST_APPLESS_MAIN(TestStabilityAdvisor)
#include "tst_stability_advisor.moc"
