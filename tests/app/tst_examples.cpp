// The example scenes of the Examples menu (resources/scenes/*.phasebox.json, compiled in as
// :/scenes/…): every file loads, says what it is, builds, round-trips and runs stably with its
// own integrator; and where physics has a closed form, the scene shows it (oscillator period,
// circular orbit, stick-or-slide on the incline, elastic gas, the flag's droop angle, the
// bouncing balls' e²·h) and the numerical lesson its description promises happens (explicit
// Euler gains energy on the orbit, symplectic Euler blows up on the stiff spring); the joint
// examples hold their joints and do what their descriptions say.

#include "app/io/SceneIO.h"
#include "physics/scene/BuildWorld.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

using namespace phasebox;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMaxRun = 10.0;  // seconds of simulated time per scene at most

const QString kResourceDir = QStringLiteral(":/scenes");
const QString kDiskDir = QStringLiteral(PHASEBOX_SOURCE_DIR "/resources/scenes");

// The scene files of a folder, sorted by name.
QStringList sceneFiles(const QString& dir) {
    return QDir(dir).entryList({QStringLiteral("*.phasebox.json")}, QDir::Files, QDir::Name);
}

// The example files: every scene file but the demo, which predates the Examples menu.
QStringList exampleFiles(const QString& dir) {
    QStringList files = sceneFiles(dir);
    files.removeAll(QStringLiteral("demo.phasebox.json"));
    return files;
}

SceneDesc load(const QString& file) {
    const SceneLoadResult result = SceneIO::load(kResourceDir + QLatin1Char('/') + file);
    if (!result.ok()) qFatal("%s", qPrintable(result.errorText()));
    return *result.scene;
}

std::unique_ptr<World> build(const SceneDesc& scene) {
    return buildWorld(scene).world;
}

int particleIndex(const World& world, const std::string& id) {
    for (int i = 0; i < static_cast<int>(world.particles().size()); ++i)
        if (world.particles()[i].id == id) return i;
    return -1;
}

int boxIndex(const World& world, const std::string& id) {
    for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i)
        if (world.rigidBodies()[i].id == id) return i;
    return -1;
}

const SpringDesc* springOn(const SceneDesc& scene, const std::string& id) {
    for (const SpringDesc& s : scene.springs)
        if (s.a == id || (s.b && *s.b == id)) return &s;
    return nullptr;
}

// Steps until the world's clock reaches t (within half a step); false on divergence.
bool runTo(World& world, double t) {
    while (world.time() < t - 0.5 * world.settings().dt)
        if (!world.step()) return false;
    return true;
}

bool integratorIsImplicit(const std::string& name) {
    return name == "implicit_euler" || name == "implicit_midpoint";
}

// Every dynamic coordinate and velocity, and the energy ledger, are finite numbers.
bool stateIsFinite(const World& world) {
    const EnergyLedger& e = world.energy();
    return world.positions().allFinite() && world.velocities().allFinite() &&
           std::isfinite(e.kinetic) && std::isfinite(e.potential) && std::isfinite(e.drift);
}

}  // namespace

class TestExamples : public QObject {
    Q_OBJECT

private slots:
    void thereAreTwentyExamplesCompiledInAndOnDisk();
    void everyExampleLoadsAndRoundTrips_data();
    void everyExampleLoadsAndRoundTrips();
    void everyExampleRunsStably_data();
    void everyExampleRunsStably();

    void springOscillatorHasPeriodTwoPiRootMOverK();
    void dampedOscillatorsFollowTheirClosedForms();
    void orbitStaysCircularUnderRk4();
    void orbitGainsEnergyUnderExplicitEuler();
    void stiffSpringDivergesUnderSymplecticEuler();
    void stiffSpringStaysBoundedUnderImplicitEuler();
    void boxesOnTheInclineStickOrSlideAsTanThetaPredicts();
    void elasticGasKeepsItsKineticEnergy();
    void flagSettlesAtTheWindAngle();
    void bouncingBallsReboundToESquaredH();
    void jointedExamplesHoldAndDoWhatTheySay_data();
    void jointedExamplesHoldAndDoWhatTheySay();
    void ragdollPushedAtAnySpeedKeepsItsBooks();
};

