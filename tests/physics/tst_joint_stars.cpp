// Stars: many joints on one body (JointSolver.h, hubs). Every joint of a star holds its centre,
// so in joint space they form a clique whose factor is dense; the centre enters the system as a
// node of its own instead, and the star factors as the tree it is. These cases check that the
// factor stays linear in the joints, and that the answer is the same constrained dynamics:
// circular motion at the tension m·v²/r, momentum and angular momentum kept under every method,
// joints held, with the centre free, hinged to the world, or a particle.

#include "JointTestSupport.h"

#include "physics/integrators/Integrator.h"
#include "physics/joints/JointSolver.h"
#include "physics/world/Probes.h"

#include <QElapsedTimer>
#include <QTest>

#include <cmath>
#include <random>
#include <string>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

// n particles of mass m on a circle of radius r about a box at the origin, each on a rod to the
// box's centre and moving along the circle at speed v (counter-clockwise); no gravity.
SceneDesc star(const QString& integrator, int n, double m, double r, double v) {
    SceneDesc s = scene(integrator, 1.0 / 60.0);
    s.effects.gravity.reset();
    BoxDesc hub;
    hub.id = "hub";
    hub.size = {0.5, 0.5};
    hub.mass = 2.0;
    s.boxes = {hub};
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * kPi * i / n;
        std::string id = "p";  // not "p" + to_string(): GCC 12 at -O3 warns falsely on that
        id += std::to_string(i);
        ParticleDesc p = particle(id, {r * std::cos(a), r * std::sin(a)}, m);
        p.velocity = {-v * std::sin(a), v * std::cos(a)};
        s.particles.push_back(p);
        s.joints.push_back(joint(JointType::Rod, p.id, "hub"));
    }
    return s;
}

}  // namespace

class TestJointStars : public QObject {
    Q_OBJECT

private slots:
    // A star of n joints factors in n blocks (one per joint and its centre), not the n·(n−1)/2
    // pairs of a clique, and a star of 20,000 rods loads and steps in seconds.
    void aStarFactorsLinearly() {
        for (const int n : {9, 40, 400}) {
            const auto built = buildWorld(star("symplectic_euler", n, 0.01, 2.0, 1.0));
            QCOMPARE(built.world->jointSolver()->factorBlocks(), n);
        }
        QElapsedTimer timer;
        timer.start();
        const auto built = buildWorld(star("symplectic_euler", 20000, 0.01, 2.0, 1.0));
        World& w = *built.world;
        for (int k = 0; k < 10; ++k) QVERIFY(w.step());
        const double seconds = timer.elapsed() / 1000.0;
        qInfo("a star of 20,000 rods: built and 10 steps in %.2f s", seconds);
        QCOMPARE(w.jointSolver()->factorBlocks(), 20000);
        QVERIFY(w.jointErrors().position < 1e-6);
        QVERIFY2(seconds < 20.0, "the star's setup or step is not linear in its joints");
    }

    // Uniform circular motion: each particle circles at ω = v/r with tension m·v²/r, and by
    // symmetry the centre stays at rest. With the centre hinged to the world, the hinge (a joint
    // on the centre alone, ordered after it) carries nothing.
    void symmetricStarCirclesAtTheClosedForm() {
        for (const bool hinged : {false, true}) {
            const int n = 24;
            const double m = 0.05, r = 1.5, v = 2.0, duration = 2.0;
            SceneDesc s = star("rk4", n, m, r, v);
            if (hinged) {
                JointDesc pin = joint(JointType::Hinge, "hub");
                pin.anchor = Point2{0.0, 0.0};
                s.joints.push_back(pin);
            }
            const auto built = buildWorld(s);
            World& w = *built.world;
            while (w.time() < duration - 1e-9) QVERIFY(w.step());
            const double turned = v / r * w.time();
            double worstPlace = 0.0, worstTension = 0.0;
            for (int i = 0; i < n; ++i) {
                const double a = 2.0 * kPi * i / n + turned;
                const Vec2 expected{r * std::cos(a), r * std::sin(a)};
                worstPlace = std::max(worstPlace, (w.particlePosition(i) - expected).norm());
                const double tension = w.jointSolver()->force(i);
                worstTension = std::max(worstTension, std::abs(tension / (m * v * v / r) - 1.0));
            }
            qInfo("hinged %d: place within %.1e m, tension within %.1e relative", hinged,
                  worstPlace, worstTension);
            QVERIFY(worstPlace < 1e-6);
            QVERIFY(worstTension < 1e-6);
            QVERIFY(w.bodyPosition(0).norm() < 1e-9);
            QVERIFY(std::abs(w.bodyAngle(0)) < 1e-9);
            if (hinged) QVERIFY(w.jointSolver()->force(n) < 1e-6);
        }
    }

