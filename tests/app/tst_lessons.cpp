// The lessons (resources/lessons/*.phasebox.json, compiled in as :/lessons/…): the six topics
// of issue #7, the rolling race, and the four joint lessons of issue #17 (simple pendulum,
// double pendulum, Atwood machine, bead on a hoop), each with notes the app shows (what to do,
// what to watch, why), each loading, building and running its duration with its own integrator
// without diverging, and each lesson's claim holding: explicit Euler spirals out where RK4 stays
// on the orbit, RK4 beats midpoint at the same step and at the same cost, explicit methods blow
// up on the stiff spring where implicit ones run, balls rebound to e²·h and crates stop after
// v²/(2μg), a cloth folds without shear springs and folds more with its bend springs lowered, an
// off-centre hit spins the box with momentum and angular momentum kept, pendulums and the bead
// keep the exact period 4·√(L/g)·K(sin(θ0/2)), double pendulums 1e-9 rad apart part after
// seconds, and Atwood machines accelerate at g·(m1 − m2)/(m1 + m2). Also the scene key that the
// Coulomb effect added.

#include "app/io/SceneIO.h"
#include "physics/scene/BuildWorld.h"

#include <QDir>
#include <QFile>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

using namespace phasebox;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81;
const QString kResourceDir = QStringLiteral(":/lessons");
const QString kDiskDir = QStringLiteral(PHASEBOX_SOURCE_DIR "/resources/lessons");

const QStringList kLessons = {QStringLiteral("atwood-machine.phasebox.json"),
                              QStringLiteral("bead-on-hoop.phasebox.json"),
                              QStringLiteral("cloth-springs.phasebox.json"),
                              QStringLiteral("double-pendulum.phasebox.json"),
                              QStringLiteral("euler-orbit-spiral.phasebox.json"),
                              QStringLiteral("impulse-spin.phasebox.json"),
                              QStringLiteral("midpoint-vs-rk4.phasebox.json"),
                              QStringLiteral("restitution-friction.phasebox.json"),
                              QStringLiteral("rolling-race.phasebox.json"),
                              QStringLiteral("simple-pendulum.phasebox.json"),
                              QStringLiteral("stiff-spring-implicit.phasebox.json"),
                              QStringLiteral("three-ways-to-collide.phasebox.json")};

SceneDesc load(const QString& file) {
    const SceneLoadResult result = SceneIO::load(kResourceDir + QLatin1Char('/') + file);
    if (!result.ok()) qFatal("%s", qPrintable(result.errorText()));
    return *result.scene;
}

std::unique_ptr<World> build(const SceneDesc& scene, const std::string& integrator = {},
                             double dt = 0.0) {
    SceneDesc s = scene;
    if (!integrator.empty()) s.simulation.integrator = integrator;
    if (dt > 0.0) s.simulation.dt = dt;
    return buildWorld(s).world;
}

int indexOf(const World& world, const std::string& id, bool box = false) {
    if (box) {
        for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i)
            if (world.rigidBodies()[i].id == id) return i;
    } else {
        for (int i = 0; i < static_cast<int>(world.particles().size()); ++i)
            if (world.particles()[i].id == id) return i;
    }
    qFatal("no object %s", id.c_str());
}

// The exact period of a pendulum of length l released from rest at θ0 (g = 9.81).
double pendulumPeriod(double length, double theta0) {
    return 4.0 * std::sqrt(length / kG) * std::comp_ellint_1(std::sin(0.5 * theta0));
}

// The mean time between upward crossings of x = centre by particle i (interpolated within the
// step) over the scene's duration, with the largest joint error at the end of any step.
double measuredPeriod(World& world, int i, double centre, double duration, double* maxJointError) {
    std::vector<double> crossings;
    double x = world.particlePosition(i).x() - centre, t = world.time();
    *maxJointError = 0.0;
    while (world.time() < duration - 0.5 * world.settings().dt) {
        if (!world.step()) return -1.0;
        const double x1 = world.particlePosition(i).x() - centre;
        if (x < 0.0 && x1 >= 0.0) crossings.push_back(t + (world.time() - t) * -x / (x1 - x));
        x = x1;
        t = world.time();
        *maxJointError = std::max(*maxJointError, world.jointErrors().position);
    }
    if (crossings.size() < 2) return -1.0;
    return (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

// Steps to the end of the scene's duration; false when a step diverges.
bool runDuration(World& world, double duration) {
    while (world.time() < duration - 0.5 * world.settings().dt)
        if (!world.step()) return false;
    return true;
}

// How far a cloth has folded: the width of its bottom row, and its sharpest crease, the largest
// turning angle between consecutive threads along any row or column (0 for a flat grid).
struct Fold {
    double width = 0.0, sharpest = 0.0;
};
Fold fold(const World& world, const Cloth& c) {
    Fold f;
    auto node = [&](int i, int j) { return world.particlePosition(clothNode(c, i, j)); };
    auto turn = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& d) {
        const Eigen::Vector2d u = b - a, v = d - b;
        f.sharpest =
            std::max(f.sharpest, std::abs(std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v))));
    };
    for (int j = 0; j < c.ny; ++j)
        for (int i = 1; i + 1 < c.nx; ++i) turn(node(i - 1, j), node(i, j), node(i + 1, j));
    for (int i = 0; i < c.nx; ++i)
        for (int j = 1; j + 1 < c.ny; ++j) turn(node(i, j - 1), node(i, j), node(i, j + 1));
    f.width = (node(c.nx - 1, c.ny - 1) - node(0, c.ny - 1)).norm();
    return f;
}

}  // namespace

