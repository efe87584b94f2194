// The effects of issue #7 against their closed forms: bodies afloat (a box's equilibrium depth
// is ρ_box/ρ_fluid of its height, a flat raft rights itself, a square log of half the fluid's
// density floats corner-down at 45°, a disk floats at its circular segment's depth, a sinking
// ball reaches (m − ρ·A)·g/b_f), the lift is the gradient of its potential and its Jacobians are
// its derivatives, Coulomb's law (repulsion to the speed energy conservation gives, a circular
// orbit round a fixed charge), the period of a circular orbit, and a flock that neither
// scatters nor collapses. (Terminal velocity with linear and quadratic air drag is checked in
// tst_drag_damping; Barnes–Hut's error in tst_barnes_hut.)

#include "PhysicsTestSupport.h"

#include "physics/effects/BuoyancyEffect.h"
#include "physics/effects/FlockingEffect.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

constexpr double kG = 9.81;
constexpr double kWater = 1000.0;

// A box of this size and density relative to the water, its centre 0.1 m above the surface, under
// gravity and buoyancy (surface y = 0). The fluid drag damps every motion at the rate `rate`
// once afloat: b_f·φ/m = rate when the submerged fraction φ equals the relative density.
SceneDesc floatingBox(Point2 size, double relativeDensity, double angle, double rate) {
    SceneDesc scene;
    scene.simulation = simulation("rk4", 1.0 / 120.0);
    scene.effects.gravity = GravityDesc{{0.0, -kG}};
    scene.effects.buoyancy = BuoyancyDesc{kWater, 0.0, rate * kWater * size[0] * size[1]};
    BoxDesc b;
    b.id = "raft";
    b.size = size;
    b.density = relativeDensity * kWater;
    b.angle = angle;
    b.position = {0.0, 0.1};
    scene.boxes.push_back(b);
    return scene;
}

// A disk of radius r and this relative density, centre at the surface.
SceneDesc floatingDisk(double radius, double relativeDensity, double drag) {
    SceneDesc scene;
    scene.simulation = simulation("rk4", 1.0 / 120.0);
    scene.effects.gravity = GravityDesc{{0.0, -kG}};
    scene.effects.buoyancy = BuoyancyDesc{kWater, 0.0, drag};
    ParticleDesc p;
    p.id = "buoy";
    p.radius = radius;
    p.mass = relativeDensity * kWater * kPi * radius * radius;
    scene.particles.push_back(p);
    return scene;
}

bool runFor(World& world, double seconds) {
    const int steps = static_cast<int>(std::lround(seconds / world.settings().dt));
    for (int n = 0; n < steps; ++n)
        if (!world.step()) return false;
    return true;
}

// The angle folded into [0, π/2): a square looks the same every quarter turn.
double quarterTurn(double angle) {
    const double q = kPi / 2.0;
    return angle - q * std::floor(angle / q);
}

}  // namespace

class TestEffectsClosedForm : public QObject {
    Q_OBJECT

private slots:
    void submergedGeometry();
    void floatingBoxSinksToDensityRatio_data();
    void floatingBoxSinksToDensityRatio();
    void tiltedRaftRightsItself();
    void squareLogFloatsCornerDown();
    void diskFloatsAtSegmentDepth_data();
    void diskFloatsAtSegmentDepth();
    void sinkingBallReachesTerminalVelocity();
    void liftIsMinusPotentialGradientAndJacobiansMatch();
    void buoyancyKeepsEnergyWithoutDrag();
    void likeChargesRepelToTheEnergySpeed();
    void oppositeChargeOrbitsAFixedCharge();
    void circularOrbitPeriodIsTwoPiRootR3OverGM();
    void flockStaysTogetherAndDoesNotCollapse();
};

