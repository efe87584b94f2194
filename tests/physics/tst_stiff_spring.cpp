// A stiff spring at a frame-rate step (k = 1e6, m = 1, dt = 1/60, so ω·dt ≈ 16.7): the
// implicit methods stay bounded, the explicit ones blow up and the world must catch it, keep
// the last good state and say where and when.

#include "PhysicsTestSupport.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

constexpr double kStiffness = 1e6;
constexpr double kGravity = 9.81;
constexpr double kDt = 1.0 / 60.0;
constexpr int kFrames = 600;  // 10 s

// A ball hanging from a fixed anchor on a spring of rest length 1, pulled 1 cm past its rest
// length. The motion stays on the vertical line through the anchor, where the spring force
// k·(−y − 1) is linear in y: one Newton iteration is then the exact backward Euler step.
SceneDesc hangingBall(const std::string& integrator, int substeps = 1, double damping = 0.0) {
    SceneDesc scene;
    scene.simulation = simulation(integrator, kDt);
    scene.simulation.substeps = substeps;
    scene.effects.gravity = GravityDesc{{0.0, -kGravity}};
    ParticleDesc p;
    p.id = "ball";
    p.position = {0.0, -1.01};
    p.mass = 1.0;
    p.radius = 0.0;
    scene.particles.push_back(p);
    SpringDesc s;
    s.a = "ball";
    s.anchor = Point2{0.0, 0.0};
    s.stiffness = kStiffness;
    s.restLength = 1.0;
    s.damping = damping;
    scene.springs.push_back(s);
    return scene;
}

}  // namespace

class TestStiffSpring : public QObject {
    Q_OBJECT

private slots:
    void implicitEulerStaysBoundedAndSettles();
    void implicitMidpointKeepsEnergy();
    void explicitMethodsDivergenceIsCaught_data();
    void explicitMethodsDivergenceIsCaught();
};

// Backward Euler on a convex potential never gains energy: with v₁ = v₀ − h·∇U(q₁) and
// q₁ = q₀ + h·v₁, ΔKE = −h·v₁·∇U(q₁) − ½|Δv|² and ΔU ≤ ∇U(q₁)·(q₁ − q₀) = h·v₁·∇U(q₁),
// so ΔE ≤ −½|Δv|². Here U = ½k(−y − 1)² + m·g·y is convex along the line of motion.
void TestStiffSpring::implicitEulerStaysBoundedAndSettles() {
    auto world = build(hangingBall("implicit_euler"));
    const double e0 = mechanicalEnergy(*world);
    QCOMPARE(e0, 0.5 * kStiffness * 0.01 * 0.01 - kGravity * 1.01);
    double previous = e0;
    for (int n = 1; n <= kFrames; ++n) {
        QVERIFY2(world->step(), qPrintable(QString("step %1 reported divergence").arg(n)));
        QVERIFY(!world->divergence());
        QVERIFY(world->positions().allFinite() && world->velocities().allFinite());
        const double e = mechanicalEnergy(*world);
        // Round-off of the energy evaluation only (the scale is ~50 J).
        QVERIFY2(
            e <= previous + 1e-11 * std::abs(e0),
            qPrintable(QString("step %1: energy rose from %2 to %3").arg(n).arg(previous).arg(e)));
        QVERIFY(e <= e0);
        previous = e;
    }
    QVERIFY(std::abs(world->time() - 10.0) < 1e-12);
    // After 600 steps each dividing the energy of the oscillation by 1 + (ω·dt)² ≈ 279, the
    // ball rests at the static equilibrium y = −1 − m·g/k, with no sideways motion.
    const double equilibrium = -1.0 - kGravity / kStiffness;
    QVERIFY2(std::abs(world->positions()[1] - equilibrium) < 1e-12,
             qPrintable(QString("y = %1, equilibrium %2")
                            .arg(world->positions()[1], 0, 'g', 17)
                            .arg(equilibrium, 0, 'g', 17)));
    QVERIFY(std::abs(world->velocities()[1]) < 1e-9);
    QCOMPARE(world->positions()[0], 0.0);
    // Implicit Euler's damping is numerical: no force did work, so it shows as negative drift.
    QCOMPARE(world->energy().workNc, 0.0);
    const double lost = e0 - mechanicalEnergy(*world);
    QVERIFY(lost > 0.99 * 0.5 * kStiffness * 0.01 * 0.01);
    QVERIFY(std::abs(world->energy().drift + lost) <= 1e-9 * lost);
}

// The implicit midpoint rule is stable at any step too, and keeps the energy of this linear
// motion (a quadratic invariant) to round-off rather than damping it.
void TestStiffSpring::implicitMidpointKeepsEnergy() {
    auto world = build(hangingBall("implicit_midpoint"));
    const double e0 = mechanicalEnergy(*world);
    for (int n = 1; n <= kFrames; ++n) {
        QVERIFY(world->step());
        const double e = mechanicalEnergy(*world);
        QVERIFY2(std::abs(e - e0) <= 1e-10 * 50.0,
                 qPrintable(QString("step %1: |E − E0| = %2").arg(n).arg(std::abs(e - e0))));
    }
}

