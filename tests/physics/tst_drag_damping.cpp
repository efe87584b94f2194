// Dissipative forces against their closed forms: falling with linear and quadratic drag
// (terminal velocities and the whole v(t) curve), the underdamped spring, and the energy
// ledger (CONTRACT.md §2): their work goes to work_nc, so the drift is the integrator's error
// alone.

#include "PhysicsTestSupport.h"

#include <QTest>

#include <cmath>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

constexpr double kG = 9.81;

SceneDesc fallingBall(double mass, double linear, double quadratic, Point2 velocity, double dt) {
    SceneDesc scene;
    scene.simulation = simulation("rk4", dt);
    scene.effects.gravity = GravityDesc{{0.0, -kG}};
    DragDesc drag;
    drag.linear = linear;
    drag.quadratic = quadratic;
    scene.effects.drag = drag;
    ParticleDesc p;
    p.id = "ball";
    p.position = {0.0, 0.0};
    p.velocity = velocity;
    p.mass = mass;
    p.radius = 0.0;
    scene.particles.push_back(p);
    return scene;
}

// Mass m on a spring (stiffness k, damping c along it, rest length 1) to the origin, released
// from x = 1.5 at rest. The motion stays on the +x axis with length x ∈ (0.5, 1.5), where the
// spring force is exactly −k·(x − 1) − c·ẋ.
SceneDesc dampedSpring(const std::string& integrator, double dt, double k, double c) {
    SceneDesc scene;
    scene.simulation = simulation(integrator, dt);
    ParticleDesc p;
    p.id = "ball";
    p.position = {1.5, 0.0};
    p.mass = 1.0;
    p.radius = 0.0;
    scene.particles.push_back(p);
    SpringDesc s;
    s.a = "ball";
    s.anchor = Point2{0.0, 0.0};
    s.stiffness = k;
    s.damping = c;
    s.restLength = 1.0;
    scene.springs.push_back(s);
    return scene;
}

// Closed-form states (position, velocity) of the three scenarios.
struct Exact {
    Eigen::Vector2d x, v;
};

// Linear drag b on mass m falling from the origin with horizontal velocity vx0.
Exact linearDragExact(double m, double b, double vx0, double t) {
    const double vt = m * kG / b, tau = m / b, decay = std::exp(-t / tau);
    return {{vx0 * tau * (1.0 - decay), -vt * (t - tau * (1.0 - decay))},
            {vx0 * decay, -vt * (1.0 - decay)}};
}

// Quadratic drag c on mass m falling from rest at the origin.
Exact quadraticDragExact(double m, double c, double t) {
    const double vt = std::sqrt(m * kG / c), s = kG * t / vt;
    return {{0.0, -(vt * vt / kG) * std::log(std::cosh(s))}, {0.0, -vt * std::tanh(s)}};
}

// The underdamped spring of dampedSpring(…, k, c) with m = 1.
Exact dampedSpringExact(double k, double c, double t) {
    const double amplitude = 0.5, gamma = c / 2.0, wd = std::sqrt(k - gamma * gamma);
    const double decay = std::exp(-gamma * t);
    const double xi = amplitude * decay * (std::cos(wd * t) + gamma / wd * std::sin(wd * t));
    const double rate = -amplitude * (k / wd) * decay * std::sin(wd * t);
    return {{1.0 + xi, 0.0}, {rate, 0.0}};
}

}  // namespace

class TestDragAndDamping : public QObject {
    Q_OBJECT

private slots:
    void linearDragTerminalVelocity();
    void quadraticDragTerminalVelocity();
    void underdampedSpringClosedForm();
    void dampingWorkEntersWorkNc_data();
    void dampingWorkEntersWorkNc();
    void driftConvergesAtMethodOrder_data();
    void driftConvergesAtMethodOrder();
    void eulerLinearDragClosedForm_data();
    void eulerLinearDragClosedForm();
    void windDrivesParticleToWindVelocity();
};

// m·v' = m·g − b·v: v(t) = v_t·(1 − e^{−t/τ}) downward with v_t = m·g/b and τ = m/b; the
// horizontal velocity decays as vx₀·e^{−t/τ}. Positions are the integrals of those.
void TestDragAndDamping::linearDragTerminalVelocity() {
    const double m = 2.0, b = 0.5, vx0 = 5.0, dt = 0.01;
    const double vt = m * kG / b;
    auto world = build(fallingBall(m, b, 0.0, {vx0, 0.0}, dt));
    for (int n = 1; n <= 6000; ++n) {  // 60 s = 15 τ
        QVERIFY(world->step());
        const double t = world->time();
        const Exact e = linearDragExact(m, b, vx0, t);
        // rk4 at h/τ = 1/400: a local error of ~(h/τ)⁵/120 of the velocity scale per step.
        const double dv = (world->velocities() - e.v).lpNorm<Eigen::Infinity>();
        const double dx = (world->positions() - e.x).lpNorm<Eigen::Infinity>();
        QVERIFY2(dv <= 1e-10 * vt, qPrintable(QString("t=%1: |Δv| = %2").arg(t).arg(dv)));
        QVERIFY2(dx <= 1e-10 * vt * t, qPrintable(QString("t=%1: |Δx| = %2").arg(t).arg(dx)));
    }
    // Terminal velocity m·g/b reached: e^{−15} ≈ 3e-7 of it is still missing.
    QVERIFY(std::abs(world->velocities()[1] + vt) <= 4e-7 * vt);
    QVERIFY(std::abs(world->velocities()[0]) <= 4e-7 * vx0);
}