// The clipped polygon and the segment formula against areas and centroids known by hand.
void TestEffectsClosedForm::submergedGeometry() {
    const Vec2 half(1.0, 0.25);                                      // a 2 × 0.5 box
    SubmergedPart p = BuoyancyEffect::submergedBox(half, 0.0, 0.1);  // 0.35 of 0.5 under
    QVERIFY(std::abs(p.area - 2.0 * 0.35) < 1e-14);
    QVERIFY(std::abs(p.centroid.y() - (-0.25 + 0.175)) < 1e-14 && std::abs(p.centroid.x()) < 1e-14);
    QVERIFY(std::abs(p.waterlineLength() - 2.0) < 1e-14);
    // Dry, and fully under.
    QCOMPARE(BuoyancyEffect::submergedBox(half, 0.3, -2.0).area, 0.0);
    p = BuoyancyEffect::submergedBox(half, 0.3, 2.0);
    QCOMPARE(p.area, 1.0);
    QCOMPARE(p.waterlineLength(), 0.0);
    // A unit square at 45° cut through its centre: the lower triangle of area ½, legs √2/2,
    // centroid a third of the way up from the corner at −√2/2, waterline the diagonal √2.
    p = BuoyancyEffect::submergedBox({0.5, 0.5}, kPi / 4.0, 0.0);
    QVERIFY(std::abs(p.area - 0.5) < 1e-14);
    QVERIFY(std::abs(p.centroid.y() + std::sqrt(2.0) / 6.0) < 1e-14);
    QVERIFY(std::abs(p.waterlineLength() - std::sqrt(2.0)) < 1e-14);
    // The same square turned by a generic angle: whatever the angle, the part below a line
    // through the centre is half the square and the centroids of both halves balance.
    p = BuoyancyEffect::submergedBox({0.5, 0.5}, 0.37, 0.0);
    QVERIFY(std::abs(p.area - 0.5) < 1e-14);
    // Half a disk: area πr²/2, centroid 4r/(3π) below the centre; a quarter-depth disk's area
    // is r²·(π/2 + asin c + c·√(1 − c²)) with c = −½.
    const double r = 0.3;
    p = BuoyancyEffect::submergedDisk(r, 0.0);
    QVERIFY(std::abs(p.area - kPi * r * r / 2.0) < 1e-15);
    QVERIFY(std::abs(p.centroid.y() + 4.0 * r / (3.0 * kPi)) < 1e-15);
    QVERIFY(std::abs(p.waterlineLength() - 2.0 * r) < 1e-15);
    p = BuoyancyEffect::submergedDisk(r, -0.5 * r);
    QVERIFY(std::abs(p.area - r * r * (kPi / 3.0 - std::sqrt(3.0) / 4.0)) < 1e-15);
    QCOMPARE(BuoyancyEffect::submergedDisk(0.0, 1.0).area, 0.0);  // a point displaces nothing
}

void TestEffectsClosedForm::floatingBoxSinksToDensityRatio_data() {
    QTest::addColumn<double>("ratio");
    QTest::newRow("quarter") << 0.25;
    QTest::newRow("half") << 0.5;
    QTest::newRow("three quarters") << 0.75;
}

// Archimedes: at rest the displaced water weighs what the box weighs, ρ_f·w·d = ρ_b·w·h, so
// the box floats with d = (ρ_b/ρ_f)·h of its height under water.
void TestEffectsClosedForm::floatingBoxSinksToDensityRatio() {
    QFETCH(double, ratio);
    const double h = 0.5;
    auto world = build(floatingBox({2.0, h}, ratio, 0.0, 4.0));
    QVERIFY(runFor(*world, 15.0));
    const double depth = h / 2.0 - world->bodyPosition(0).y();  // surface − bottom
    qInfo("ρ_b/ρ_f = %.2f: depth %.9f m, Archimedes %.9f m", ratio, depth, ratio * h);
    QVERIFY2(std::abs(depth - ratio * h) <= 1e-6 * h, qPrintable(QString::number(depth, 'g', 12)));
    QVERIFY(std::abs(world->bodyAngle(0)) < 1e-12);  // an upright box is never turned
    // The water's drag took the bobbing energy: work_nc < 0 and the drift is rk4's alone.
    QVERIFY(world->energy().workNc < 0.0);
    QVERIFY(world->energy().maxAbsDrift <= 1e-6 * std::abs(world->energy().workNc));
}

