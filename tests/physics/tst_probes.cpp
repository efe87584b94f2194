// Probes (CONTRACT §7) against closed forms: the period of a mass on a spring, 2π·√(m/k); the
// conserved momentum and angular momentum of a free system; distances and signed angles of
// known geometry (the ±π boundary included); a rod pendulum's tension at the bottom of its
// swing, m·g + m·v²/L; the contact force under a resting box, m·g; the centre of mass by hand;
// and what an unknown probe is told. The period tracker is checked on its own too: bounded
// memory, and the same period from a small decimating buffer as from every sample.

#include "PhysicsTestSupport.h"
#include "physics/world/Probes.h"
#include "tests/support/SceneBuilders.h"

#include <QTest>

#include <cmath>
#include <string>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

constexpr double kG = 9.81;

Probe probe(const World& world, const std::string& text) {
    const ProbeParse parsed = parseProbe(world, text);
    if (!parsed) qFatal("%s", parsed.error.c_str());
    return *parsed.probe;
}

double value(const World& world, const std::string& text) {
    return evaluateProbe(world, probe(world, text));
}

}  // namespace

class TestProbes : public QObject {
    Q_OBJECT

private slots:
    // A mass on a spring (k = 10 N/m, m = 2 kg, rest length 0 to the origin): the period of
    // p.x is 2π·√(m/k) = 2.80993 s within 0.1%, from the tracker at its default capacity
    // (which decimates over these ten periods) and from one that keeps every sample.
    void springPeriodIsTwoPiRootMOverK_data() {
        QTest::addColumn<QString>("integrator");
        QTest::newRow("rk4") << "rk4";
        QTest::newRow("symplectic_euler") << "symplectic_euler";
    }
    void springPeriodIsTwoPiRootMOverK() {
        QFETCH(QString, integrator);
        const double k = 10.0, m = 2.0, dt = 1e-3;
        const double expected = 2.0 * kPi * std::sqrt(m / k);
        auto world =
            build(oscillatorScene(integrator.toStdString(), dt, {0.5, 0.0}, {0.0, 0.0}, k, m));
        const Probe x = probe(*world, "ball.x");
        PeriodTracker bounded, everything(1 << 16);
        const auto sample = [&] {
            bounded.add(world->time(), evaluateProbe(*world, x));
            everything.add(world->time(), evaluateProbe(*world, x));
        };
        sample();
        while (world->time() < 10.0 * expected) {
            QVERIFY(world->step());
            sample();
        }
        QVERIFY(!bounded.complete());
        QVERIFY(bounded.storedSamples() <= PeriodTracker::kDefaultCapacity);
        QVERIFY(everything.complete());
        const ProbeSummary a = bounded.summary(), b = everything.summary();
        QVERIFY(a.period && b.period);
        qInfo(
            "%s dt %g: period %.8f s (bounded) %.8f s (every sample), 2pi*sqrt(m/k) %.8f s, "
            "relative error %.2e; min %.6f max %.6f mean %.2e",
            qPrintable(integrator), dt, *a.period, *b.period, expected, *a.period / expected - 1.0,
            a.min, a.max, a.mean);
        QVERIFY(std::abs(*a.period / expected - 1.0) < 1e-3);
        QVERIFY(std::abs(*b.period / expected - 1.0) < 1e-3);
        QCOMPARE(a.samples, b.samples);
        QCOMPARE(a.min, b.min);
        QCOMPARE(a.max, b.max);
        // The start is the top of the swing. RK4 loses a little amplitude; symplectic Euler
        // keeps ω²x² + v² − h·ω²·x·v, whose largest x is A/√(1 − (ωh)²/4). The sampled bottom
        // lies within A·(ωh)²/8 of the true one.
        const double omegaH = std::sqrt(k / m) * dt;
        QVERIFY(a.max >= 0.5);  // the first sample
        QVERIFY(a.max <= 0.5 / std::sqrt(1.0 - omegaH * omegaH / 4.0) + 1e-12);
        QVERIFY(std::abs(a.min + 0.5) < 1e-6);
        QVERIFY(std::abs(a.mean) < 0.01);  // ten whole periods and a bit: the mean is ~0
    }