class TestLessons : public QObject {
    Q_OBJECT

private slots:
    void theLessonsAreCompiledInAndOnDisk();
    void everyLessonHasNotesAndRunsItsDuration_data();
    void everyLessonHasNotesAndRunsItsDuration();
    void eulerSpiralsOutWhileRk4StaysOnTheOrbit();
    void eulerStepRaisesTheOrbitsEnergy();
    void rk4BeatsMidpointAtTheSameStepAndTheSameCost();
    void stiffSpringBlowsUpExplicitMethodsButNotImplicitOnes();
    void ballsReboundToESquaredHAndCratesStopAfterVSquaredOverTwoMuG();
    void clothWithoutShearOrBendSpringsDeformsMore();
    void offCentreHitSpinsTheBoxAndKeepsAngularMomentum();
    void coulombConstantsRoundTripThroughTheSceneFormat();
    void theRollingRaceFinishesInTheOrderOfItsClosedForms();
    void simplePendulumsSwingWithTheExactPeriods();
    void doublePendulumsPartAfterSomeSeconds();
    void atwoodMachinesAccelerateAtTheClosedForm();
    void beadOnTheHoopSwingsWithThePendulumsPeriod();
    void threeWaysToCollide_data();
    void threeWaysToCollide();
};

void TestLessons::theLessonsAreCompiledInAndOnDisk() {
    const QStringList compiledIn =
        QDir(kResourceDir).entryList({QStringLiteral("*.phasebox.json")}, QDir::Files, QDir::Name);
    const QStringList onDisk =
        QDir(kDiskDir).entryList({QStringLiteral("*.phasebox.json")}, QDir::Files, QDir::Name);
    QCOMPARE(onDisk, kLessons);
    QCOMPARE(compiledIn, onDisk);
    for (const QString& name : onDisk) {
        QFile a(kResourceDir + QLatin1Char('/') + name), b(kDiskDir + QLatin1Char('/') + name);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QVERIFY2(a.readAll() == b.readAll(),
                 qPrintable(name + QStringLiteral(" differs; rebuild")));
    }
}

void TestLessons::everyLessonHasNotesAndRunsItsDuration_data() {
    QTest::addColumn<QString>("file");
    for (const QString& file : kLessons) QTest::newRow(qPrintable(file)) << file;
}

// Notes in three parts (what to do step by step, what to watch, why) and of a lesson's length;
// the scene builds with nothing unsupported and runs its whole duration with its integrator.
void TestLessons::everyLessonHasNotesAndRunsItsDuration() {
    QFETCH(QString, file);
    const SceneDesc scene = load(file);
    QVERIFY(QString::fromStdString(scene.name).startsWith(QStringLiteral("Lesson: ")));
    const QString notes = QString::fromStdString(scene.description);
    for (const char* part : {"Try this: 1)", "What to watch:", "Why:"})
        QVERIFY2(notes.contains(QLatin1String(part)), part);
    const qsizetype why = notes.indexOf(QStringLiteral("Why:"));
    const auto sentences = notes.mid(why).count(QStringLiteral(". ")) + 1;
    QVERIFY2(sentences >= 4 && sentences <= 8, qPrintable(QString::number(sentences)));
    BuildResult built = buildWorld(scene);
    QVERIFY(built.unsupported.empty());
    QVERIFY2(runDuration(*built.world, scene.simulation.duration),
             built.world->divergence() ? built.world->divergence()->message().c_str() : "");
    QVERIFY(built.world->positions().allFinite());
}

// Explicit Euler raises a circular orbit's energy by about 2·(ω·dt)² of it per step
// (eulerStepRaisesTheOrbitsEnergy): the inner orbit (ω = 1.92 rad/s) doubles its semi-major axis
// a = −GM/(2E) within 20 s, the outer one (0.89 rad/s) grows by more than a third. Symplectic
// Euler's radius wobbles by about two percent and its orbits keep their size; RK4's radius stays
// within 1e-5.
void TestLessons::eulerSpiralsOutWhileRk4StaysOnTheOrbit() {
    const SceneDesc scene = load(QStringLiteral("euler-orbit-spiral.phasebox.json"));
    const double gm = 100.0;
    for (const char* method : {"explicit_euler", "symplectic_euler", "rk4"}) {
        auto world = build(scene, method);
        const int inner = indexOf(*world, "inner"), outer = indexOf(*world, "outer");
        double worst = 0.0;
        while (world->time() < scene.simulation.duration - 1e-9) {
            QVERIFY(world->step());
            worst = std::max({worst, std::abs(world->particlePosition(inner).norm() / 3.0 - 1.0),
                              std::abs(world->particlePosition(outer).norm() / 5.0 - 1.0)});
        }
        auto semiMajorAxis = [&](int i) {
            const double energy = 0.5 * world->particleVelocity(i).squaredNorm() -
                                  gm / world->particlePosition(i).norm();
            return -gm / (2.0 * energy);
        };
        const double grownInner = semiMajorAxis(inner) / 3.0 - 1.0;
        const double grownOuter = semiMajorAxis(outer) / 5.0 - 1.0;
        qInfo(
            "%-16s semi-major axes grew by %.1f%% (inner) and %.1f%% (outer); radius off by "
            "%.2e at worst",
            method, 100.0 * grownInner, 100.0 * grownOuter, worst);
        if (std::string(method) == "explicit_euler") {
            QVERIFY(grownInner > 0.8 && grownInner < 1.3);
            QVERIFY(grownOuter > 0.3 && grownOuter < 0.5);
            QVERIFY(world->energy().drift > 0.0);
        } else {
            QVERIFY(worst < (std::string(method) == "rk4" ? 1e-5 : 5e-2));
            QVERIFY(std::abs(grownInner) < 1e-3 && std::abs(grownOuter) < 1e-3);
        }
    }
}