void TestExamples::thereAreTwentyExamplesCompiledInAndOnDisk() {
    const QStringList compiledIn = sceneFiles(kResourceDir);
    const QStringList onDisk = sceneFiles(kDiskDir);
    qInfo("%lld scene files compiled in, %lld on disk", static_cast<long long>(compiledIn.size()),
          static_cast<long long>(onDisk.size()));
    // Issue 19: at least 20 examples, the demo not counted.
    QVERIFY2(exampleFiles(kResourceDir).size() >= 20,
             qPrintable(compiledIn.join(QLatin1Char(' '))));
    QVERIFY2(exampleFiles(kDiskDir).size() >= 20, qPrintable(onDisk.join(QLatin1Char(' '))));
    // The built app carries exactly the files of the source tree, byte for byte.
    QCOMPARE(compiledIn, onDisk);
    for (const QString& name : onDisk) {
        QFile a(kResourceDir + QLatin1Char('/') + name), b(kDiskDir + QLatin1Char('/') + name);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QVERIFY2(a.readAll() == b.readAll(),
                 qPrintable(name + QStringLiteral(" differs; rebuild")));
    }
    for (const char* required :
         {"spring-oscillator", "pendulum-stiff-spring", "spring-chain", "cloth-flag", "box-pyramid",
          "newtons-cradle", "projectile-drag", "orbit", "elastic-gas", "box-incline",
          "stiff-spring-blowup", "chain-bridge", "ragdoll", "car"})
        QVERIFY2(
            compiledIn.contains(QString::fromLatin1(required) + QStringLiteral(".phasebox.json")),
            required);
}

void TestExamples::everyExampleLoadsAndRoundTrips_data() {
    QTest::addColumn<QString>("file");
    for (const QString& file : sceneFiles(kResourceDir)) QTest::newRow(qPrintable(file)) << file;
}

void TestExamples::everyExampleLoadsAndRoundTrips() {
    QFETCH(QString, file);
    const SceneLoadResult loaded = SceneIO::load(kResourceDir + QLatin1Char('/') + file);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    QVERIFY(loaded.errors.isEmpty());
    const SceneDesc& scene = *loaded.scene;
    QVERIFY2(!QString::fromStdString(scene.name).trimmed().isEmpty(), "the scene has no name");
    const QString description = QString::fromStdString(scene.description);
    QVERIFY2(description.size() >= 80,
             qPrintable(QStringLiteral("description too short: ") + description));

    // It builds, and everything it asks for is simulated.
    BuildResult built = buildWorld(scene);
    QVERIFY(built.world != nullptr);
    QVERIFY2(built.unsupported.empty(),
             built.unsupported.empty() ? "" : built.unsupported.front().c_str());
    QCOMPARE(built.world->settings().integrator, scene.simulation.integrator);

    // serialize → parse → serialize gives the same bytes.
    const QByteArray first = SceneIO::serialize(scene);
    const SceneLoadResult reparsed = SceneIO::parse(first, file);
    QVERIFY2(reparsed.ok(), qPrintable(reparsed.errorText()));
    QCOMPARE(SceneIO::serialize(*reparsed.scene), first);
}

void TestExamples::everyExampleRunsStably_data() {
    everyExampleLoadsAndRoundTrips_data();
}

// Each example runs with its own integrator for its duration (at most 10 s): no divergence,
// finite state, nothing flying off, and an energy error that is small against the energy that
// is actually moving about (the largest kinetic energy plus the range of the potential).
// Implicit Euler loses energy by design (its numerical damping is the lesson of two of the
// scenes), so for the implicit scenes the check is that the energy never rises.
void TestExamples::everyExampleRunsStably() {
    QFETCH(QString, file);
    const SceneDesc scene = load(file);
    auto world = build(scene);
    const double duration = std::min(scene.simulation.duration, kMaxRun);

    // Where things start: every object's position, and the spring anchors.
    double extent = 0.0;
    for (const ParticleDesc& p : scene.particles)
        extent = std::max({extent, std::abs(p.position[0]), std::abs(p.position[1])});
    for (const BoxDesc& b : scene.boxes)
        extent = std::max({extent, std::abs(b.position[0]), std::abs(b.position[1])});
    for (const ClothDesc& c : scene.cloths)
        extent = std::max(
            {extent, std::abs(c.origin[0]) + c.size[0], std::abs(c.origin[1]) + c.size[1]});
    QVERIFY2(extent <= 20.0, "objects should start within a classroom-sized view");

    double maxKinetic = world->energy().kinetic;
    double minPotential = world->energy().potential, maxPotential = minPotential;
    double maxDrift = 0.0, minDrift = 0.0, farthest = 0.0;
    while (world->time() < duration - 0.5 * scene.simulation.dt) {
        const bool ok = world->step();
        QVERIFY2(ok, world->divergence() ? world->divergence()->message().c_str() : "step failed");
        QVERIFY(!world->divergence());
        QVERIFY2(stateIsFinite(*world),
                 qPrintable(QStringLiteral("non-finite at t = %1").arg(world->time())));
        const EnergyLedger& e = world->energy();
        maxKinetic = std::max(maxKinetic, e.kinetic);
        minPotential = std::min(minPotential, e.potential);
        maxPotential = std::max(maxPotential, e.potential);
        maxDrift = std::max(maxDrift, e.drift);
        minDrift = std::min(minDrift, e.drift);
        // Positions only: the state's angles grow without bound on a wheel that keeps turning
        // (the car's), and are not distances.
        for (int i = 0; i < static_cast<int>(world->particles().size()); ++i)
            farthest = std::max(farthest, world->particlePosition(i).cwiseAbs().maxCoeff());
        for (int i = 0; i < static_cast<int>(world->rigidBodies().size()); ++i)
            farthest = std::max(farthest, world->bodyPosition(i).cwiseAbs().maxCoeff());
    }
    const double moving = maxKinetic + (maxPotential - minPotential);
    qInfo("%-36s %-17s %5.1f s: energy in motion %9.4g J, drift in [%.3g, %.3g] J, farthest %.2f m",
          qPrintable(file), scene.simulation.integrator.c_str(), world->time(), moving, minDrift,
          maxDrift, farthest);
    QVERIFY(std::abs(world->time() - duration) < scene.simulation.dt);
    QVERIFY2(farthest < extent + 15.0, "something flew away");
    if (integratorIsImplicit(scene.simulation.integrator)) {
        QVERIFY2(maxDrift <= 1e-3 * moving, "an implicit scene gained energy");
    } else {
        QVERIFY2(std::max(maxDrift, -minDrift) <= 0.05 * moving + 1e-9,
                 "the energy error is more than 5% of the energy in motion");
    }
}