    // Memory stays bounded however long the run, and a buffer far too small to hold even one
    // period (64 samples for 50 periods of 1000 steps) still gives the exact period: the
    // crossings are counted as the samples come once the level is frozen.
    void trackerKeepsThePeriodInBoundedMemory() {
        const double period = 1.0, dt = 1e-3;
        PeriodTracker tiny(64), full(1 << 17);
        for (int i = 0; i <= 50000; ++i) {
            const double t = i * dt;
            const double v = 3.0 + std::cos(2.0 * kPi * t / period);
            tiny.add(t, v);
            full.add(t, v);
        }
        QVERIFY(tiny.storedSamples() <= 64);
        QVERIFY(full.complete());
        const ProbeSummary a = tiny.summary(), b = full.summary();
        QVERIFY(a.period && b.period);
        qInfo("cosine, period 1 s: %.12f s from 64 samples, %.12f s from every sample", *a.period,
              *b.period);
        QVERIFY(std::abs(*b.period - period) < 1e-9);
        QVERIFY(std::abs(*a.period - period) < 1e-9);
        QCOMPARE(a.max, 4.0);
        QCOMPARE(a.final, 4.0);

        // A swing whose range keeps growing (t·sin t) cannot freeze its level for good: the
        // period comes from the decimated series then, as exact as its samples per period.
        PeriodTracker small(1024), all(1 << 16);
        for (int i = 0; i <= 40000; ++i) {
            const double t = i * dt;
            const double v = t * std::sin(2.0 * kPi * t / period);
            small.add(t, v);
            all.add(t, v);
        }
        const ProbeSummary c = small.summary(), d = all.summary();
        QVERIFY(c.period && d.period);
        qInfo("growing swing: %.9f s from 1024 samples, %.9f s from every sample", *c.period,
              *d.period);
        QVERIFY(std::abs(*c.period / *d.period - 1.0) < 1e-3);

        // A ramp never crosses upward twice: no period.
        PeriodTracker ramp;
        for (int i = 0; i < 100000; ++i) ramp.add(i * dt, i * dt);
        QVERIFY(!ramp.summary().period);
        QVERIFY(ramp.storedSamples() <= PeriodTracker::kDefaultCapacity);
        QCOMPARE(ramp.summary().min, 0.0);
        QCOMPARE(ramp.summary().final, 99999 * dt);
        QVERIFY(std::abs(ramp.summary().mean - 0.5 * 99999 * dt) < 1e-9);
        // No samples, one crossing: no period either.
        QVERIFY(!PeriodTracker().summary().period);
        PeriodTracker once;
        for (int i = 0; i <= 1500; ++i) once.add(i * dt, std::sin(2.0 * kPi * i * dt));
        QVERIFY(!once.summary().period);
    }