// The lesson's rate, from the closed form: on a circular orbit of radius r and angular speed ω
// one explicit Euler step adds a·dt ⊥ v to the velocity (kinetic energy +½·ω⁴·r²·dt² a unit
// mass) and moves the planet along the tangent to r·√(1 + (ω·dt)²) (potential +½·ω⁴·r²·dt²),
// against |E| = ½·ω²·r²: 2·(ω·dt)² of the energy. ω² goes as r⁻³, so the inner orbit's share is
// (5/3)³ = 4.63 times the outer one's.
void TestLessons::eulerStepRaisesTheOrbitsEnergy() {
    const SceneDesc scene = load(QStringLiteral("euler-orbit-spiral.phasebox.json"));
    const double gm = 100.0, dt = scene.simulation.dt;
    double rates[2] = {0.0, 0.0};
    for (const int k : {0, 1}) {
        auto world = build(scene, "explicit_euler");
        const int i = indexOf(*world, k == 0 ? "inner" : "outer");
        const auto energy = [&] {  // per unit mass, about the star at the origin
            return 0.5 * world->particleVelocity(i).squaredNorm() -
                   gm / world->particlePosition(i).norm();
        };
        const double r = world->particlePosition(i).norm();
        const double omegaDt = std::sqrt(gm / (r * r * r)) * dt;
        const double before = energy();
        QVERIFY(world->step());
        rates[k] = (energy() - before) / std::abs(before);
        qInfo("r = %g m: one step raised the energy by %.6g of it; 2·(ω·dt)² = %.6g", r, rates[k],
              2.0 * omegaDt * omegaDt);
        QVERIFY2(std::abs(rates[k] / (2.0 * omegaDt * omegaDt) - 1.0) < 0.01,
                 qPrintable(QString::number(rates[k])));
    }
    QVERIFY2(rates[0] > 4.5 * rates[1], qPrintable(QString::number(rates[0] / rates[1])));
}

// x = cos 2t exactly. At dt = 0.1 (ω·dt = 0.2) midpoint's phase runs ahead by about z³/6 per
// step and its amplitude grows; RK4's error is ~(ω·dt)⁴ smaller. Midpoint at dt/2 costs what
// RK4 costs at dt (4 force evaluations per 0.1 s) and is still far less accurate.
void TestLessons::rk4BeatsMidpointAtTheSameStepAndTheSameCost() {
    const SceneDesc scene = load(QStringLiteral("midpoint-vs-rk4.phasebox.json"));
    QCOMPARE(scene.simulation.integrator, std::string("midpoint"));
    auto errorOf = [&](const char* method, double dt, double* phase = nullptr) {
        auto world = build(scene, method, dt);
        double worst = 0.0;
        while (world->time() < scene.simulation.duration - 1e-9) {
            if (!world->step()) return -1.0;
            worst = std::max(
                worst, std::abs(world->particlePosition(0).x() - std::cos(2.0 * world->time())));
        }
        if (phase) {
            const Eigen::Vector2d x = world->particlePosition(0), v = world->particleVelocity(0);
            *phase =
                std::remainder(std::atan2(-v.x() / 2.0, x.x()) - 2.0 * world->time(), 2.0 * kPi);
        }
        return worst;
    };
    double midpointPhase = 0.0;
    const double midpoint = errorOf("midpoint", 0.1, &midpointPhase);
    const double rk4 = errorOf("rk4", 0.1);
    const double midpointHalf = errorOf("midpoint", 0.05);
    qInfo(
        "max |x − cos 2t| over 20 s: midpoint %.3e (phase %+.3f rad), RK4 %.3e, midpoint at "
        "dt/2 %.3e",
        midpoint, midpointPhase, rk4, midpointHalf);
    QVERIFY(rk4 > 0.0 && rk4 < midpoint / 100.0);
    QVERIFY(midpointHalf > 10.0 * rk4);
    QVERIFY(midpointPhase > 0.2 && midpointPhase < 0.35);  // "a quarter of a radian ahead"
}