// Both balls bounce with T = 2π√(m/k); gravity only shifts the equilibrium to mg/k below the
// spring's rest length. The period is measured between upward crossings of the equilibrium
// (linear interpolation between steps) under the scene's own integrator.
void TestExamples::springOscillatorHasPeriodTwoPiRootMOverK() {
    const SceneDesc scene = load(QStringLiteral("spring-oscillator.phasebox.json"));
    QVERIFY(scene.effects.gravity.has_value());
    const double g = -scene.effects.gravity->g[1];
    for (const ParticleDesc& p : scene.particles) {
        const SpringDesc* spring = springOn(scene, p.id);
        QVERIFY(spring && spring->anchor && spring->restLength);
        const double k = spring->stiffness, m = p.mass;
        const double expected = 2.0 * kPi * std::sqrt(m / k);
        const double yEq = (*spring->anchor)[1] - *spring->restLength - m * g / k;

        auto world = build(scene);
        const int i = particleIndex(*world, p.id);
        QVERIFY(i >= 0);
        std::vector<double> crossings;
        double previous = world->particlePosition(i).y() - yEq, tPrevious = world->time();
        while (world->time() < std::min(scene.simulation.duration, kMaxRun)) {
            QVERIFY(world->step());
            const double now = world->particlePosition(i).y() - yEq;
            if (previous < 0.0 && now >= 0.0)
                crossings.push_back(tPrevious +
                                    (world->time() - tPrevious) * (-previous) / (now - previous));
            previous = now;
            tPrevious = world->time();
        }
        QVERIFY2(crossings.size() >= 3, "too few oscillations to measure");
        const double measured = (crossings.back() - crossings.front()) / (crossings.size() - 1);
        qInfo("%s: m = %g kg, k = %.4g N/m: period %.5f s, 2*pi*sqrt(m/k) = %.5f s (%zu periods)",
              p.id.c_str(), m, k, measured, expected, crossings.size() - 1);
        QVERIFY2(std::abs(measured - expected) < 0.01 * expected,
                 qPrintable(QString::number(measured)));
    }
}