// m·v' = m·g − c·v²: falling from rest, v(t) = v_t·tanh(g·t/v_t) with v_t = √(m·g/c), and
// the drop y(t) = −(v_t²/g)·ln cosh(g·t/v_t).
void TestDragAndDamping::quadraticDragTerminalVelocity() {
    const double m = 1.0, c = 0.1, dt = 0.01;
    const double vt = std::sqrt(m * kG / c);
    auto world = build(fallingBall(m, 0.0, c, {0.0, 0.0}, dt));
    for (int n = 1; n <= 1000; ++n) {  // 10 s; the time scale v_t/g is ≈ 1 s
        QVERIFY(world->step());
        const double t = world->time();
        const Exact e = quadraticDragExact(m, c, t);
        QVERIFY2(
            std::abs(world->velocities()[1] - e.v.y()) <= 1e-9 * vt,
            qPrintable(
                QString("t=%1: v=%2, exact %3").arg(t).arg(world->velocities()[1]).arg(e.v.y())));
        QVERIFY2(
            std::abs(world->positions()[1] - e.x.y()) <= 1e-9 * vt * t,
            qPrintable(
                QString("t=%1: y=%2, exact %3").arg(t).arg(world->positions()[1]).arg(e.x.y())));
        QCOMPARE(world->positions()[0], 0.0);
    }
    // tanh(9.9) = 1 − 5e-9: the terminal velocity √(m·g/c).
    QVERIFY(std::abs(world->velocities()[1] + vt) <= 1e-8 * vt);
}

// ξ = x − 1 obeys ξ'' + 2γ·ξ' + ω₀²·ξ = 0 with γ = c/2m, ω₀² = k/m. Underdamped (γ < ω₀):
// ξ(t) = A·e^{−γt}·(cos ω_d·t + (γ/ω_d)·sin ω_d·t), ξ'(t) = −A·(ω₀²/ω_d)·e^{−γt}·sin ω_d·t.
void TestDragAndDamping::underdampedSpringClosedForm() {
    const double k = 4.0, c = 0.4, dt = 0.005;
    auto world = build(dampedSpring("rk4", dt, k, c));
    for (int n = 1; n <= 4000; ++n) {  // 20 s, about 13 periods
        QVERIFY(world->step());
        const double t = world->time();
        const Exact e = dampedSpringExact(k, c, t);
        // rk4's global error here is about n·(ω₀h)⁵/120·A ≈ 2e-10; allow 1e-8.
        QVERIFY2(
            std::abs(world->positions()[0] - e.x.x()) <= 1e-8,
            qPrintable(
                QString("t=%1: x=%2, exact %3").arg(t).arg(world->positions()[0]).arg(e.x.x())));
        QVERIFY2(
            std::abs(world->velocities()[0] - e.v.x()) <= 1e-8,
            qPrintable(
                QString("t=%1: v=%2, exact %3").arg(t).arg(world->velocities()[0]).arg(e.v.x())));
        QCOMPARE(world->positions()[1], 0.0);
    }
}

void TestDragAndDamping::dampingWorkEntersWorkNc_data() {
    QTest::addColumn<QString>("scenario");
    QTest::newRow("damped spring") << QString("spring");
    QTest::newRow("linear drag") << QString("linear");
    QTest::newRow("quadratic drag") << QString("quadratic");
}