// ω·dt ≈ 17 for the bead: symplectic Euler and RK4 diverge (and are stopped); implicit Euler
// runs but damps the soft swing (to about half in 10 s); implicit midpoint runs and keeps it.
void TestLessons::stiffSpringBlowsUpExplicitMethodsButNotImplicitOnes() {
    const SceneDesc scene = load(QStringLiteral("stiff-spring-implicit.phasebox.json"));
    for (const char* method : {"symplectic_euler", "rk4"}) {
        auto world = build(scene, method);
        QVERIFY2(!runDuration(*world, scene.simulation.duration), method);
        qInfo("%-17s diverged at t = %.3f s", method, world->divergence()->time);
        QVERIFY(world->divergence()->time < 1.0);
    }
    // The soft swing's amplitude over the last 2 s (a period) against the initial 0.5 m.
    auto swing = [&](const char* method) {
        auto world = build(scene, method);
        double amplitude = 0.0;
        while (world->time() < scene.simulation.duration - 1e-9) {
            if (!world->step()) return -1.0;
            if (world->time() > scene.simulation.duration - 2.0)
                amplitude = std::max(amplitude, std::abs(world->particlePosition(0).x() - 1.0));
        }
        return amplitude / 0.5;
    };
    const double backward = swing("implicit_euler"), midpoint = swing("implicit_midpoint");
    qInfo("soft swing kept after 10 s: implicit Euler %.2f, implicit midpoint %.2f", backward,
          midpoint);
    QVERIFY(backward > 0.2 && backward < 0.7);
    QVERIFY(midpoint > 0.9);
}

// Each ball's first rebound peaks at e²·h; each crate stops after v²/(2·μ·g).
void TestLessons::ballsReboundToESquaredHAndCratesStopAfterVSquaredOverTwoMuG() {
    const SceneDesc scene = load(QStringLiteral("restitution-friction.phasebox.json"));
    auto world = build(scene);
    const int balls = static_cast<int>(scene.particles.size());
    std::vector<double> top(balls, -1.0);
    std::vector<bool> bounced(balls, false), done(balls, false);
    std::vector<double> start, stopped;
    std::vector<int> crates;
    for (const char* id : {"on_ice", "on_wood", "on_rubber"}) {
        crates.push_back(indexOf(*world, id, true));
        start.push_back(world->bodyPosition(crates.back()).x());
        stopped.push_back(-1.0);
    }
    while (world->time() < scene.simulation.duration - 1e-9) {
        QVERIFY(world->step());
        for (int i = 0; i < balls; ++i) {
            const double vy = world->particleVelocity(i).y();
            if (done[i]) continue;
            bounced[i] = bounced[i] || vy > 0.0;
            if (bounced[i]) top[i] = std::max(top[i], world->particlePosition(i).y() - 0.15);
            done[i] = bounced[i] && vy < 0.0;
        }
        for (std::size_t k = 0; k < crates.size(); ++k)
            if (stopped[k] < 0.0 && std::abs(world->bodyVelocity(crates[k]).x()) < 1e-3)
                stopped[k] = world->bodyPosition(crates[k]).x() - start[k];
    }
    for (int i = 0; i < balls; ++i) {
        const double e = scene.particles[i].restitution, expected = e * e * 2.0;
        qInfo("ball e = %.1f: rebound %.3f m, e²·h = %.3f m", e, top[i], expected);
        QVERIFY(done[i] && std::abs(top[i] - expected) < 0.02 * 2.0);
    }
    const double mu[] = {0.1, 0.4, 0.8};
    for (std::size_t k = 0; k < crates.size(); ++k) {
        const double expected = 16.0 / (2.0 * mu[k] * kG);
        qInfo("crate μ = %.1f: stopped after %.3f m, v²/(2μg) = %.3f m", mu[k], stopped[k],
              expected);
        QVERIFY(stopped[k] > 0.0 && std::abs(stopped[k] - expected) < 0.03 * expected);
    }
}

// The three cloths hang side by side from two inner nodes of their top edge: the full one keeps
// its shape; without shear springs the mesh folds and the cloth narrows; with the bend springs
// lowered too (to 0) it folds more: narrower still, and with sharper creases.
void TestLessons::clothWithoutShearOrBendSpringsDeformsMore() {
    const SceneDesc scene = load(QStringLiteral("cloth-springs.phasebox.json"));
    QCOMPARE(scene.cloths[1].stiffness.bend, 20.0);
    QCOMPARE(scene.cloths[2].stiffness.bend, 0.0);
    auto world = build(scene);
    QVERIFY(runDuration(*world, scene.simulation.duration));
    const Cloth &full = world->cloths()[0], &noShear = world->cloths()[1],
                &noBend = world->cloths()[2];
    const Fold f = fold(*world, full), s = fold(*world, noShear), b = fold(*world, noBend);
    qInfo(
        "bottom width / sharpest crease: full %.3f m / %.3f rad, no shear %.3f m / %.3f rad, "
        "no shear and no bend %.3f m / %.3f rad",
        f.width, f.sharpest, s.width, s.sharpest, b.width, b.sharpest);
    QVERIFY(std::abs(f.width - 1.2) < 0.01 && f.sharpest < 0.2);
    QVERIFY(s.width < 0.8);
    QVERIFY(b.width < s.width - 0.1);
    QVERIFY(b.sharpest > 1.5 * s.sharpest);
}