    // Two particles on a spring, no gravity, with momentum and spin: symplectic Euler keeps
    // the total momentum (internal forces cancel) and the angular momentum about the origin
    // (central forces, and the method's x' = x + h·v' adds no torque) to rounding.
    void freeSystemKeepsMomentumAndAngularMomentum() {
        SceneDesc scene;
        scene.simulation = simulation("symplectic_euler", 1e-3);
        scene.particles = {particle("a", {1.0, 0.5}, 1.0, {0.3, 1.0}),
                           particle("b", {-1.0, 0.0}, 3.0, {0.1, -0.2})};
        SpringDesc s;
        s.a = "a";
        s.b = "b";
        s.stiffness = 50.0;
        s.restLength = 1.5;
        scene.springs = {s};
        auto world = build(scene);
        // By hand: P = Σ m·v, L = Σ m·(x·vy − y·vx).
        const double px = 1.0 * 0.3 + 3.0 * 0.1, py = 1.0 * 1.0 + 3.0 * -0.2;
        const double L = 1.0 * (1.0 * 1.0 - 0.5 * 0.3) + 3.0 * (-1.0 * -0.2 - 0.0 * 0.1);
        QCOMPARE(value(*world, "system.px"), px);
        QCOMPARE(value(*world, "system.py"), py);
        QVERIFY(std::abs(value(*world, "system.L") - L) < 1e-15);
        QVERIFY(std::abs(value(*world, "a.L") + value(*world, "b.L") - L) < 1e-15);
        QCOMPARE(value(*world, "b.px"), 0.3);
        QVERIFY(std::abs(value(*world, "a.kinetic") - 0.5 * (0.09 + 1.0)) < 1e-15);
        const Probe probes[] = {probe(*world, "system.px"), probe(*world, "system.py"),
                                probe(*world, "system.L")};
        double worst[3] = {0.0, 0.0, 0.0};
        const double expected[3] = {px, py, L};
        double stretch = 0.0;
        for (int i = 0; i < 5000; ++i) {
            QVERIFY(world->step());
            for (int j = 0; j < 3; ++j)
                worst[j] =
                    std::max(worst[j], std::abs(evaluateProbe(*world, probes[j]) - expected[j]));
            stretch = std::max(stretch, std::abs(value(*world, "distance(a,b)") - 1.5));
        }
        qInfo("5 s: |dPx| %.1e, |dPy| %.1e, |dL| %.1e; the spring swung %.3f m", worst[0], worst[1],
              worst[2], stretch);
        QVERIFY(stretch > 0.1);  // it really oscillated
        for (const double w : worst) QVERIFY(w < 1e-12);
    }

    // Ruler and protractor on pinned particles, a static box and cloth nodes: the distance
    // between centres, and the signed angle at B from BA to BC in (−π, π].
    void distanceAndAngleOfKnownGeometry() {
        SceneDesc scene;
        auto pinned = [](const std::string& id, Point2 at) {
            ParticleDesc p = particle(id, at);
            p.pinned = true;
            return p;
        };
        scene.particles = {pinned("A", {3.0, 1.0}),
                           pinned("B", {1.0, 1.0}),
                           pinned("C", {1.0, 4.0}),
                           pinned("D", {-2.0, 1.0}),
                           pinned("below", {-2.0, 1.0 - 1e-9}),
                           pinned("above", {-2.0, 1.0 + 1e-9})};
        BoxDesc crate;
        crate.id = "crate";
        crate.position = {4.0, 5.0};
        crate.isStatic = true;
        scene.boxes = {crate};
        ClothDesc flag;
        flag.id = "flag";
        flag.origin = {0.0, 10.0};
        flag.size = {2.0, 1.0};
        flag.resolution = {5, 3};  // columns 0.5 m apart, rows 0.5 m
        scene.cloths = {flag};
        auto world = build(scene);
        QCOMPARE(value(*world, "distance(A,B)"), 2.0);
        QCOMPARE(value(*world, "distance(B, crate)"), 5.0);  // 3-4-5
        QCOMPARE(value(*world, "distance(flag[0,0],flag[4,2])"), std::hypot(2.0, 1.0));
        QCOMPARE(value(*world, "flag[1,0].x"), 0.5);
        QCOMPARE(value(*world, "angle(A,B,C)"), kPi / 2.0);   // counter-clockwise
        QCOMPARE(value(*world, "angle(C,B,A)"), -kPi / 2.0);  // clockwise
        QCOMPARE(value(*world, "angle(A,B,D)"), kPi);         // straight: +π, never −π
        QCOMPARE(value(*world, "angle(D,B,A)"), kPi);
        QVERIFY(value(*world, "angle(A,B,above)") < kPi);  // just short of +π
        QVERIFY(value(*world, "angle(A,B,above)") > kPi - 1e-8);
        QVERIFY(value(*world, "angle(A,B,below)") > -kPi);  // just past: near −π
        QVERIFY(value(*world, "angle(A,B,below)") < -kPi + 1e-8);
        QCOMPARE(value(*world, "angle(A,B,crate)"), std::atan2(4.0, 3.0));
        // Fixed objects: where they are, at rest.
        QCOMPARE(value(*world, "crate.y"), 5.0);
        QCOMPARE(value(*world, "crate.omega"), 0.0);
        QCOMPARE(value(*world, "A.speed"), 0.0);
        QCOMPARE(value(*world, "crate.kinetic"), 0.0);
    }