void TestStiffSpring::explicitMethodsDivergenceIsCaught_data() {
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<int>("substeps");
    QTest::addColumn<double>("damping");
    // Every explicit method is unstable at ω·h ≈ 16.7 (and at 4.2 with four sub-steps). The
    // damped row makes work_nc non-zero, so that its bookkeeping across the restore shows.
    QTest::newRow("explicit_euler") << QString("explicit_euler") << 1 << 0.0;
    QTest::newRow("symplectic_euler") << QString("symplectic_euler") << 1 << 0.0;
    QTest::newRow("rk4") << QString("rk4") << 1 << 0.0;
    QTest::newRow("velocity_verlet") << QString("velocity_verlet") << 1 << 0.0;
    QTest::newRow("explicit_euler damped") << QString("explicit_euler") << 1 << 50.0;
    QTest::newRow("explicit_euler 4 substeps") << QString("explicit_euler") << 4 << 0.0;
}

// "Returns false when the step diverged: the world is then back in its last good state"
// (World.h). A good state is one that a successful step() left behind (the engine may go back
// further than the last one, to before a blow-up began), and being back in it means all of it:
// its time, step count, q and u bit for bit, and its energy ledger (a rejected step's work
// must not stay in work_nc, or the drift of the restored state is wrong). A state part-way
// through a frame, between sub-steps, was never accepted and is not a good state.
void TestStiffSpring::explicitMethodsDivergenceIsCaught() {
    QFETCH(QString, integrator);
    QFETCH(int, substeps);
    QFETCH(double, damping);
    auto world = build(hangingBall(integrator.toStdString(), substeps, damping));
    struct Accepted {
        double time;
        long long stepCount;
        Eigen::VectorXd q, u;
        EnergyLedger ledger;
    };
    std::vector<Accepted> accepted{{world->time(), world->stepCount(), world->positions(),
                                    world->velocities(), world->energy()}};
    bool failed = false;
    for (int n = 1; n <= kFrames && !failed; ++n) {
        if (world->step()) {
            // Every accepted step leaves a finite state behind.
            QVERIFY(world->positions().allFinite() && world->velocities().allFinite());
            QVERIFY(!world->divergence());
            accepted.push_back({world->time(), world->stepCount(), world->positions(),
                                world->velocities(), world->energy()});
        } else {
            failed = true;
        }
    }
    QVERIFY2(failed, "an unstable explicit step ran 10 s without World::step() returning false");
    QVERIFY(world->divergence().has_value());
    const Divergence& d = *world->divergence();
    QCOMPARE(QString::fromStdString(d.objectId), QString("ball"));
    QVERIFY(!d.what.empty());
    QVERIFY(!d.message().empty());
    // When: the frame after the last accepted one, within the 10 s run.
    const double lastTime = accepted.back().time;
    QVERIFY2(
        std::abs(d.time - (lastTime + kDt)) <= 1e-12,
        qPrintable(
            QString("divergence at t=%1, last accepted frame at %2").arg(d.time).arg(lastTime)));
    QCOMPARE(world->time(), d.restoredTime);
    // No NaN or infinity is left in the world, and the ledger is finite.
    QVERIFY(world->positions().allFinite() && world->velocities().allFinite());
    QVERIFY(std::isfinite(world->energy().kinetic) && std::isfinite(world->energy().potential));
    QVERIFY(std::isfinite(world->energy().drift));
    // Back in a good state: one that step() accepted, as a whole.
    const auto match = std::find_if(accepted.begin(), accepted.end(),
                                    [&](const Accepted& a) { return a.time == world->time(); });
    QVERIFY2(
        match != accepted.end(),
        qPrintable(QString("restored to t=%1, which is no accepted frame (last accepted %2); "
                           "energy there %3, at the last accepted frame %4")
                       .arg(world->time(), 0, 'g', 12)
                       .arg(lastTime, 0, 'g', 12)
                       .arg(mechanicalEnergy(*world))
                       .arg(accepted.back().ledger.kinetic + accepted.back().ledger.potential)));
    QCOMPARE(world->stepCount(), match->stepCount);
    QVERIFY2(world->positions() == match->q && world->velocities() == match->u,
             "the restored state differs from the accepted state at that time");
    QCOMPARE(world->energy().kinetic, match->ledger.kinetic);
    QCOMPARE(world->energy().potential, match->ledger.potential);
    QCOMPARE(world->energy().workNc, match->ledger.workNc);
    QCOMPARE(world->energy().drift, match->ledger.drift);
}

QTEST_APPLESS_MAIN(TestStiffSpring)
#include "tst_stiff_spring.moc"