// J = (1 + e)·m·v/(1 + m/M + m·d²/I), V = J/M, ω = −J·d/I (clockwise for a hit above the
// centre); momentum and angular momentum about the point of impact are kept.
void TestLessons::offCentreHitSpinsTheBoxAndKeepsAngularMomentum() {
    const SceneDesc scene = load(QStringLiteral("impulse-spin.phasebox.json"));
    auto world = build(scene);
    const double m = 0.1, v = 20.0, M = 2.0, d = 0.15, e = 0.5;
    const double I = M * (1.0 + 0.25) / 12.0;
    const double J = (1.0 + e) * m * v / (1.0 + m / M + m * d * d / I);
    const Eigen::Vector2d impact(-0.5, 0.15);
    auto momenta = [&](Eigen::Vector2d& p) {
        const Eigen::Vector2d x = world->particlePosition(0) - impact,
                              u = world->particleVelocity(0);
        const Eigen::Vector2d X = world->bodyPosition(0) - impact, U = world->bodyVelocity(0);
        p = m * u + M * U;
        return m * (x.x() * u.y() - x.y() * u.x()) + M * (X.x() * U.y() - X.y() * U.x()) +
               I * world->bodyAngularVelocity(0);
    };
    Eigen::Vector2d p0, p1;
    const double l0 = momenta(p0);
    QVERIFY(runDuration(*world, scene.simulation.duration));
    const double l1 = momenta(p1);
    const double omega = world->bodyAngularVelocity(0);
    qInfo(
        "box: ω = %.4f rad/s (closed form %.4f), V = %.4f m/s (%.4f); L about the impact "
        "point %.2e → %.2e, momentum change %.2e",
        omega, -J * d / I, world->bodyVelocity(0).x(), J / M, l0, l1, (p1 - p0).norm());
    QVERIFY(std::abs(omega + J * d / I) < 0.02 * J * d / I);
    QVERIFY(std::abs(world->bodyVelocity(0).x() - J / M) < 0.02 * J / M);
    QVERIFY(std::abs(l1 - l0) < 1e-3 * m * v * d);
    QVERIFY((p1 - p0).norm() < 1e-9 * m * v);
}

// effects.coulomb {k, softening} reads, validates, writes back, and a misspelt key is an error.
void TestLessons::coulombConstantsRoundTripThroughTheSceneFormat() {
    const QByteArray text = R"({"format": "phasebox-scene", "version": 1,
        "effects": {"coulomb": {"k": 2.5, "softening": 0.1}},
        "particles": [{"position": [0, 0], "charge": 1}, {"position": [1, 0], "charge": -1}]})";
    const SceneLoadResult loaded = SceneIO::parse(text, QStringLiteral("charges.json"));
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    QVERIFY(loaded.scene->effects.coulomb.has_value());
    QCOMPARE(loaded.scene->effects.coulomb->k, 2.5);
    QCOMPARE(loaded.scene->effects.coulomb->softening, 0.1);
    auto world = buildWorld(*loaded.scene).world;
    // k·q₁·q₂/√(r² + ε²) with the file's constants.
    QVERIFY(std::abs(world->energy().potential - (-2.5 / std::sqrt(1.01))) < 1e-12);
    const QByteArray written = SceneIO::serialize(*loaded.scene);
    QVERIFY(written.contains("\"coulomb\""));
    const SceneLoadResult again = SceneIO::parse(written, QStringLiteral("charges.json"));
    QVERIFY(again.ok());
    QCOMPARE(SceneIO::serialize(*again.scene), written);
    const SceneLoadResult typo = SceneIO::parse(
        R"({"format": "phasebox-scene", "version": 1, "effects": {"coulomb": {"softenning": 1}}})",
        QStringLiteral("charges.json"));
    QVERIFY(!typo.ok());
    QVERIFY2(typo.errorText().contains(QStringLiteral("effects.coulomb.softenning")),
             qPrintable(typo.errorText()));
    const SceneLoadResult negative = SceneIO::parse(
        R"({"format": "phasebox-scene", "version": 1, "effects": {"coulomb": {"k": -1}}})",
        QStringLiteral("charges.json"));
    QVERIFY(!negative.ok());
}