    // A 2 kg bob on a 1 m rod swinging 10°: at the bottom the rod pulls with
    // m·g + m·v²/L = m·g·(3 − 2·cos θ0), and at the ends of the swing with m·g·cos θ0.
    void rodTensionAtTheBottomOfTheSwing() {
        const double m = 2.0, length = 1.0, theta0 = 10.0 * kPi / 180.0;
        SceneDesc scene;
        scene.simulation = simulation("rk4", 1.0 / 600.0);
        scene.effects.gravity = GravityDesc{};
        scene.particles = {
            particle("bob", {length * std::sin(theta0), -length * std::cos(theta0)}, m)};
        JointDesc rod;
        rod.id = "rod";
        rod.type = JointType::Rod;
        rod.a = "bob";
        rod.anchor = Point2{0.0, 0.0};
        scene.joints = {rod};
        auto world = build(scene);
        const Probe force = probe(*world, "force(rod)"), x = probe(*world, "bob.x");
        const double bottom = m * kG * (3.0 - 2.0 * std::cos(theta0));
        const double end = m * kG * std::cos(theta0);
        const double quarter = 0.5 * kPi * std::sqrt(length / kG);
        double atBottom = 0.0, nearest = 1e9, least = 1e9;
        while (world->time() < 2.2 * quarter) {  // through the bottom to the other end
            QVERIFY(world->step());
            const double f = evaluateProbe(*world, force);
            least = std::min(least, f);
            if (std::abs(evaluateProbe(*world, x)) < nearest) {
                nearest = std::abs(evaluateProbe(*world, x));
                atBottom = f;
            }
        }
        qInfo(
            "rod tension at the bottom %.6f N (m g + m v^2/L = %.6f N), least %.6f N "
            "(m g cos theta0 = %.6f N)",
            atBottom, bottom, least, end);
        QVERIFY(std::abs(atBottom / bottom - 1.0) < 1e-4);
        QVERIFY(std::abs(least / end - 1.0) < 1e-3);
    }

    // A 2 kg box resting on the ground: the ground pushes it up with m·g, each step's contact
    // impulse over dt. A particle of 0.5 kg on the ground likewise.
    void contactForceUnderARestingBoxIsItsWeight() {
        SceneDesc scene;
        scene.effects.gravity = GravityDesc{};
        PlaneDesc ground;
        ground.id = "ground";
        scene.planes = {ground};
        BoxDesc crate;
        crate.id = "crate";
        crate.position = {0.0, 0.5};
        crate.mass = 2.0;
        scene.boxes = {crate};
        ParticleDesc ball = particle("ball", {3.0, 0.1}, 0.5);
        ball.radius = 0.1;
        scene.particles = {ball};
        auto world = build(scene);
        const Probe onBox = probe(*world, "contact_force(crate)");
        const Probe onBall = probe(*world, "contact_force(ball)");
        for (int i = 0; i < 120; ++i) QVERIFY(world->step());  // settle
        double box = 0.0, ball2 = 0.0, worst = 0.0;
        const int steps = 60;
        for (int i = 0; i < steps; ++i) {
            QVERIFY(world->step());
            const double f = evaluateProbe(*world, onBox);
            box += f / steps;
            ball2 += evaluateProbe(*world, onBall) / steps;
            worst = std::max(worst, std::abs(f / (2.0 * kG) - 1.0));
        }
        qInfo(
            "resting: contact force on the box %.6f N (m g = %.6f N, worst step %.1e off), on "
            "the ball %.6f N (m g = %.6f N)",
            box, 2.0 * kG, worst, ball2, 0.5 * kG);
        QVERIFY(std::abs(box / (2.0 * kG) - 1.0) < 1e-3);
        QVERIFY(worst < 1e-2);
        QVERIFY(std::abs(ball2 / (0.5 * kG) - 1.0) < 1e-3);
        // Sliding at 2 m/s with μ = 0.5: the ground pushes up with m·g and back with μ·m·g,
        // |F| = m·g·√(1 + μ²), until friction stops it after v/(μ·g) = 0.41 s.
        scene.planes[0].friction = 0.5;
        scene.boxes[0].friction = 0.5;
        scene.boxes[0].velocity = {2.0, 0.0};
        auto sliding = build(scene);
        const Probe slide = probe(*sliding, "contact_force(crate)");
        const Probe speed = probe(*sliding, "crate.speed");
        double least = 1e9, most = 0.0;
        while (sliding->time() < 0.3) {
            QVERIFY(sliding->step());
            if (sliding->time() < 0.05) continue;  // the first contacts settle
            QVERIFY(evaluateProbe(*sliding, speed) > 0.1);
            least = std::min(least, evaluateProbe(*sliding, slide));
            most = std::max(most, evaluateProbe(*sliding, slide));
        }
        const double expected = 2.0 * kG * std::sqrt(1.25);
        qInfo("sliding: contact force %.6f to %.6f N (m g sqrt(1 + mu^2) = %.6f N)", least, most,
              expected);
        QVERIFY(std::abs(least / expected - 1.0) < 1e-3 && std::abs(most / expected - 1.0) < 1e-3);
        // In free flight nothing touches: no contact force.
        scene.boxes[0].position = {0.0, 50.0};
        auto falling = build(scene);
        QVERIFY(falling->step());
        QCOMPARE(evaluateProbe(*falling, probe(*falling, "contact_force(crate)")), 0.0);
    }