// The three dampers: y − y_eq = A·e^{−γt/2}·(cos ω_d t + γ/(2ω_d)·sin ω_d t) under-damped,
// A·(1 + ωt)·e^{−ωt} critical, A·(r₁e^{r₂t} − r₂e^{r₁t})/(r₁ − r₂) over-damped (γ = c/m,
// ω² = k/m, r₁,₂ = −γ/2 ± √(γ²/4 − ω²)), released at rest from A = rest length − m·g/k above
// y_eq. Run under RK4 at a quarter of the scene's dt, so that the method's error is far below
// the tolerance and what is checked is the scene's physics.
void TestExamples::dampedOscillatorsFollowTheirClosedForms() {
    SceneDesc scene = load(QStringLiteral("damped-oscillators.phasebox.json"));
    scene.simulation.integrator = "rk4";
    scene.simulation.dt /= 4.0;
    const double g = -scene.effects.gravity->g[1];
    auto world = build(scene);
    while (world->time() < 3.0 - 0.5 * scene.simulation.dt) QVERIFY(world->step());
    const double t = world->time();
    for (const ParticleDesc& p : scene.particles) {
        const SpringDesc* spring = springOn(scene, p.id);
        QVERIFY(spring && spring->anchor && spring->restLength);
        const double m = p.mass, gamma = spring->damping / m, w2 = spring->stiffness / m;
        const double yEq = (*spring->anchor)[1] - *spring->restLength - m * g / spring->stiffness;
        const double A = p.position[1] - yEq;
        const double disc = 0.25 * gamma * gamma - w2;
        double offset = 0.0;
        if (std::abs(disc) < 1e-9 * w2) {
            const double w = std::sqrt(w2);
            offset = A * (1.0 + w * t) * std::exp(-w * t);
        } else if (disc < 0.0) {
            const double wd = std::sqrt(-disc);
            offset = A * std::exp(-0.5 * gamma * t) *
                     (std::cos(wd * t) + 0.5 * gamma / wd * std::sin(wd * t));
        } else {
            const double r1 = -0.5 * gamma + std::sqrt(disc), r2 = -0.5 * gamma - std::sqrt(disc);
            offset = A * (r1 * std::exp(r2 * t) - r2 * std::exp(r1 * t)) / (r1 - r2);
        }
        const double y = world->particlePosition(particleIndex(*world, p.id)).y();
        qInfo("%-8s zeta = %.3f: y(%.2f s) = %.6f m, closed form %.6f m", p.id.c_str(),
              0.5 * gamma / std::sqrt(w2), t, y, yEq + offset);
        QVERIFY2(std::abs(y - (yEq + offset)) < 1e-4, qPrintable(QString::number(y)));
    }
}

// The ship on the circular orbit: r = GM/v² stays put and the energy stays flat over one
// period T = 2π·r^{3/2}/√(GM) with RK4, and the comet's ellipse closes.
void TestExamples::orbitStaysCircularUnderRk4() {
    SceneDesc scene = load(QStringLiteral("orbit.phasebox.json"));
    QCOMPARE(scene.simulation.integrator, std::string("rk4"));
    QVERIFY(scene.effects.newtonianGravity &&
            scene.effects.newtonianGravity->attractors.size() == 1);
    const double GM =
        scene.effects.newtonianGravity->G * scene.effects.newtonianGravity->attractors[0].mass;
    auto world = build(scene);
    const int ship = particleIndex(*world, "ship");
    const int comet = particleIndex(*world, "comet");
    QVERIFY(ship >= 0 && comet >= 0);
    const double r0 = world->particlePosition(ship).norm();
    const double v0 = world->particleVelocity(ship).norm();
    QVERIFY2(std::abs(v0 * v0 * r0 / GM - 1.0) < 1e-6, "the ship should start on a circular orbit");
    const double period = 2.0 * kPi * std::pow(r0, 1.5) / std::sqrt(GM);
    const double e0 = world->energy().kinetic + world->energy().potential;

    // The comet's period from its semi-major axis (vis-viva).
    const Eigen::Vector2d cometStart = world->particlePosition(comet);
    const double rc = cometStart.norm(), vc = world->particleVelocity(comet).norm();
    const double a = 1.0 / (2.0 / rc - vc * vc / GM);
    const double cometPeriod = 2.0 * kPi * std::pow(a, 1.5) / std::sqrt(GM);

    double worstRadius = 0.0, worstEnergy = 0.0,
           cometMiss = std::numeric_limits<double>::infinity();
    while (world->time() < std::max(period, cometPeriod) + 0.1) {
        QVERIFY(world->step());
        if (world->time() <= period + 1e-9)
            worstRadius =
                std::max(worstRadius, std::abs(world->particlePosition(ship).norm() / r0 - 1.0));
        worstEnergy = std::max(worstEnergy, std::abs(world->energy().drift / e0));
        if (std::abs(world->time() - cometPeriod) < 0.5 * scene.simulation.dt)
            cometMiss = (world->particlePosition(comet) - cometStart).norm();
    }
    qInfo(
        "rk4: ship radius within %.2e of r0 over one period (%.3f s), relative energy drift %.2e, "
        "comet back within %.2e m of its start after its period %.3f s",
        worstRadius, period, worstEnergy, cometMiss, cometPeriod);
    QVERIFY(worstRadius < 0.01);
    QVERIFY(worstEnergy < 0.01);
    QVERIFY(cometMiss < 0.02 * a);
}