// The rolling race: on the same 20° slope a frictionless disk slides at g·sin θ, a disk that
// rolls at ⅔·g·sin θ and a box with μ = 0.2 at g·(sin θ − μ·cos θ); each covers its 5 m in
// √(2L/a), and they finish in that order.
void TestLessons::theRollingRaceFinishesInTheOrderOfItsClosedForms() {
    const SceneDesc scene = load(QStringLiteral("rolling-race.phasebox.json"));
    const double theta = 20.0 * std::numbers::pi / 180.0, length = 5.0;
    const Vec2 down(-std::cos(theta), -std::sin(theta));
    const struct {
        const char* id;
        double acceleration;
    } racers[] = {{"slider", kG * std::sin(theta)},
                  {"disk", 2.0 / 3.0 * kG * std::sin(theta)},
                  {"box", kG * (std::sin(theta) - 0.2 * std::cos(theta))}};
    auto world = build(scene);
    std::vector<int> index;
    std::vector<Vec2> start;
    for (const auto& r : racers) {
        index.push_back(indexOf(*world, r.id, true));
        start.push_back(world->bodyPosition(index.back()));
    }
    std::vector<double> finished(std::size(racers), -1.0);
    while (world->time() < scene.simulation.duration - 1e-9) {
        const double before = world->time();
        std::vector<double> was;
        for (std::size_t k = 0; k < index.size(); ++k)
            was.push_back((world->bodyPosition(index[k]) - start[k]).dot(down));
        QVERIFY(world->step());
        for (std::size_t k = 0; k < index.size(); ++k) {
            const double now = (world->bodyPosition(index[k]) - start[k]).dot(down);
            if (finished[k] < 0.0 && now >= length)  // interpolated within the step
                finished[k] =
                    before + (world->time() - before) * (length - was[k]) / (now - was[k]);
        }
    }
    for (std::size_t k = 0; k < index.size(); ++k) {
        const double expected = std::sqrt(2.0 * length / racers[k].acceleration);
        qInfo("%s: 5 m in %.3f s, sqrt(2L/a) = %.3f s", racers[k].id, finished[k], expected);
        QVERIFY2(finished[k] > 0.0 && std::abs(finished[k] / expected - 1.0) < 0.01,
                 qPrintable(QString::number(finished[k])));
    }
    QVERIFY(finished[0] < finished[1] && finished[1] < finished[2]);
}

// Two 1 kg bobs on 1 m rods released at 10° and 90°: each swings with the exact period
// 4·√(L/g)·K(sin(θ0/2)) (2.0099 s and 2.3678 s; 2π·√(L/g) = 2.006 s for small swings), which
// the notes quote; within 0.1% under the lesson's symplectic Euler at 1/60 s and within 1e-4 s
// under RK4 at 1/600 s. The rods hold to round-off.
void TestLessons::simplePendulumsSwingWithTheExactPeriods() {
    const SceneDesc scene = load(QStringLiteral("simple-pendulum.phasebox.json"));
    QCOMPARE(scene.simulation.integrator, std::string("symplectic_euler"));
    QCOMPARE(scene.simulation.dt, 1.0 / 60.0);
    const QString notes = QString::fromStdString(scene.description);
    QVERIFY(notes.contains(QStringLiteral("2π·√(L/g) = 2.006 s")));
    QCOMPARE(scene.joints.size(), std::size_t(2));
    for (const JointDesc& rod : scene.joints) {
        QVERIFY(rod.type == JointType::Rod && rod.anchor && !rod.b);
        const ParticleDesc* bob = nullptr;
        for (const ParticleDesc& p : scene.particles)
            if (p.id == rod.a) bob = &p;
        QVERIFY(bob && bob->mass == 1.0);
        const Vec2 pivot((*rod.anchor)[0], (*rod.anchor)[1]);
        const Vec2 offset = Vec2(bob->position[0], bob->position[1]) - pivot;
        QVERIFY(std::abs(offset.norm() - 1.0) < 1e-9 && rod.length && *rod.length == 1.0);
        const double theta0 = std::atan2(std::abs(offset.x()), -offset.y());
        const double exact = pendulumPeriod(1.0, theta0);
        QVERIFY2(notes.contains(QString::number(exact, 'f', 4) + QStringLiteral(" s")),
                 qPrintable(QString::number(exact, 'f', 4)));
        for (const auto& [method, dt, tolerance] :
             {std::tuple{"symplectic_euler", 1.0 / 60.0, 1e-3 * exact},
              std::tuple{"rk4", 1.0 / 600.0, 1e-4}}) {
            auto world = build(scene, method, dt);
            double maxError = 0.0;
            const double period = measuredPeriod(*world, indexOf(*world, bob->id), pivot.x(),
                                                 scene.simulation.duration, &maxError);
            qInfo(
                "%s released at %.0f deg, %s dt %.4f: period %.5f s, exact %.5f s, joint error "
                "%.1e m",
                bob->id.c_str(), theta0 * 180.0 / kPi, method, dt, period, exact, maxError);
            QVERIFY(std::abs(period - exact) < tolerance);
            QVERIFY(maxError < 1e-6);
        }
    }
}

// Two double pendulums whose lower rods start 1e-9 rad apart, under RK4 at a fine step: they
// move as one for seconds (lower bobs within 1 mm of each other, relative to their pivots, up
// to 7 s), then part (more than 0.1 m apart by 14 s); the energy stays to within 1e-4 J.
void TestLessons::doublePendulumsPartAfterSomeSeconds() {
    const SceneDesc scene = load(QStringLiteral("double-pendulum.phasebox.json"));
    QCOMPARE(scene.simulation.integrator, std::string("rk4"));
    QVERIFY(scene.simulation.dt <= 1.0 / 500.0);
    QVERIFY(scene.simulation.duration >= 15.0);
    auto world = build(scene);
    const int a = indexOf(*world, "a2"), b = indexOf(*world, "b2");
    const Vec2 shift = world->particlePosition(b) - world->particlePosition(a);
    QVERIFY(std::abs(shift.y()) < 1e-8);  // the pivots are level; the bobs start 1e-9 m apart
    double together = 0.0, parted = -1.0, worstDrift = 0.0, worstJoint = 0.0;
    while (world->time() < 14.0) {
        QVERIFY(world->step());
        const double gap = (world->particlePosition(b) - world->particlePosition(a) - shift).norm();
        if (world->time() <= 7.0) together = std::max(together, gap);
        if (parted < 0.0 && gap > 0.1) parted = world->time();
        worstDrift = std::max(worstDrift, std::abs(world->energy().drift));
        worstJoint = std::max(worstJoint, world->jointErrors().position);
    }
    qInfo(
        "lower bobs within %.2e m up to 7 s, 0.1 m apart at %.2f s; |drift| <= %.1e J, joint "
        "error <= %.1e m",
        together, parted, worstDrift, worstJoint);
    QVERIFY(together < 1e-3);
    QVERIFY(parted > 7.0 && parted < 14.0);
    QVERIFY(worstDrift < 1e-4);
    QVERIFY(worstJoint < 1e-6);
}