    // The centre of mass of the dynamic objects by hand; pinned and static ones are left out.
    // Without forces it moves with the total momentum over the total mass.
    void centreOfMassByHand() {
        SceneDesc scene;
        scene.simulation = simulation("symplectic_euler", 0.01);
        ParticleDesc heavyPin = particle("pin", {50.0, 50.0}, 100.0);
        heavyPin.pinned = true;
        scene.particles = {particle("p", {0.0, 0.0}, 1.0, {1.0, 0.0}),
                           particle("q", {4.0, 0.0}, 3.0, {0.0, 2.0}), heavyPin};
        BoxDesc crate;
        crate.id = "crate";
        crate.position = {1.0, 3.0};
        crate.size = {2.0, 1.0};
        crate.mass = 2.0;
        crate.velocity = {0.5, -1.0};
        crate.angularVelocity = 3.0;
        BoxDesc wall;
        wall.id = "wall";
        wall.position = {-30.0, 0.0};
        wall.isStatic = true;
        wall.mass = 1000.0;
        scene.boxes = {crate, wall};
        auto world = build(scene);
        // (1·0 + 3·4 + 2·1)/6 and (0 + 0 + 2·3)/6
        QVERIFY(std::abs(value(*world, "system.com_x") - 14.0 / 6.0) < 1e-15);
        QVERIFY(std::abs(value(*world, "system.com_y") - 1.0) < 1e-15);
        // The box's angular momentum: orbital m·(x·vy − y·vx) plus spin I·ω, I = m(w²+h²)/12.
        const double spin = 2.0 * (4.0 + 1.0) / 12.0 * 3.0;
        QVERIFY(std::abs(value(*world, "crate.L") - (2.0 * (1.0 * -1.0 - 3.0 * 0.5) + spin)) <
                1e-15);
        QVERIFY(std::abs(value(*world, "crate.kinetic") -
                         (0.5 * 2.0 * 1.25 + 0.5 * 2.0 * 5.0 / 12.0 * 9.0)) < 1e-14);
        QCOMPARE(value(*world, "crate.angle"), 0.0);
        QCOMPARE(value(*world, "crate.omega"), 3.0);
        const double px = 1.0 + 0.0 + 1.0, py = 0.0 + 6.0 - 2.0, mass = 6.0;
        QCOMPARE(value(*world, "system.px"), px);
        QCOMPARE(value(*world, "system.py"), py);
        for (int i = 0; i < 100; ++i) QVERIFY(world->step());
        const double t = world->time();
        QVERIFY(std::abs(value(*world, "system.com_x") - (14.0 / 6.0 + px / mass * t)) < 1e-12);
        QVERIFY(std::abs(value(*world, "system.com_y") - (1.0 + py / mass * t)) < 1e-12);
        QVERIFY(std::abs(value(*world, "crate.angle") - 3.0 * t) < 1e-12);
    }