    // Random motion of a spinning star: the joints' forces are internal, so momentum keeps its
    // value after the first projection (which takes out the rods' stretching rates, itself an
    // internal impulse) under every method, and the rods hold. Angular momentum is kept exactly
    // by symplectic Euler with SHAKE (the constraint impulses act along the rods at the step's
    // start, where the positions that turn them are); by the others to their order: halving dt
    // shrinks its change by 2^order (or it is at rounding already); the adaptive methods' by their
    // tolerance. The centre a box (3×3
    // blocks) and a particle (2×2).
    void starsKeepMomentumUnderEveryMethod() {
        struct Result {
            double p = 0.0, l = 0.0, error = 0.0, l0 = 0.0;
        };
        const auto run = [](const IntegratorInfo& info, bool particleHub, double dt) {
            SceneDesc s = star(QString::fromStdString(std::string(info.name)), 30, 0.02, 1.0, 0.0);
            s.simulation.dt = dt;
            if (particleHub) {
                s.boxes.clear();
                s.particles.push_back(particle("hub", {0.0, 0.0}, 0.5));
            } else {
                s.boxes[0].angularVelocity = 1.5;
            }
            std::mt19937 random(7);
            std::uniform_real_distribution<double> speed(-1.0, 1.0);
            for (ParticleDesc& p : s.particles) p.velocity = {speed(random), speed(random)};
            const auto built = buildWorld(s);
            World& w = *built.world;
            Result r;
            if (!w.step()) return Result{1e9, 1e9, 1e9, 0.0};
            const SystemMotion start = systemMotion(w);
            r.l0 = std::abs(start.angularMomentum);
            while (w.time() < 2.0 - 1e-9) {
                if (!w.step()) return Result{1e9, 1e9, 1e9, 0.0};
                const SystemMotion now = systemMotion(w);
                r.p = std::max(r.p, (now.momentum - start.momentum).norm());
                r.l = std::max(r.l, std::abs(now.angularMomentum - start.angularMomentum));
                r.error = std::max(r.error, w.jointErrors().position);
            }
            return r;
        };
        for (const bool particleHub : {false, true}) {
            for (const IntegratorInfo& info : integratorRegistry()) {
                const Result coarse = run(info, particleHub, 1.0 / 60.0);
                const Result fine = run(info, particleHub, 1.0 / 120.0);
                const std::string name(info.name);
                qInfo(
                    "%s centre, %s: |Δp| <= %.1e, |ΔL| <= %.1e (dt/2: %.1e) of L = %.2f, "
                    "joint error <= %.1e m",
                    particleHub ? "particle" : "box", name.c_str(), coarse.p, coarse.l, fine.l,
                    coarse.l0, coarse.error);
                QVERIFY2(coarse.p < 1e-9 && fine.p < 1e-9, name.c_str());
                QVERIFY2(coarse.error < 1e-3 && fine.error < 1e-3, name.c_str());
                const double rounding = 1e-12 * (1.0 + coarse.l0);
                if (name == "symplectic_euler") {
                    QVERIFY2(coarse.l < rounding && fine.l < rounding, name.c_str());
                } else if (!info.adaptive && coarse.l > 1e3 * rounding) {
                    const double expected = std::pow(2.0, -info.order);
                    QVERIFY2(fine.l < 1.5 * expected * coarse.l, name.c_str());
                } else {  // adaptive: the error follows the tolerance over many steps, not dt
                    QVERIFY2(coarse.l < 1e-2 * coarse.l0, name.c_str());
                }
            }
        }
    }
};

QTEST_APPLESS_MAIN(TestJointStars)
#include "tst_joint_stars.moc"