// Each Atwood machine accelerates at a = g·(m1 − m2)/(m1 + m2) (g/2 and g/10 here) while both
// weights hang, with the rope's tension T = 2·m1·m2·g/(m1 + m2) quoted in the notes; each
// heavy weight lands on the floor and no weight reaches its pulley.
void TestLessons::atwoodMachinesAccelerateAtTheClosedForm() {
    const SceneDesc scene = load(QStringLiteral("atwood-machine.phasebox.json"));
    const QString notes = QString::fromStdString(scene.description);
    auto world = build(scene);
    struct Machine {
        int heavy, light;
        double a, groundB, top;
    };
    std::vector<Machine> machines;
    for (const JointDesc& j : scene.joints) {
        QVERIFY(j.type == JointType::Pulley && j.ratio == 1.0 && j.b);
        const BoxDesc *heavy = nullptr, *light = nullptr;
        for (const BoxDesc& box : scene.boxes) {
            if (box.id == j.a) heavy = &box;
            if (box.id == *j.b) light = &box;
        }
        QVERIFY(heavy && light && heavy->mass && light->mass && *heavy->mass > *light->mass);
        const double m1 = *heavy->mass, m2 = *light->mass;
        const double tension = 2.0 * m1 * m2 * kG / (m1 + m2);
        const QString t3 = QString::number(tension, 'g', 3), t4 = QString::number(tension, 'g', 4);
        QVERIFY2(
            notes.contains(t3 + QStringLiteral(" N")) || notes.contains(t4 + QStringLiteral(" N")),
            qPrintable(t3));
        machines.push_back({indexOf(*world, j.a, true), indexOf(*world, *j.b, true),
                            kG * (m1 - m2) / (m1 + m2), j.groundB[1], 0.5 * light->size[1]});
    }
    QCOMPARE(machines.size(), std::size_t(2));
    QVERIFY(runDuration(*world, 0.5));  // before either heavy weight lands
    for (const Machine& m : machines) {
        const double vHeavy = world->bodyVelocity(m.heavy).y(),
                     vLight = world->bodyVelocity(m.light).y();
        qInfo("a = %.4f m/s^2 (closed form %.4f): heavy %.4f m/s, light %.4f m/s at t = %.2f s",
              -vHeavy / world->time(), m.a, vHeavy, vLight, world->time());
        QVERIFY(std::abs(-vHeavy / world->time() - m.a) < 1e-3 * m.a);
        QVERIFY(std::abs(vLight / world->time() - m.a) < 1e-3 * m.a);
    }
    double highest = -1e9;
    while (world->time() < scene.simulation.duration - 0.5 * scene.simulation.dt) {
        QVERIFY(world->step());
        QVERIFY(world->jointErrors().position < 1e-3);
        for (const Machine& m : machines)
            highest = std::max(highest, world->bodyPosition(m.light).y() + m.top - m.groundB);
    }
    for (const Machine& m : machines) {
        const double bottom =
            world->bodyPosition(m.heavy).y() - 0.5 * world->rigidBodies()[m.heavy].size.y();
        QVERIFY2(std::abs(bottom) < 0.01, qPrintable(QString::number(bottom)));
    }
    QVERIFY2(highest < -1.0, qPrintable(QString::number(highest)));
}

// A bead on a frictionless circular wire of radius 1 m released at 90°: the period of a 1 m
// pendulum released at 90° (2.3678 s, quoted in the notes), within 0.1% under the lesson's
// symplectic Euler at 1/60 s; the bead never leaves the wire.
void TestLessons::beadOnTheHoopSwingsWithThePendulumsPeriod() {
    const SceneDesc scene = load(QStringLiteral("bead-on-hoop.phasebox.json"));
    QCOMPARE(scene.simulation.dt, 1.0 / 60.0);
    QCOMPARE(scene.joints.size(), std::size_t(1));
    const JointDesc& wire = scene.joints[0];
    QVERIFY(wire.type == JointType::Track && wire.circle && wire.circle->radius == 1.0);
    const double exact = pendulumPeriod(1.0, kPi / 2.0);
    QVERIFY(QString::fromStdString(scene.description).contains(QStringLiteral("2.3678 s")));
    auto world = build(scene);
    const int bead = indexOf(*world, wire.a);
    const Vec2 centre(wire.circle->center[0], wire.circle->center[1]);
    QVERIFY(std::abs((world->particlePosition(bead) - centre).norm() - 1.0) < 1e-12);
    QVERIFY(std::abs(world->particlePosition(bead).y() - centre.y()) < 1e-12);  // at 90°
    double maxError = 0.0;
    const double period =
        measuredPeriod(*world, bead, centre.x(), scene.simulation.duration, &maxError);
    qInfo("bead: period %.5f s, exact %.5f s; off the wire by %.1e m at most", period, exact,
          maxError);
    QVERIFY(std::abs(period - exact) < 1e-3 * exact);
    QVERIFY(maxError < 1e-6);
}