    // The energy ledger as probes: the same numbers the ledger holds.
    void systemEnergiesAreTheLedger() {
        auto world = build(oscillatorScene("rk4", 0.01, {1.0, 0.0}, {0.0, 0.5}));
        for (int i = 0; i < 50; ++i) QVERIFY(world->step());
        const EnergyLedger& e = world->energy();
        QCOMPARE(value(*world, "system.kinetic"), e.kinetic);
        QCOMPARE(value(*world, "system.potential"), e.potential);
        QCOMPARE(value(*world, "system.total"), e.kinetic + e.potential);
        QCOMPARE(value(*world, "system.work_nc"), e.workNc);
        QCOMPARE(value(*world, "system.drift"), e.drift);
        QCOMPARE(value(*world, "system.correction"), e.correction);
        QVERIFY(std::abs(value(*world, "ball.kinetic") - e.kinetic) < 1e-15);
    }

    // Unknown forms, ids and misuses are refused with the reason and the whole vocabulary.
    void unknownProbesAreRefusedWithTheVocabulary_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("reason");
        QTest::newRow("field") << "ball.z"
                               << "unknown probe \"ball.z\"; known: ";
        QTest::newRow("object") << "nobody.x"
                                << "unknown probe \"nobody.x\": no object \"nobody\"; known: ";
        QTest::newRow("particle angle")
            << "ball.angle"
            << "\"ball\" is a particle: angle and omega are of rigid bodies";
        QTest::newRow("system") << "system.energy"
                                << "unknown probe \"system.energy\"; known: ";
        QTest::newRow("arguments") << "distance(ball)"
                                   << "takes 2 arguments: distance(A,B)";
        QTest::newRow("angle arguments") << "angle(ball,ball)"
                                         << "takes 3 arguments: angle(A,B,C)";
        QTest::newRow("joint") << "force(j9)"
                               << "no joint \"j9\"";
        QTest::newRow("instrument object") << "distance(ball,ghost)"
                                           << "no object \"ghost\"";
        QTest::newRow("pinned contact") << "contact_force(post)"
                                        << "\"post\" is static or pinned";
        QTest::newRow("function") << "speed(ball)"
                                  << "unknown probe \"speed(ball)\"; known: ";
        QTest::newRow("empty") << ""
                               << "unknown probe \"\"; known: ";
        QTest::newRow("bare id") << "ball"
                                 << "unknown probe \"ball\"; known: ";
    }
    void unknownProbesAreRefusedWithTheVocabulary() {
        QFETCH(QString, text);
        QFETCH(QString, reason);
        SceneDesc scene = oscillatorScene("rk4", 0.01, {1.0, 0.0}, {0.0, 0.0});
        ParticleDesc post = particle("post", {0.0, 1.0});
        post.pinned = true;
        scene.particles.push_back(post);
        auto world = build(scene);
        const ProbeParse parsed = parseProbe(*world, text.toStdString());
        QVERIFY(!parsed);
        const QString error = QString::fromStdString(parsed.error);
        QVERIFY2(error.startsWith(QStringLiteral("unknown probe \"%1\"").arg(text)),
                 qPrintable(error));
        QVERIFY2(error.contains(reason), qPrintable(error));
        QVERIFY2(error.endsWith(QString::fromUtf8(
                     probeVocabulary().data(), static_cast<qsizetype>(probeVocabulary().size()))),
                 qPrintable(error));
        for (const char* form : {"ID.x", "ID.L", "system.com_y", "distance(A,B)", "angle(A,B,C)",
                                 "force(JOINT)", "contact_force(ID)"})
            QVERIFY(error.contains(QLatin1String(form)));
        // What is known parses, spaces around the arguments allowed.
        QVERIFY(parseProbe(*world, " distance( ball , post ) "));
        QVERIFY(parseProbe(*world, "post.vy"));
        QVERIFY(parseProbe(*world, "contact_force(ball)"));
    }
};

QTEST_GUILESS_MAIN(TestProbes)
#include "tst_probes.moc"