// Explicit Euler gains energy (ΔE ≈ ½h²·(|a|² + vᵀ·∇²U·v) per step, > 0 on the circle): the
// drift is clearly positive after one period and larger after two, and the ship's orbit has
// visibly spiralled out.
void TestExamples::orbitGainsEnergyUnderExplicitEuler() {
    SceneDesc scene = load(QStringLiteral("orbit.phasebox.json"));
    scene.simulation.integrator = "explicit_euler";
    auto world = build(scene);
    const int ship = particleIndex(*world, "ship");
    const double r0 = world->particlePosition(ship).norm();
    const double GM =
        scene.effects.newtonianGravity->G * scene.effects.newtonianGravity->attractors[0].mass;
    const double period = 2.0 * kPi * std::pow(r0, 1.5) / std::sqrt(GM);
    const double e0 = world->energy().kinetic + world->energy().potential;
    QVERIFY(runTo(*world, period));
    const double drift1 = world->energy().drift;
    const double r1 = world->particlePosition(ship).norm();
    QVERIFY(runTo(*world, 2.0 * period));
    const double drift2 = world->energy().drift;
    const double r2 = world->particlePosition(ship).norm();
    qInfo(
        "explicit Euler: drift %.4f J after one period, %.4f J after two (|E0| = %.3f J); ship "
        "radius %.3f -> %.3f -> %.3f m",
        drift1, drift2, std::abs(e0), r0, r1, r2);
    QVERIFY(drift1 > 0.01 * std::abs(e0));
    QVERIFY(drift2 > drift1 + 0.01 * std::abs(e0));
    QVERIFY(r1 > 1.02 * r0);
    QVERIFY(r2 > r1);
}

// ω·h = √(1e5)/60 ≈ 5.3 is past symplectic Euler's limit of 2: the world catches the blow-up
// within a few frames, says where, and keeps the last good (finite) state.
void TestExamples::stiffSpringDivergesUnderSymplecticEuler() {
    SceneDesc scene = load(QStringLiteral("stiff-spring-blowup.phasebox.json"));
    QCOMPARE(scene.simulation.integrator, std::string("implicit_euler"));
    QCOMPARE(scene.simulation.dt, 1.0 / 60.0);
    QVERIFY(scene.springs.size() == 1 && scene.springs[0].stiffness >= 1e5);
    scene.simulation.integrator = "symplectic_euler";
    auto world = build(scene);
    bool diverged = false;
    for (int n = 0; n < 120 && !diverged; ++n) diverged = !world->step();
    QVERIFY2(diverged, "symplectic Euler should blow up within 2 s");
    QVERIFY(world->divergence().has_value());
    qInfo("symplectic Euler: %s", world->divergence()->message().c_str());
    QCOMPARE(world->divergence()->objectId, std::string("ball"));
    QVERIFY(world->divergence()->time < 1.0);
    QVERIFY(world->positions().allFinite() && world->velocities().allFinite());
}

// Backward Euler never gains energy on this convex problem; the ball stays on its spring.
void TestExamples::stiffSpringStaysBoundedUnderImplicitEuler() {
    const SceneDesc scene = load(QStringLiteral("stiff-spring-blowup.phasebox.json"));
    auto world = build(scene);
    const SpringDesc& spring = scene.springs[0];
    const Eigen::Vector2d anchor((*spring.anchor)[0], (*spring.anchor)[1]);
    const double e0 = world->energy().kinetic + world->energy().potential;
    double highest = e0, longest = 0.0;
    while (world->time() < scene.simulation.duration - 0.5 * scene.simulation.dt) {
        QVERIFY(world->step());
        QVERIFY(stateIsFinite(*world));
        highest = std::max(highest, world->energy().kinetic + world->energy().potential);
        longest = std::max(longest, (world->particlePosition(0) - anchor).norm());
    }
    qInfo(
        "implicit Euler: energy %.4f J at the start, at most %.4f J, %.4f J after %.0f s; longest "
        "spring %.4f m (rest %.2f m)",
        e0, highest, world->energy().kinetic + world->energy().potential, world->time(), longest,
        *spring.restLength);
    QVERIFY(highest <= e0 + 1e-9 * std::abs(e0) + 1e-9);
    QVERIFY(longest < *spring.restLength * 1.01);
}