// A wide raft (2 × 0.5 m, half the water's density) is stable upright: its metacentre lies
// w²/(12·d) = 1.33 m above the centre of buoyancy, far above its centre of mass. Released at
// 20°, the lift at the centroid of the submerged part turns it back to level.
void TestEffectsClosedForm::tiltedRaftRightsItself() {
    auto world = build(floatingBox({2.0, 0.5}, 0.5, 20.0 * kPi / 180.0, 4.0));
    double minAngle = 1.0;
    for (int n = 0; n < 20 * 120; ++n) {
        QVERIFY(world->step());
        minAngle = std::min(minAngle, world->bodyAngle(0));
    }
    qInfo("raft: angle after 20 s %.3e rad (overshoot to %.3f rad), depth %.6f m",
          world->bodyAngle(0), minAngle, 0.25 - world->bodyPosition(0).y());
    QVERIFY(std::abs(world->bodyAngle(0)) < 1e-4);
    QVERIFY(std::abs(world->bodyPosition(0).y()) < 1e-4);  // half of the 0.5 m under: centre at 0
    QVERIFY(minAngle > -0.35);  // it came back, and did not flip the other way
}

// A square log of half the water's density is unstable upright (metacentre 1/6 m above the
// centre of buoyancy, below the centre of mass at 1/4 m) and stable corner-down: at 45° the
// waterline is the diagonal √2, the metacentric height √2/3 − √2/6 = 0.236 m > 0. Nudged by
// 0.2 rad off upright, it turns until a diagonal is vertical.
void TestEffectsClosedForm::squareLogFloatsCornerDown() {
    auto world = build(floatingBox({1.0, 1.0}, 0.5, 0.2, 4.0));
    QVERIFY(runFor(*world, 30.0));
    const double folded = quarterTurn(world->bodyAngle(0));
    qInfo("square log: angle %.6f rad (mod π/2), 45° = %.6f", folded, kPi / 4.0);
    QVERIFY(std::abs(folded - kPi / 4.0) < 1e-4);
    // At 45° the half-submerged square's centre sits exactly at the surface.
    QVERIFY(std::abs(world->bodyPosition(0).y()) < 1e-4);
}

void TestEffectsClosedForm::diskFloatsAtSegmentDepth_data() {
    QTest::addColumn<double>("ratio");
    QTest::newRow("0.3") << 0.3;
    QTest::newRow("0.8") << 0.8;
}

// A disk floats where the circular segment under water has the area m/ρ_f: c solves
// π/2 + asin c + c·√(1 − c²) = π·ρ_disk/ρ_f, the centre then c·r below the surface.
void TestEffectsClosedForm::diskFloatsAtSegmentDepth() {
    QFETCH(double, ratio);
    const double r = 0.5;
    // b_f = 4·ρ_f·π·r² damps the bobbing at b_f·φ/m = 4/s once afloat (φ = ρ_disk/ρ_f).
    auto world = build(floatingDisk(r, ratio, 4.0 * kWater * kPi * r * r));
    QVERIFY(runFor(*world, 15.0));
    double lo = -1.0, hi = 1.0;  // bisection: the segment grows with c
    for (int i = 0; i < 200; ++i) {
        const double c = 0.5 * (lo + hi);
        (kPi / 2.0 + std::asin(c) + c * std::sqrt(1.0 - c * c) < kPi * ratio ? lo : hi) = c;
    }
    const double expected = -0.5 * (lo + hi) * r;
    qInfo("disk ρ/ρ_f = %.1f: centre at %.9f m, segment depth %.9f m", ratio,
          world->particlePosition(0).y(), expected);
    QVERIFY(std::abs(world->particlePosition(0).y() - expected) < 1e-7);
}

// A ball three times as dense as the water, under water from rest: m·v' = −(m − ρ_f·A)·g − b_f·v,
// so v(t) = −v_t·(1 − e^{−t/τ}) with v_t = (m − ρ_f·A)·g/b_f and τ = m/b_f (linear drag, and
// the buoyancy that makes the closed form differ from tst_drag_damping's).
void TestEffectsClosedForm::sinkingBallReachesTerminalVelocity() {
    const double r = 0.1, area = kPi * r * r, m = 3.0 * kWater * area, b = 100.0;
    SceneDesc scene = floatingDisk(r, 3.0, b);
    scene.particles[0].position = {0.0, -1.0};
    auto world = build(scene);
    const double vt = (m - kWater * area) * kG / b, tau = m / b;
    double worst = 0.0;
    for (int n = 0; n < 15 * 120; ++n) {
        QVERIFY(world->step());
        const double exact = -vt * (1.0 - std::exp(-world->time() / tau));
        worst = std::max(worst, std::abs(world->particleVelocity(0).y() - exact));
    }
    qInfo("sinking ball: v = %.9f m/s, v_t = %.9f m/s, worst |Δv| %.2e",
          world->particleVelocity(0).y(), -vt, worst);
    QVERIFY(worst <= 1e-9 * vt);
    QVERIFY(std::abs(world->particleVelocity(0).y() + vt) <= 1e-6 * vt);
}

