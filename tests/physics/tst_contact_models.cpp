// The three contact models of CONTRACT §6 against what physics says: the penalty contact's
// closed forms (a ball on a plane is a linear damped oscillator while it overlaps), the
// kinematic response's bounce heights, the stability advisor on stiff penalty contacts, and a
// live switch between the models keeping the state.

#include "PhysicsTestSupport.h"

#include "physics/contacts/PenaltyContacts.h"
#include "physics/diagnostics/StabilityAdvisor.h"

#include <QTest>

#include <cmath>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

constexpr double kRadius = 0.1;

// A ball (a particle disk) of mass m just above a plane at y = 0, moving down at speed v, with
// no force but the contact's.
SceneDesc ballOnPlane(const std::string& integrator, double dt, ContactModel model, double v,
                      double m = 1.0) {
    SceneDesc scene;
    scene.simulation = simulation(integrator, dt);
    scene.simulation.contactModel = model;
    ParticleDesc ball;
    ball.id = "ball";
    ball.position = {0.0, kRadius + 1e-3};
    ball.velocity = {0.0, -v};
    ball.mass = m;
    ball.radius = kRadius;
    ball.restitution = 0.0;
    ball.friction = 0.0;
    scene.particles.push_back(ball);
    PlaneDesc plane;
    plane.restitution = 0.0;
    plane.friction = 0.0;
    scene.planes.push_back(plane);
    return scene;
}

// One impact under the penalty model: when the overlap began and ended (interpolated within the
// step), the deepest overlap, and the speed it left with.
struct Impact {
    double duration = 0.0;
    double deepest = 0.0;
    double exitSpeed = 0.0;
    bool left = false;
};

Impact impact(World& world, double maxSeconds) {
    Impact result;
    double begin = -1.0;
    double previousDepth = kRadius - world.particlePosition(0).y();
    const long long steps = std::llround(maxSeconds / world.settings().dt);
    for (long long k = 0; k < steps; ++k) {
        const double t0 = world.time();
        if (!world.step()) return result;
        const double depth = kRadius - world.particlePosition(0).y();
        result.deepest = std::max(result.deepest, depth);
        const double t = t0 + (world.time() - t0) * previousDepth / (previousDepth - depth);
        if (begin < 0.0 && previousDepth <= 0.0 && depth > 0.0) begin = t;
        if (begin >= 0.0 && previousDepth > 0.0 && depth <= 0.0) {
            result.duration = t - begin;
            result.exitSpeed = world.particleVelocity(0).y();
            result.left = true;
            return result;
        }
        previousDepth = depth;
    }
    return result;
}

}  // namespace

class TestContactModels : public QObject {
    Q_OBJECT

private slots:
    void penaltyContactIsADampedOscillator_data() {
        QTest::addColumn<double>("zeta");
        QTest::addColumn<QString>("integrator");
        for (double zeta : {0.0, 0.1, 0.3})
            for (const char* integrator : {"rk4", "implicit_midpoint"})
                QTest::newRow(qPrintable(QString("zeta %1, %2").arg(zeta).arg(integrator)))
                    << zeta << QString(integrator);
    }
    void penaltyContactIsADampedOscillator() {
        // While it overlaps, a ball of mass m on a plane with no other force obeys
        // m·d'' = −k·d − c·d': it stays π·√(m/k)/√(1 − ζ²), sinks at most v·√(m/k) when
        // c = 0, and leaves at e·v, e = exp(−ζπ/√(1 − ζ²)), ζ = c/(2·√(k·m)).
        QFETCH(double, zeta);
        QFETCH(QString, integrator);
        const double m = 2.0, k = 2e4, v = 3.0;
        SceneDesc scene = ballOnPlane(integrator.toStdString(), 1e-5, ContactModel::Penalty, v, m);
        scene.simulation.contactStiffness = k;
        scene.simulation.contactDamping = zeta * 2.0 * std::sqrt(k * m);
        auto world = build(scene);
        QCOMPARE(world->penaltyStiffness(), k);
        const Impact hit = impact(*world, 0.2);
        QVERIFY(hit.left);
        const double root = std::sqrt(1.0 - zeta * zeta);
        const double duration = kPi * std::sqrt(m / k) / root;
        const double e = std::exp(-zeta * kPi / root);
        qInfo(
            "zeta %.1f: contact %.6f s (theory %.6f), exit %.5f m/s (theory %.5f), deepest %.6f m",
            zeta, hit.duration, duration, hit.exitSpeed, e * v, hit.deepest);
        QVERIFY(std::abs(hit.duration - duration) <= 1e-3 * duration);
        QVERIFY(std::abs(hit.exitSpeed - e * v) <= 1e-3 * v);
        if (zeta == 0.0) {
            const double sink = v * std::sqrt(m / k);
            QVERIFY(std::abs(hit.deepest - sink) <= 1e-3 * sink);
        }
    }