// Each dynamic box rests on a static ramp of the same slope θ; with μ = √(μ_box·μ_ramp) it
// sticks when tan θ < μ and otherwise slides with a = g·(sin θ − μ·cos θ).
void TestExamples::boxesOnTheInclineStickOrSlideAsTanThetaPredicts() {
    const SceneDesc scene = load(QStringLiteral("box-incline.phasebox.json"));
    const double g = -scene.effects.gravity->g[1];
    int sticking = 0, sliding = 0;
    for (const BoxDesc& box : scene.boxes) {
        if (box.isStatic) continue;
        // Its ramp: the nearest static box.
        const BoxDesc* ramp = nullptr;
        double nearest = std::numeric_limits<double>::infinity();
        for (const BoxDesc& r : scene.boxes) {
            const double d =
                std::hypot(r.position[0] - box.position[0], r.position[1] - box.position[1]);
            if (r.isStatic && d < nearest) nearest = d, ramp = &r;
        }
        QVERIFY(ramp != nullptr);
        QCOMPARE(box.angle, ramp->angle);
        const double theta = std::abs(ramp->angle);
        const double mu = std::sqrt(box.friction * ramp->friction);
        const bool sticks = std::tan(theta) < mu;
        QVERIFY2(std::abs(std::tan(theta) - mu) > 0.1,
                 "too close to the threshold for a clear lesson");
        // Downhill unit vector along the ramp.
        Eigen::Vector2d down(std::cos(ramp->angle), std::sin(ramp->angle));
        if (down.y() > 0.0) down = -down;

        auto world = build(scene);
        const int i = boxIndex(*world, box.id);
        QVERIFY(runTo(*world, 0.25));  // let the contact settle
        const double s0 = world->bodyPosition(i).dot(down), v0 = world->bodyVelocity(i).dot(down);
        const double t = 1.5;
        QVERIFY(runTo(*world, 0.25 + t));
        const double s1 = world->bodyPosition(i).dot(down);
        const double measured = 2.0 * (s1 - s0 - v0 * t) / (t * t);
        const double expected = sticks ? 0.0 : g * (std::sin(theta) - mu * std::cos(theta));
        qInfo(
            "%s: theta = %.1f deg, tan = %.3f, mu = %.2f -> %s; moved %.4f m, a = %.4f m/s^2 "
            "(expected %.4f)",
            box.id.c_str(), theta * 180.0 / kPi, std::tan(theta), mu, sticks ? "sticks" : "slides",
            s1 - s0, measured, expected);
        if (sticks) {
            ++sticking;
            QVERIFY(std::abs(s1 - s0) < 0.005);
            QVERIFY(std::abs(world->bodyAngle(i) - box.angle) < 0.01);
        } else {
            ++sliding;
            QVERIFY(std::abs(measured - expected) < 0.03 * expected);
        }
    }
    QVERIFY2(sticking >= 1 && sliding >= 1, "the scene should show both cases");
}

// With restitution 1 and no friction every contact impulse is elastic, so the kinetic energy
// is constant up to the solver's error. The soft contact's push-out leaves no velocity behind,
// and pairs are resolved one at a time, so the only loss would come from disks in simultaneous
// contact; measured it is at round-off (~1e-13). 1e-6 of the energy is far below anything a
// student could see in the plot (a line width is ~1e-3) and still catches any real leak.
void TestExamples::elasticGasKeepsItsKineticEnergy() {
    const SceneDesc scene = load(QStringLiteral("elastic-gas.phasebox.json"));
    QVERIFY(!scene.effects.gravity && !scene.effects.drag);
    QVERIFY(scene.effects.particleCollisions &&
            scene.effects.particleCollisions->restitution == 1.0);
    QVERIFY(scene.particles.size() >= 150);
    auto world = build(scene);
    const double k0 = world->energy().kinetic;
    double worst = 0.0;
    while (world->time() <
           std::min(scene.simulation.duration, kMaxRun) - 0.5 * scene.simulation.dt) {
        QVERIFY(world->step());
        worst = std::max(worst, std::abs(world->energy().kinetic / k0 - 1.0));
    }
    // And the disks did collide: the speeds are no longer all equal.
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (int i = 0; i < static_cast<int>(world->particles().size()); ++i) {
        if (world->particles()[i].mass != 1.0) continue;
        lo = std::min(lo, world->particleVelocity(i).norm());
        hi = std::max(hi, world->particleVelocity(i).norm());
    }
    qInfo(
        "elastic gas: kinetic energy %.4f J, largest relative change %.2e over %.0f s; speeds "
        "now from %.3f to %.3f m/s",
        k0, worst, world->time(), lo, hi);
    QVERIFY(worst < 1e-6);
    QVERIFY(hi - lo > 1.0);
}

// Each node of the flag feels m·g down and b·(w − v) from the wind; at rest the net force
// points at tan α = m·g / (b·w) below the horizontal, and with no shear springs the flag's
// top edge lines up with it.
void TestExamples::flagSettlesAtTheWindAngle() {
    const SceneDesc scene = load(QStringLiteral("cloth-flag.phasebox.json"));
    QVERIFY(scene.cloths.size() == 1 && scene.effects.wind && scene.effects.gravity);
    const ClothDesc& cloth = scene.cloths[0];
    const double nodeMass = cloth.mass / (cloth.resolution[0] * cloth.resolution[1]);
    const double g = -scene.effects.gravity->g[1];
    const double w = scene.effects.wind->velocity[0];
    QCOMPARE(scene.effects.wind->velocity[1], 0.0);
    const double expected = std::atan(nodeMass * g / (scene.effects.wind->drag * w));
    auto world = build(scene);
    QVERIFY(runTo(*world, std::min(scene.simulation.duration, kMaxRun)));
    const Cloth& c = world->cloths()[0];
    const Eigen::Vector2d edge = world->particlePosition(clothNode(c, c.nx - 1, 0)) -
                                 world->particlePosition(clothNode(c, 0, 0));
    const double measured = std::atan2(-edge.y(), edge.x());
    qInfo("flag: top edge %.2f deg below level, tan a = m g/(b w) gives %.2f deg",
          measured * 180.0 / kPi, expected * 180.0 / kPi);
    QVERIFY(std::abs(measured - expected) < 1.0 * kPi / 180.0);
}