// The lift is −∇U (force and torque) and K, D are the derivatives of the forces, for a tilted
// box and a disk both cutting the surface, and two charges.
void TestEffectsClosedForm::liftIsMinusPotentialGradientAndJacobiansMatch() {
    SceneDesc scene = floatingBox({2.0, 0.5}, 0.5, 0.4, 4.0);
    scene.boxes[0].position = {0.3, 0.05};
    ParticleDesc disk;
    disk.position = {3.0, 0.1};
    disk.radius = 0.4;
    disk.mass = 200.0;
    disk.charge = 2e-5;
    ParticleDesc charge;
    charge.position = {3.5, 1.2};
    charge.radius = 0.0;
    charge.charge = -1e-5;
    scene.particles = {disk, charge};
    auto world = build(scene);
    QVERIFY(world->findEffect("coulomb") != nullptr);
    const Eigen::VectorXd q = world->positions();
    const int n = static_cast<int>(q.size());
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n), force(n), fp(n), fm(n);
    world->forces(0.0, q, u, force);
    const double delta = 1e-6;
    for (int j = 0; j < n; ++j) {
        Eigen::VectorXd qp = q, qm = q;
        qp[j] += delta;
        qm[j] -= delta;
        world->setState(qp, u);
        const double up = world->potentialEnergy();
        world->setState(qm, u);
        const double gradient = (up - world->potentialEnergy()) / (2.0 * delta);
        QVERIFY2(
            std::abs(force[j] + gradient) <= 1e-6 * (1.0 + std::abs(force[j])),
            qPrintable(QString("dof %1: force %2, −dU/dq %3").arg(j).arg(force[j]).arg(-gradient)));
    }
    world->setState(q, u);
    u << 0.3, -0.2, 0.1, 0.5, -0.4, 0.7, 0.25;  // drag needs a velocity to act on
    ForceJacobians jac;
    world->forcesAndJacobians(0.0, q, u, force, jac);
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), D = Eigen::MatrixXd::Zero(n, n);
    for (const Triplet& t : jac.stiffnessTriplets()) K(t.row(), t.col()) += t.value();
    for (const Triplet& t : jac.dampingTriplets()) D(t.row(), t.col()) += t.value();
    Eigen::MatrixXd numK(n, n), numD(n, n);
    for (int j = 0; j < n; ++j) {
        Eigen::VectorXd qp = q, qm = q, vp = u, vm = u;
        qp[j] += delta;
        qm[j] -= delta;
        // The drag's dependence on the submerged fraction is left out of K (see the header), so
        // K is compared at rest and D with the position fixed.
        const Eigen::VectorXd rest = Eigen::VectorXd::Zero(n);
        world->forces(0.0, qp, rest, fp);
        world->forces(0.0, qm, rest, fm);
        numK.col(j) = (fp - fm) / (2.0 * delta);
        vp[j] += delta;
        vm[j] -= delta;
        world->forces(0.0, q, vp, fp);
        world->forces(0.0, q, vm, fm);
        numD.col(j) = (fp - fm) / (2.0 * delta);
    }
    const double dk = (K - numK).lpNorm<Eigen::Infinity>(),
                 dd = (D - numD).lpNorm<Eigen::Infinity>();
    QVERIFY2(dk <= 1e-6 * numK.lpNorm<Eigen::Infinity>(),
             qPrintable(QString("|K − ∂F/∂q| = %1").arg(dk)));
    QVERIFY2(dd <= 1e-6 * numD.lpNorm<Eigen::Infinity>(),
             qPrintable(QString("|D − ∂F/∂u| = %1").arg(dd)));
    QVERIFY(std::abs(numK(1, 2)) > 1.0);  // the lift does depend on the tilt
}