    void automaticStiffnessGivesTheLightestBodyHalfARadianPerStep() {
        SceneDesc scene = ballOnPlane("symplectic_euler", 1.0 / 60.0, ContactModel::Penalty, 1.0);
        ParticleDesc heavy = scene.particles.front();
        heavy.id = "heavy";
        heavy.position = {1.0, 1.0};
        heavy.mass = 8.0;
        scene.particles.push_back(heavy);
        scene.simulation.substeps = 2;
        auto world = build(scene);
        const double h = 1.0 / 120.0;
        // ω = √(k/m_lightest), ω·h = 0.5.
        QCOMPARE(std::sqrt(world->penaltyStiffness() / 1.0) * h, 0.5);
    }

    void penaltyEnergyIsPotentialWhileOverlapping() {
        // With c = 0 and no friction the contact is conservative: K + ½·k·d² holds through the
        // impact (RK4 at a small step), so drift stays near zero and work_nc is zero.
        SceneDesc scene = ballOnPlane("rk4", 1e-4, ContactModel::Penalty, 2.0);
        scene.simulation.contactStiffness = 1e4;
        auto world = build(scene);
        double worst = 0.0;
        for (int i = 0; i < 400; ++i) {
            QVERIFY(world->step());
            worst = std::max(worst, std::abs(world->energy().drift));
            if (i == 100) QVERIFY(world->potentialEnergy() > 0.1);  // mid-contact: ½·k·d²
        }
        qInfo("largest |drift| through the impact: %.3g J of 2 J", worst);
        QVERIFY(worst < 1e-3);
        QCOMPARE(world->energy().workNc, 0.0);
    }

    void stiffPenaltyAdvice() {
        // k = 1e7 with a 1 kg ball: ω ≈ 3162 rad/s. Symplectic Euler at 1/60 has ω·h = 53: the
        // advisor says so (largest stable step ω·h ≤ 1 for explicit methods under penalty),
        // the run diverges and is caught; implicit Euler rests the ball.
        SceneDesc scene = ballOnPlane("symplectic_euler", 1.0 / 60.0, ContactModel::Penalty, 0.0);
        scene.simulation.contactStiffness = 1e7;
        scene.effects.gravity = GravityDesc{};
        auto world = build(scene);
        const StabilityAdvice advice = adviseStability(*world);
        QVERIFY(!advice.currentStable);
        QVERIFY(std::abs(advice.omegaMax - std::sqrt(1e7)) <= 1e-6 * std::sqrt(1e7));
        for (const StepLimit& limit : advice.limits)
            if (limit.integrator == "symplectic_euler")
                QVERIFY(std::abs(limit.maxDt - 1.0 / std::sqrt(1e7)) < 1e-9);
        bool diverged = false;
        for (int i = 0; i < 600 && !diverged; ++i) diverged = !world->step();
        QVERIFY(diverged);
        QVERIFY(world->positions().allFinite());

        scene.simulation.integrator = "implicit_euler";
        world = build(scene);
        for (int i = 0; i < 600; ++i) QVERIFY(world->step());
        const double sag = 9.81 / 1e7;  // m·g/k
        QVERIFY(std::abs(world->particleVelocity(0).y()) < 1e-3);
        QVERIFY(std::abs(world->particlePosition(0).y() - (kRadius - sag)) < 1e-4);
    }