// A ball dropped from h rebounds to e²·h (the floor has restitution 0, so the pair's e is the
// ball's own).
void TestExamples::bouncingBallsReboundToESquaredH() {
    const SceneDesc scene = load(QStringLiteral("bouncing-balls.phasebox.json"));
    QVERIFY(scene.planes.size() == 1 && scene.planes[0].restitution == 0.0);
    auto world = build(scene);
    const int n = static_cast<int>(world->particles().size());
    std::vector<double> drop(n), top(n, -1.0);
    std::vector<bool> bounced(n, false), done(n, false);
    for (int i = 0; i < n; ++i)
        drop[i] = world->particlePosition(i).y() - world->particles()[i].radius;
    while (world->time() < scene.simulation.duration - 0.5 * scene.simulation.dt) {
        QVERIFY(world->step());
        for (int i = 0; i < n; ++i) {
            const double vy = world->particleVelocity(i).y();
            const double height = world->particlePosition(i).y() - world->particles()[i].radius;
            if (done[i]) continue;
            if (vy > 0.0) bounced[i] = true;
            if (bounced[i]) top[i] = std::max(top[i], height);
            if (bounced[i] && vy < 0.0) done[i] = true;
        }
    }
    for (int i = 0; i < n; ++i) {
        const double e = scene.particles[i].restitution;
        const double expected = e * e * drop[i];
        qInfo("%s: e = %.2f, dropped from %.2f m, rebounds to %.4f m (e^2 h = %.4f m)",
              world->particles()[i].id.c_str(), e, drop[i], top[i], expected);
        QVERIFY(done[i]);
        QVERIFY(std::abs(top[i] - expected) < 0.02 * drop[i]);
    }
}

void TestExamples::jointedExamplesHoldAndDoWhatTheySay_data() {
    QTest::addColumn<QString>("file");
    for (const char* name : {"chain-bridge", "ragdoll", "car"})
        QTest::newRow(name) << QString::fromLatin1(name) + QStringLiteral(".phasebox.json");
}