// Without drag the lift is conservative, so a raft rocking and bobbing keeps kinetic +
// gravity + buoyancy potential: the drift is rk4's error, which falls ~16× per halved step
// away from the kinks where a corner crosses the surface.
void TestEffectsClosedForm::buoyancyKeepsEnergyWithoutDrag() {
    std::vector<double> drift;
    for (double dt : {1.0 / 120.0, 1.0 / 240.0}) {
        SceneDesc scene = floatingBox({2.0, 0.5}, 0.5, 0.3, 0.0);
        scene.simulation.dt = dt;
        auto world = build(scene);
        QVERIFY(runFor(*world, 10.0));
        QCOMPARE(world->energy().workNc, 0.0);
        drift.push_back(world->energy().maxAbsDrift);
    }
    // The energy in play: the raft starts 0.25 m too high and 0.3 rad off level.
    SceneDesc scene = floatingBox({2.0, 0.5}, 0.5, 0.3, 0.0);
    const double swing = build(scene)->energy().potential;
    qInfo("rocking raft: max |drift| %.3e (dt 1/120), %.3e (dt 1/240) of %.3e J", drift[0],
          drift[1], swing);
    QVERIFY(drift[0] <= 1e-5 * std::abs(swing));
    QVERIFY(drift[1] < drift[0] / 4.0);
}

// Two like charges q released at rest d₀ apart fly apart; energy conservation gives each the
// speed v(d) = √(k·q²·(1/d₀ − 1/d)/m) when they are d apart.
void TestEffectsClosedForm::likeChargesRepelToTheEnergySpeed() {
    const double q = 1e-5, m = 1.0, d0 = 0.1, k = 8.9875517923e9;
    const double escape = std::sqrt(k * q * q / (m * d0));  // the speed when far apart
    SceneDesc scene;
    scene.simulation = simulation("rk4", 1e-3);
    for (double x : {-d0 / 2.0, d0 / 2.0}) {
        ParticleDesc p;
        p.position = {x, 0.0};
        p.radius = 0.0;
        p.mass = m;
        p.charge = q;
        scene.particles.push_back(p);
    }
    auto world = build(scene);
    QCOMPARE(world->energy().potential, k * q * q / d0);
    double worst = 0.0;
    for (int n = 0; n < 2000; ++n) {
        QVERIFY(world->step());
        const double d = world->particlePosition(1).x() - world->particlePosition(0).x();
        const double exact = std::sqrt(k * q * q * (1.0 / d0 - 1.0 / d) / m);
        worst = std::max(worst, std::abs(world->particleVelocity(1).x() - exact) / escape);
        QCOMPARE(world->particleVelocity(0).x(), -world->particleVelocity(1).x());
    }
    qInfo("like charges: %.3f m apart at %.6f m/s, worst error %.2e of the escape speed",
          world->particlePosition(1).x() - world->particlePosition(0).x(),
          world->particleVelocity(1).x(), worst);
    // rk4 at h = τ/33, τ = √(m·d₀³/(k·q²)) the time scale of the first push: ~1e-8.
    QVERIFY(worst < 5e-8);
}

// A charge −q of mass m round a pinned charge +q at radius r: k·q²/r² = m·v²/r, so
// v = √(k·q²/(m·r)) and the period is 2π·r/v.
void TestEffectsClosedForm::oppositeChargeOrbitsAFixedCharge() {
    const double q = 1e-5, m = 1.0, r = 1.0, k = 8.9875517923e9;
    const double v = std::sqrt(k * q * q / (m * r)), period = 2.0 * kPi * r / v;
    SceneDesc scene;
    scene.simulation = simulation("rk4", period / 1000.0);
    ParticleDesc nucleus, electron;
    nucleus.pinned = true;
    nucleus.charge = q;
    electron.position = {r, 0.0};
    electron.velocity = {0.0, v};
    electron.radius = 0.0;
    electron.mass = m;
    electron.charge = -q;
    nucleus.radius = 0.0;
    scene.particles = {nucleus, electron};
    auto world = build(scene);
    for (int n = 0; n < 1000; ++n) {
        QVERIFY(world->step());
        QVERIFY(std::abs(world->particlePosition(1).norm() - r) < 1e-9);
    }
    QVERIFY((world->particlePosition(1) - Eigen::Vector2d(r, 0.0)).norm() < 1e-9);
    QVERIFY(std::abs(world->energy().drift) < 1e-12);
}