    void advisorCountsPointsAndStacks() {
        // The advisor's ω comes from the assembled contact stiffness: a disk on a plane has one
        // point, ω² = k/m; a box on a plane two, 2k/m along the normal and k·w²/(2I) rocking; a
        // stack of boxes couples their springs, and its stiffest mode is stiffer still.
        const double k = 1e4;
        const auto omegaOf = [&](int boxes, bool disk) {
            SceneDesc scene;
            scene.simulation = simulation("implicit_euler", 1.0 / 60.0);
            scene.simulation.contactModel = ContactModel::Penalty;
            scene.simulation.contactStiffness = k;
            scene.effects.gravity = GravityDesc{};
            scene.planes.push_back(PlaneDesc{});
            if (disk) {
                DiskDesc d;
                d.position = {0.0, 0.5};
                d.radius = 0.5;
                d.mass = 1.0;
                scene.disks.push_back(d);
            }
            for (int i = 0; i < boxes; ++i) {
                BoxDesc b;
                b.position = {0.0, 0.5 + i};
                b.size = {1.0, 1.0};
                b.mass = 1.0;
                scene.boxes.push_back(b);
            }
            auto world = build(scene);
            bool settled = true;
            for (int i = 0; i < 60; ++i) settled = world->step() && settled;  // into contact
            return settled ? adviseStability(*world).omegaMax : -1.0;
        };
        const double disk = omegaOf(0, true), box = omegaOf(1, false), stack = omegaOf(4, false);
        // A unit box: I = 1/6, rocking ω² = k·1/(2/6) = 3k, above the 2k of its normal mode.
        qInfo("omega: disk %.2f, box %.2f, stack of four %.2f rad/s", disk, box, stack);
        QVERIFY(std::abs(disk - std::sqrt(k)) < 1e-3 * std::sqrt(k));
        QVERIFY(std::abs(box - std::sqrt(3.0 * k)) < 1e-3 * std::sqrt(3.0 * k));
        QVERIFY(stack > 1.2 * box);
    }

    void kinematicBounceHeights_data() {
        QTest::addColumn<double>("restitution");
        for (double e : {1.0, 0.8, 0.5, 0.2}) QTest::newRow(qPrintable(QString::number(e))) << e;
    }
    void kinematicBounceHeights() {
        // Dropped from h, the kinematic response reflects the approach speed scaled by e: the
        // next apex is e²·h (within 2% at dt 1/1000).
        QFETCH(double, restitution);
        const double h = 1.0;
        SceneDesc scene = ballOnPlane("symplectic_euler", 1e-3, ContactModel::Kinematic, 0.0);
        scene.particles.front().position = {0.0, kRadius + h};
        scene.particles.front().restitution = restitution;
        scene.effects.gravity = GravityDesc{};
        auto world = build(scene);
        double apex = 0.0;
        bool bounced = false;
        for (int i = 0; i < 4000; ++i) {
            QVERIFY(world->step());
            const double vy = world->particleVelocity(0).y();
            if (vy > 0.0) bounced = true;
            if (bounced) apex = std::max(apex, world->particlePosition(0).y() - kRadius);
            if (bounced && vy < 0.0) break;
        }
        const double expected = restitution * restitution * h;
        qInfo("e = %.1f: apex %.5f m, e^2 h = %.5f m", restitution, apex, expected);
        QVERIFY(bounced);
        QVERIFY(std::abs(apex - expected) <= 0.02 * expected);
        // No forces: the push-out is correction, the lost speed work_nc, drift stays small.
        QVERIFY(world->energy().workNc <= 0.0);
        QVERIFY(std::abs(world->energy().drift) < 0.02 * 9.81 * h);
    }

    void kinematicTangentialScaling() {
        // A ball sliding into the plane at an angle: the tangential relative velocity leaves
        // scaled by 1 − μ, the normal one reflected by e.
        SceneDesc scene = ballOnPlane("symplectic_euler", 1e-3, ContactModel::Kinematic, 2.0);
        scene.particles.front().velocity = {3.0, -2.0};
        scene.particles.front().friction = 0.25;
        scene.particles.front().restitution = 0.5;
        scene.planes.front().friction = 0.25;
        auto world = build(scene);
        for (int i = 0; i < 50; ++i) QVERIFY(world->step());
        QCOMPARE(world->particleVelocity(0).y(), 1.0);   // −2 reflected with e = 0.5
        QCOMPARE(world->particleVelocity(0).x(), 2.25);  // 3·(1 − √(0.25·0.25))
    }