// The joint examples (issue 17) at dt 1/60 with the method each names (velocity Verlet for the
// car and the ragdoll, RK4 for the bridge: under symplectic Euler a body resting on a contact
// books SE's O(h) energy error as drift and its return as correction, far past the 5% that
// everyExampleRunsStably allows): every joint holds within 1 mm and
// 0.001 rad (hinge limits) at the end of every step over 10 s, and each scene does what its
// description says: the crate comes to rest on the bridge between the pillars, the ragdoll comes
// to rest at the foot of the stairs, stopped by the wall, from nudged starts as well, and the motor
// car climbs the ramp onto the plateau.
void TestExamples::jointedExamplesHoldAndDoWhatTheySay() {
    QFETCH(QString, file);
    const SceneDesc scene = load(file);
    QCOMPARE(scene.simulation.dt, 1.0 / 60.0);
    QVERIFY(!scene.joints.empty());
    auto world = build(scene);
    double position = 0.0, angle = 0.0;
    while (world->time() < kMaxRun - 0.5 * scene.simulation.dt) {
        QVERIFY2(world->step(),
                 world->divergence() ? world->divergence()->message().c_str() : "step failed");
        position = std::max(position, world->jointErrors().position);
        angle = std::max(angle, world->jointErrors().angle);
    }
    qInfo(
        "%s: joint error at most %.2e m, %.2e rad over %.0f s; energy drift %.4g J, "
        "correction %.4g J, work_nc %.4g J",
        qPrintable(file), position, angle, world->time(), world->energy().drift,
        world->energy().correction, world->energy().workNc);
    QVERIFY(position < 1e-3);
    QVERIFY(angle < 1e-3);
    if (file.startsWith(QLatin1String("chain-bridge"))) {
        const Vec2 crate = world->bodyPosition(boxIndex(*world, "crate"));
        const double pillar = world->bodyPosition(boxIndex(*world, "right_pillar")).x();
        qInfo("crate at (%.3f, %.3f) m, speed %.3f m/s", crate.x(), crate.y(),
              world->bodyVelocity(boxIndex(*world, "crate")).norm());
        QVERIFY(std::abs(crate.x()) < pillar - 0.5);
        QVERIFY(crate.y() > 2.0 && crate.y() < 3.0);  // on the bridge, which hangs at 2.4-3 m
    } else if (file.startsWith(QLatin1String("ragdoll"))) {
        // Where it lands is chaotic (a nanometre's nudge changes the tumble), so the scene
        // must end alike from nudged starts too: the run above and four nudged ones.
        for (const double nudge : {0.0, 1e-9, -1e-9, 1e-6, -1e-6}) {
            SceneDesc nudged = scene;
            for (BoxDesc& box : nudged.boxes)
                if (box.id == "torso") box.position[0] += nudge;
            auto run = nudge == 0.0 ? std::move(world) : build(nudged);
            while (run->time() < kMaxRun - 0.5 * scene.simulation.dt) QVERIFY(run->step());
            double right = -1e9, low = 1e9;
            for (int i = 0; i < static_cast<int>(run->rigidBodies().size()); ++i) {
                if (run->rigidBodies()[i].isStatic) continue;
                right = std::max(right, run->bodyPosition(i).x());
                low = std::min(low, run->bodyPosition(i).y());
            }
            const int wall = boxIndex(*run, "wall");
            QVERIFY(wall >= 0);
            const double face =
                run->bodyPosition(wall).x() - 0.5 * run->rigidBodies()[wall].size.x();
            qInfo(
                "torso nudged %g m: parts at x <= %.3f m (wall face %.2f m), y >= %.3f m, "
                "kinetic %.3g J",
                nudge, right, face, low, run->energy().kinetic);
            // Between the stairs and the wall, above the floor. Not asserted: that it lies
            // still. Lying limbs are pushed out of the floor over and over (a known fault of
            // the contact-joint coupling, booked as correction), and some nudged runs still
            // stir at 10 s.
            QVERIFY(right < face && low > 0.0);
        }
    } else {
        const int chassis = boxIndex(*world, "chassis");
        const Vec2 at = world->bodyPosition(chassis);
        qInfo("car at (%.3f, %.3f) m, %.3f m/s, tilted %.3f rad", at.x(), at.y(),
              world->bodyVelocity(chassis).x(), world->bodyAngle(chassis));
        QVERIFY(at.y() > 1.3 && at.x() > 2.5 && at.x() < 6.0);  // on the 1 m plateau
        QVERIFY(std::abs(world->bodyAngle(chassis)) < 0.1);
        QVERIFY(world->energy().workNc > 0.0);  // the motors put work in
    }
}

// The ragdoll example pushed off the top of its stairs at 16 speeds from 0.8 to 1.2 times its
// own 2 m/s, under its own method (velocity Verlet), 10 s each: the solver may not make more
// energy than the examples' 5% of the scene's own (everyExampleRunsStably's bound), in any of
// them. A contact force held over the method's step at a point that step had opened (a forearm
// pushed off a stair by the held force, pulled back by the joints, caught by a larger force,
// held again) grew geometrically: 7 of these 16 falls booked 60 to 2,221 J of correction and
// 4 were launched (docs/robustness.md). A point left open holds no force now (refreshHeld).
void TestExamples::ragdollPushedAtAnySpeedKeepsItsBooks() {
    const SceneDesc scene = load(QStringLiteral("ragdoll.phasebox.json"));
    QCOMPARE(scene.simulation.integrator, std::string("velocity_verlet"));
    constexpr int kPushes = 16;
    int within = 0;
    double worst = 0.0;
    for (int k = 0; k < kPushes; ++k) {
        const double scale = 0.8 + 0.4 * k / (kPushes - 1);
        SceneDesc pushed = scene;
        for (BoxDesc& box : pushed.boxes)
            box.velocity = {scale * box.velocity[0], scale * box.velocity[1]};
        auto world = build(pushed);
        double most = 0.0;
        while (world->time() < kMaxRun - 0.5 * scene.simulation.dt) {
            QVERIFY(world->step());
            most = std::max(most, std::abs(world->energy().correction));
        }
        const double bound = 0.05 * world->energy().initial;
        worst = std::max(worst, most / bound);
        within += most <= bound;
        qInfo("pushed at %.3f m/s: |correction| at most %.3g J (bound %.3g J)", 2.0 * scale, most,
              bound);
    }
    qInfo("%d of %d pushes within the bound; the worst at %.2f of it", within, kPushes, worst);
    QCOMPARE(within, kPushes);
}

QTEST_GUILESS_MAIN(TestExamples)
#include "tst_examples.moc"