// Circular orbit of radius r round G·M: speed √(GM/r), period 2π·√(r³/GM). The period is read
// off the run as the time the orbit takes to cross the +x axis again (interpolated).
void TestEffectsClosedForm::circularOrbitPeriodIsTwoPiRootR3OverGM() {
    const double gm = 50.0, r = 3.0, period = 2.0 * kPi * std::sqrt(r * r * r / gm);
    SceneDesc scene;
    scene.simulation = simulation("rk4", 0.002);
    NewtonianGravityDesc ng;
    ng.G = 1.0;
    ng.attractors.push_back({{0.0, 0.0}, gm});
    scene.effects.newtonianGravity = ng;
    ParticleDesc p;
    p.position = {r, 0.0};
    p.velocity = {0.0, std::sqrt(gm / r)};
    p.radius = 0.0;
    scene.particles.push_back(p);
    auto world = build(scene);
    double crossed = -1.0, previousY = 0.0, previousT = 0.0;
    while (crossed < 0.0 && world->time() < 2.0 * period) {
        QVERIFY(world->step());
        const double y = world->particlePosition(0).y();
        if (world->time() > 0.5 * period && previousY < 0.0 && y >= 0.0)
            crossed = previousT + (world->time() - previousT) * (-previousY) / (y - previousY);
        previousY = y;
        previousT = world->time();
    }
    qInfo("orbit r = %.1f about GM = %.1f: period %.9f s, 2π√(r³/GM) = %.9f s", r, gm, crossed,
          period);
    QVERIFY(std::abs(crossed - period) < 1e-6 * period);
}

// 100 boids in a 10 × 10 block 0.6 m apart, heading the same way give or take 0.2 m/s, with
// the default weights (radius 1 m, so separation within 0.5 m; max speed 2 m/s): over 30 s they
// must stay one flock (every pair within twice the block's diagonal) without collapsing (no two
// ever closer than 0.35 of the separation radius, and once settled, after 20 s, than 0.6 of it:
// the flock does not keep shrinking), line up, and respect the speed limit.
void TestEffectsClosedForm::flockStaysTogetherAndDoesNotCollapse() {
    SceneDesc scene;
    scene.simulation = simulation("symplectic_euler", 1.0 / 60.0);
    scene.effects.flocking = FlockingDesc{};
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    for (int j = 0; j < 10; ++j)
        for (int i = 0; i < 10; ++i) {
            ParticleDesc p;
            p.position = {0.6 * i, 0.6 * j};
            p.velocity = {1.0 + jitter(rng), 0.5 + jitter(rng)};
            p.radius = 0.0;
            scene.particles.push_back(p);
        }
    auto world = build(scene);
    const double diagonal = 0.6 * 9.0 * std::sqrt(2.0);
    const double separationRadius = FlockingEffect::kSeparationFraction * FlockingDesc{}.radius;
    double widest = 0.0, closest = 1e9, closestSettled = 1e9, fastest = 0.0;
    for (int n = 0; n < 30 * 60; ++n) {
        QVERIFY(world->step());
        const Eigen::VectorXd& q = world->positions();
        for (int a = 0; a < 100; ++a) {
            fastest = std::max(fastest, world->velocities().segment<2>(2 * a).norm());
            for (int b = a + 1; b < 100; ++b) {
                const double d = (q.segment<2>(2 * a) - q.segment<2>(2 * b)).norm();
                widest = std::max(widest, d);
                closest = std::min(closest, d);
                if (world->time() > 20.0) closestSettled = std::min(closestSettled, d);
            }
        }
    }
    Eigen::Vector2d heading = Eigen::Vector2d::Zero();
    for (int a = 0; a < 100; ++a) heading += world->velocities().segment<2>(2 * a).normalized();
    const double polarisation = heading.norm() / 100.0;
    qInfo(
        "flock over 30 s: widest pair %.3f m (block diagonal %.3f), closest %.3f m (%.3f m "
        "after 20 s), fastest %.3f m/s, polarisation %.4f",
        widest, diagonal, closest, closestSettled, fastest, polarisation);
    QVERIFY(widest < 2.0 * diagonal);
    QVERIFY(closest > 0.35 * separationRadius);
    QVERIFY(closestSettled > 0.6 * separationRadius);
    QVERIFY(polarisation > 0.99);
    QVERIFY(fastest < 1.1 * FlockingDesc{}.maxSpeed);
}

QTEST_APPLESS_MAIN(TestEffectsClosedForm)
#include "tst_effects_closed_form.moc"