    void switchingModelsKeepsTheState_data() {
        QTest::addColumn<int>("from");
        QTest::addColumn<int>("to");
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                if (a != b)
                    QTest::newRow(qPrintable(QString("%1 to %2")
                                                 .arg(contactModelName(ContactModel(a)).data())
                                                 .arg(contactModelName(ContactModel(b)).data())))
                        << a << b;
    }
    void switchingModelsKeepsTheState() {
        // A box dropped on a plane, the model switched mid-run: the state is kept exactly, the
        // drift is continuous (the penalty's potential of the overlap then present comes or
        // goes with the model, not as integration error), and the box keeps resting on the
        // plane under the new model.
        QFETCH(int, from);
        QFETCH(int, to);
        SceneDesc scene;
        scene.simulation = simulation("implicit_euler", 1.0 / 60.0);
        scene.simulation.contactModel = ContactModel(from);
        scene.effects.gravity = GravityDesc{};
        BoxDesc box;
        box.id = "box";
        box.position = {0.0, 0.6};
        box.size = {1.0, 1.0};
        scene.boxes.push_back(box);
        scene.planes.push_back(PlaneDesc{});
        auto world = build(scene);
        for (int i = 0; i < 120; ++i) QVERIFY(world->step());
        const Eigen::VectorXd q = world->positions(), u = world->velocities();
        const double drift = world->energy().drift;
        SimulationSettings settings = world->settings();
        settings.contactModel = ContactModel(to);
        world->setSettings(settings);
        QCOMPARE(world->positions(), q);
        QCOMPARE(world->velocities(), u);
        QVERIFY(std::abs(world->energy().drift - drift) < 1e-12);
        for (int i = 0; i < 120; ++i) QVERIFY(world->step());
        QVERIFY(std::abs(world->bodyPosition(0).y() - 0.5) < 0.05);
    }

    void contactForceHoldsUpTheWeight_data() {
        QTest::addColumn<int>("model");
        for (int m = 0; m < 3; ++m) QTest::newRow(contactModelName(ContactModel(m)).data()) << m;
    }
    void contactForceHoldsUpTheWeight() {
        // A 2 kg ball resting on a plane: whatever answers the contact, its force on the ball
        // (contact_force, CONTRACT §7) balances the weight, m·g = 19.62 N, once it has settled.
        QFETCH(int, model);
        SceneDesc scene = ballOnPlane("implicit_euler", 1.0 / 60.0, ContactModel(model), 0.0, 2.0);
        scene.effects.gravity = GravityDesc{};
        auto world = build(scene);
        for (int i = 0; i < 300; ++i) QVERIFY(world->step());
        const int dof = world->particles().front().dof;
        const Vec2 f = world->contactForce(dof);
        qInfo("%s: contact force (%.4f, %.4f) N", contactModelName(ContactModel(model)).data(),
              f.x(), f.y());
        QVERIFY(std::abs(f.x()) < 1e-9);
        QVERIFY(std::abs(f.y() - 2.0 * 9.81) < 1e-3 * 2.0 * 9.81);
    }

    void absentContactsCostNothing() {
        // The model is a setting: a scene with nothing that can touch has no contact stage and
        // no penalty force under any model.
        SceneDesc scene = oscillatorScene("symplectic_euler", 0.01, {1.0, 0.0}, {0.0, 0.0});
        scene.simulation.contactModel = ContactModel::Penalty;
        auto world = build(scene);
        QVERIFY(world->contacts() == nullptr);
        QCOMPARE(world->penaltyStiffness(), 0.0);
        QCOMPARE(world->anticipatedContactOmegaSquared(), 0.0);
        for (const EffectCost& cost : world->effectCosts()) QVERIFY(cost.name != "contacts");
    }
};

QTEST_APPLESS_MAIN(TestContactModels)
#include "tst_contact_models.moc"