// Kinetic + potential − work_nc stays equal to its initial value (drift ≈ 0) while work_nc is
// a large part of the energy, and work_nc itself equals the closed-form work of the dissipative
// force (the mechanical energy lost along the exact trajectory).
void TestDragAndDamping::dampingWorkEntersWorkNc() {
    QFETCH(QString, scenario);
    std::unique_ptr<World> world;
    int steps = 0;
    if (scenario == "spring") {
        world = build(dampedSpring("rk4", 0.005, 4.0, 0.4));
        steps = 4000;
    } else if (scenario == "linear") {
        world = build(fallingBall(2.0, 0.5, 0.0, {5.0, 0.0}, 0.01));
        steps = 3000;
    } else {
        world = build(fallingBall(1.0, 0.0, 0.1, {0.0, 0.0}, 0.01));
        steps = 1000;
    }
    const double e0 = mechanicalEnergy(*world);
    QCOMPARE(world->energy().workNc, 0.0);
    QCOMPARE(world->energy().drift, 0.0);
    double worstDrift = 0.0;
    for (int n = 1; n <= steps; ++n) {
        QVERIFY(world->step());
        const EnergyLedger& l = world->energy();
        // The ledger's definition of drift (CONTRACT.md §2).
        QVERIFY(std::abs(l.drift - (l.kinetic + l.potential - l.workNc - l.initial)) <=
                1e-12 * (std::abs(l.kinetic) + std::abs(l.potential) + std::abs(l.workNc)));
        // Dissipation only ever removes energy.
        QVERIFY(l.workNc <= 0.0);
        worstDrift = std::max(worstDrift, std::abs(l.drift));
    }
    const EnergyLedger& l = world->energy();
    QCOMPARE(l.initial, e0);
    // The work of the dissipative force in closed form: the mechanical energy the exact
    // trajectory has lost by now.
    const double t = world->time();
    double exactWork = 0.0;
    if (scenario == "spring") {
        const Exact e = dampedSpringExact(4.0, 0.4, t);
        exactWork = 0.5 * 4.0 * std::pow(e.x.x() - 1.0, 2) + 0.5 * e.v.squaredNorm() - e0;
    } else {
        const double m = world->mass()[0];
        const Exact e =
            scenario == "linear" ? linearDragExact(m, 0.5, 5.0, t) : quadraticDragExact(m, 0.1, t);
        exactWork = 0.5 * m * e.v.squaredNorm() + m * kG * e.x.y() - e0;
    }
    // work_nc is a large part of the energy in play: the spring has lost all but e^{−8} of its
    // 0.5 J; a falling ball near terminal speed turns most of the potential energy it releases
    // into drag work.
    const double scale = std::abs(exactWork);
    if (scenario == "spring")
        QVERIFY(scale > 0.99 * e0);
    else
        QVERIFY(scale > 0.5 * world->mass()[0] * kG * -world->positions()[1]);
    QVERIFY2(std::abs(l.workNc - exactWork) <= 1e-8 * scale,
             qPrintable(QString("work_nc %1, closed form %2")
                            .arg(l.workNc, 0, 'g', 12)
                            .arg(exactWork, 0, 'g', 12)));
    QVERIFY2(
        worstDrift <= 1e-8 * scale,
        qPrintable(QString("max |drift| %1 against work_nc %2").arg(worstDrift).arg(l.workNc)));
}

void TestDragAndDamping::driftConvergesAtMethodOrder_data() {
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<double>("order");
    QTest::addColumn<int>("coarsestSteps");
    // rk4 starts coarser so that its finest drift (~1e-11) stays clear of round-off.
    QTest::newRow("explicit_euler") << QString("explicit_euler") << 1.0 << 1000;
    QTest::newRow("symplectic_euler") << QString("symplectic_euler") << 1.0 << 1000;
    QTest::newRow("midpoint") << QString("midpoint") << 2.0 << 1000;
    QTest::newRow("heun") << QString("heun") << 2.0 << 1000;
    QTest::newRow("rk4") << QString("rk4") << 4.0 << 250;
    QTest::newRow("velocity_verlet") << QString("velocity_verlet") << 2.0 << 1000;
    QTest::newRow("implicit_euler") << QString("implicit_euler") << 1.0 << 1000;
    QTest::newRow("implicit_midpoint") << QString("implicit_midpoint") << 2.0 << 1000;
}

// If work_nc is integrated consistently with each method, the drift is that method's global
// error in E − W and vanishes at the method's order. A work quadrature of lower order than the
// method (wrong stage weights, power taken at the wrong point) would show here. The scene
// mixes spring damping with linear and quadratic drag on a swinging, stretching spring.
void TestDragAndDamping::driftConvergesAtMethodOrder() {
    QFETCH(QString, integrator);
    QFETCH(double, order);
    QFETCH(int, coarsestSteps);
    std::vector<double> h, drift;
    for (int k = 0; k < 4; ++k) {
        const int steps = coarsestSteps << k;
        SceneDesc scene = dampedSpring(integrator.toStdString(), 10.0 / steps, 4.0, 0.4);
        scene.particles[0].velocity = {0.0, 0.7};
        DragDesc drag;
        drag.linear = 0.1;
        drag.quadratic = 0.3;
        scene.effects.drag = drag;
        auto world = build(scene);
        for (int n = 0; n < steps; ++n) QVERIFY(world->step());
        // The dissipation is substantial: most of the initial 0.745 J.
        QVERIFY(world->energy().workNc < -0.5 * world->energy().initial);
        h.push_back(10.0 / steps);
        drift.push_back(world->energy().maxAbsDrift);
    }
    const double observed = fittedOrder(h, drift);
    qInfo("%-18s max |drift| %.3e .. %.3e, order %.3f", qPrintable(integrator), drift.front(),
          drift.back(), observed);
    QVERIFY2(std::abs(observed - order) <= 0.15,
             qPrintable(
                 QString("drift converges at order %1, method order %2").arg(observed).arg(order)));
}