void TestLessons::threeWaysToCollide_data() {
    QTest::addColumn<int>("model");
    for (int m = 0; m < 3; ++m) QTest::newRow(contactModelName(ContactModel(m)).data()) << m;
}

// The notes' claims under each contact model (CONTRACT §6): the ball dropped from h = 2 m
// with e = 0.8 rebounds to e²·h within 3% under impulses and kinematic response; under penalty
// it stays in contact π·√(m/k)/√(1 − ζ²) (within a step), sinks at most v·√(m/k) and leaves at
// e·v with e = exp(−ζπ/√(1 − ζ²)); the stack stands under all three; the cradle hands the swing
// to the last ball with the middle ones still under impulses and kinematic response, and
// spreads it along the row under penalty.
void TestLessons::threeWaysToCollide() {
    QFETCH(int, model);
    SceneDesc scene = load(QStringLiteral("three-ways-to-collide.phasebox.json"));
    scene.simulation.contactModel = ContactModel(model);
    auto world = build(scene);
    const int ball = indexOf(*world, "ball"), last = indexOf(*world, "cradle4");
    const int middle = indexOf(*world, "cradle2"), top = indexOf(*world, "box3", true);
    const double radius = 0.25, h = 2.0, m = 1.0, dt = scene.simulation.dt;
    const double k = world->penaltyStiffness();
    QCOMPARE(k, m * (0.5 / dt) * (0.5 / dt));  // automatic: ω·h = 0.5
    const double zeta = scene.simulation.contactDamping / (2.0 * std::sqrt(k * m));
    const double root = std::sqrt(1.0 - zeta * zeta);
    const double ePenalty = std::exp(-zeta * kPi / root);
    double touch = -1.0, leave = -1.0, vIn = 0.0, vOut = 0.0, deepest = 0.0, apex = 0.0;
    double lastHighest = 0.0, middleFarthest = 0.0;
    const double lastRest = world->particlePosition(last).y();
    const double middleRest = world->particlePosition(middle).x();
    const double topStart = world->bodyPosition(top).y();
    double topFarthest = 0.0;
    while (world->time() < 4.0) {
        const Eigen::Vector2d v0 = world->particleVelocity(ball);
        QVERIFY(world->step());
        const double y = world->particlePosition(ball).y();
        if (touch < 0.0 && y < radius) {
            touch = world->time();
            vIn = -v0.y();
        }
        // Impulses and the kinematic response stop it at the surface: it leaves from there.
        if (leave < 0.0 && y >= radius && world->particleVelocity(ball).y() > 0) {
            leave = world->time();
            vOut = world->particleVelocity(ball).y();
        }
        deepest = std::max(deepest, radius - y);
        if (leave >= 0.0) apex = std::max(apex, y - radius);
        lastHighest = std::max(lastHighest, world->particlePosition(last).y() - lastRest);
        middleFarthest =
            std::max(middleFarthest, std::abs(world->particlePosition(middle).x() - middleRest));
        topFarthest = std::max(topFarthest, std::abs(world->bodyPosition(top).y() - topStart));
    }
    const double released = 2.0 * (1.0 - std::cos(40.0 * kPi / 180.0));  // the first ball's drop
    qInfo(
        "%s: apex %.4f m, deepest %.4f m, contact %.4f s, exit %.4f of %.4f m/s; cradle: last "
        "ball rises %.3f m of %.3f, middle moves %.3f m; stack top moves %.4f m",
        contactModelName(ContactModel(model)).data(), apex, deepest,
        touch >= 0.0 ? leave - touch : 0.0, vOut, vIn, lastHighest, released, middleFarthest,
        topFarthest);
    QVERIFY(topFarthest < 0.05);
    if (ContactModel(model) == ContactModel::Penalty) {
        const double duration = kPi * std::sqrt(m / k) / root;
        QVERIFY(std::abs((leave - touch) - duration) <= 1.5 * dt);
        QVERIFY(deepest <= vIn * std::sqrt(m / k));
        QVERIFY(std::abs(vOut - ePenalty * vIn) <= 0.02 * vIn);
        QVERIFY(middleFarthest > 0.1);  // the momentum spreads along the row
    } else {
        QVERIFY(std::abs(apex - 0.64 * h) <= 0.03 * 0.64 * h);
        QVERIFY(middleFarthest < 0.03);
        QVERIFY(lastHighest > 0.95 * released);
    }
}

QTEST_GUILESS_MAIN(TestLessons)
#include "tst_lessons.moc"