void TestDragAndDamping::eulerLinearDragClosedForm_data() {
    QTest::addColumn<QString>("integrator");
    QTest::newRow("explicit_euler") << QString("explicit_euler");
    QTest::newRow("implicit_euler") << QString("implicit_euler");
}

// v' = g − (b/m)·v is linear, so the Euler methods have exact step-by-step solutions: with
// v_t = (m/b)·g, explicit Euler gives v_N − v_t = (1 − h·b/m)^N·(v₀ − v_t) and backward Euler
// (one Newton iteration is exact here) v_N − v_t = (1 + h·b/m)^{−N}·(v₀ − v_t). Positions
// add up h·v_n (explicit: n = 0…N−1; implicit: n = 1…N), geometric sums in closed form.
void TestDragAndDamping::eulerLinearDragClosedForm() {
    QFETCH(QString, integrator);
    const bool implicit = integrator == "implicit_euler";
    const double m = 2.0, b = 0.5, h = 0.1;
    SceneDesc scene = fallingBall(m, b, 0.0, {5.0, 0.0}, h);
    scene.simulation.integrator = integrator.toStdString();
    auto world = build(scene);
    const Eigen::Vector2d vt(0.0, -m * kG / b), v0(5.0, 0.0);
    const double r = implicit ? 1.0 / (1.0 + h * b / m) : 1.0 - h * b / m;
    for (int n = 1; n <= 400; ++n) {
        QVERIFY(world->step());
        const Eigen::Vector2d v = vt + std::pow(r, n) * (v0 - vt);
        // Σ_{k=0}^{n−1} r^k (explicit) or Σ_{k=1}^{n} r^k (implicit).
        const double sum = (implicit ? r : 1.0) * (1.0 - std::pow(r, n)) / (1.0 - r);
        const Eigen::Vector2d x = h * (n * vt + sum * (v0 - vt));
        const double dv = (world->velocities() - v).lpNorm<Eigen::Infinity>();
        const double dx = (world->positions() - x).lpNorm<Eigen::Infinity>();
        QVERIFY2(dv <= 1e-12 * vt.norm(), qPrintable(QString("step %1: |Δv| = %2").arg(n).arg(dv)));
        QVERIFY2(dx <= 1e-12 * vt.norm() * n * h,
                 qPrintable(QString("step %1: |Δx| = %2").arg(n).arg(dx)));
    }
}

// Wind w with drag b on a particle from rest (no gravity): v(t) = w·(1 − e^{−t/τ}),
// x(t) = w·(t − τ·(1 − e^{−t/τ})), τ = m/b. The wind's work is all the kinetic energy gained.
void TestDragAndDamping::windDrivesParticleToWindVelocity() {
    const double m = 0.5, b = 0.2, tau = m / b, dt = 0.01;
    const Eigen::Vector2d w(3.0, 1.0);
    SceneDesc scene;
    scene.simulation = simulation("rk4", dt);
    scene.effects.wind = WindDesc{{w.x(), w.y()}, b};
    ParticleDesc p;
    p.id = "leaf";
    p.mass = m;
    p.radius = 0.0;
    scene.particles.push_back(p);
    auto world = build(scene);
    for (int n = 1; n <= 5000; ++n) {  // 50 s = 20 τ
        QVERIFY(world->step());
        const double t = world->time(), decay = std::exp(-t / tau);
        const Eigen::Vector2d v = w * (1.0 - decay), x = w * (t - tau * (1.0 - decay));
        QVERIFY2((world->velocities() - v).lpNorm<Eigen::Infinity>() <= 1e-10 * w.norm(),
                 qPrintable(QString("t=%1: off the exact velocity").arg(t)));
        QVERIFY2((world->positions() - x).lpNorm<Eigen::Infinity>() <= 1e-10 * w.norm() * t,
                 qPrintable(QString("t=%1: off the exact position").arg(t)));
    }
    QVERIFY((world->velocities() - w).norm() <= 1e-8 * w.norm() + std::exp(-20.0) * w.norm());
    const double gained = 0.5 * m * w.squaredNorm() * std::pow(1.0 - std::exp(-20.0), 2);
    QVERIFY(std::abs(world->energy().workNc - gained) <= 1e-9 * gained);
    QVERIFY(std::abs(world->energy().drift) <= 1e-9 * gained);
}

QTEST_APPLESS_MAIN(TestDragAndDamping)
#include "tst_drag_damping.moc"
