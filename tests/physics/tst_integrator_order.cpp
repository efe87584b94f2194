// Observed global order of every integrator against exact solutions (CONTRACT.md §3):
// the harmonic oscillator and a Kepler orbit for the eight fixed-step methods, and for the two
// adaptive ones how the error follows the tolerance and that they land on the caller's step.

#include "PhysicsTestSupport.h"
#include "physics/integrators/Integrator.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

// Allowed distance between the observed and the theoretical order.
constexpr double kOrderTolerance = 0.15;

// Oscillator (k = m = 1) from x = (1, 0), v = (0, 0.5): x(t) = (cos t, 0.5·sin t). The end time
// T = 10 is deliberately not a multiple of the period: at a whole period the O(h) error of
// symplectic Euler cancels (it is conjugate to Störmer–Verlet by an O(h) change of variables
// that the exact flow maps onto itself after a period), which would hide its first order.
constexpr double kOscillatorTime = 10.0;

double oscillatorError(const SceneDesc& scene, int steps) {
    auto world = build(scene);
    for (int i = 0; i < steps; ++i)
        if (!world->step()) return std::nan("");
    const double t = world->time();
    Eigen::VectorXd q(2), u(2);
    q << std::cos(t), 0.5 * std::sin(t);
    u << -std::sin(t), 0.5 * std::cos(t);
    return stateError(*world, q, u);
}

// Kepler orbit (e = 0.5, a = 1, G·M = 1) over one period 2π: the exact end state is the start.
// The orbit starts at true anomaly π/2, not at perihelion: from an apsis the O(h) error of
// symplectic Euler also cancels over a whole period (it measures as order 2 there).
constexpr double kEccentricity = 0.5;
constexpr double kKeplerPeriod = 2.0 * kPi;

double keplerError(const SceneDesc& scene, int steps) {
    auto world = build(scene);
    const Eigen::VectorXd q0 = world->positions(), u0 = world->velocities();
    for (int i = 0; i < steps; ++i)
        if (!world->step()) return std::nan("");
    return stateError(*world, q0, u0);
}

}  // namespace

class TestIntegratorOrder : public QObject {
    Q_OBJECT

private slots:
    void registryStatesTheoreticalOrders();
    void harmonicOscillatorOrder_data();
    void harmonicOscillatorOrder();
    void keplerOrder_data();
    void keplerOrder();
    void adaptiveErrorFollowsTolerance_data();
    void adaptiveErrorFollowsTolerance();
    void adaptiveLandsOnStepBoundaries_data();
    void adaptiveLandsOnStepBoundaries();
    void adaptiveResultIndependentOfFrameSplitting_data();
    void adaptiveResultIndependentOfFrameSplitting();
    void positionWeightIsTheStepsDisplacement_data();
    void positionWeightIsTheStepsDisplacement();
};

// The registry's advertised order is what the app and `phasebox-cli integrators` show.
void TestIntegratorOrder::registryStatesTheoreticalOrders() {
    for (const Theory& t : kFixedStep) {
        const IntegratorInfo* info = findIntegrator(t.name);
        QVERIFY2(info, t.name);
        QCOMPARE(double(info->order), t.order);
        QVERIFY(!info->adaptive);
    }
    QVERIFY(findIntegrator("adaptive_euler") && findIntegrator("adaptive_euler")->adaptive);
    QVERIFY(findIntegrator("rk45") && findIntegrator("rk45")->adaptive);
    QCOMPARE(integratorRegistry().size(), std::size_t(10));
}

void TestIntegratorOrder::harmonicOscillatorOrder_data() {
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<double>("order");
    QTest::addColumn<int>("coarsestSteps");
    // The coarsest step counts put every method in its asymptotic regime (error ≪ 1) while
    // rk4's finest error (~1e-8) stays far above round-off.
    const int coarsest[] = {1000, 1000, 250, 250, 32, 250, 1000, 250};
    int i = 0;
    for (const Theory& t : kFixedStep)
        QTest::newRow(t.name) << QString(t.name) << t.order << coarsest[i++];
}

void TestIntegratorOrder::harmonicOscillatorOrder() {
    QFETCH(QString, integrator);
    QFETCH(double, order);
    QFETCH(int, coarsestSteps);
    std::vector<double> h, error;
    for (int k = 0; k < 4; ++k) {
        const int steps = coarsestSteps << k;
        const double dt = kOscillatorTime / steps;
        const double e = oscillatorError(
            oscillatorScene(integrator.toStdString(), dt, {1.0, 0.0}, {0.0, 0.5}), steps);
        QVERIFY2(std::isfinite(e) && e > 0.0, qPrintable(QString("error %1").arg(e)));
        h.push_back(dt);
        error.push_back(e);
    }
    const double observed = fittedOrder(h, error);
    qInfo("oscillator %-18s observed order %.3f (errors %.3e .. %.3e)", qPrintable(integrator),
          observed, error.front(), error.back());
    QVERIFY2(std::abs(observed - order) <= kOrderTolerance,
             qPrintable(QString("observed order %1, theory %2").arg(observed).arg(order)));
}

void TestIntegratorOrder::keplerOrder_data() {
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<double>("order");
    QTest::addColumn<int>("coarsestSteps");
    // The first-order methods need ~1e4 steps per orbit before the e = 0.5 perihelion passage
    // is resolved well enough for the leading error term to dominate.
    const int coarsest[] = {10000, 2000, 500, 500, 100, 500, 10000, 500};
    int i = 0;
    for (const Theory& t : kFixedStep)
        QTest::newRow(t.name) << QString(t.name) << t.order << coarsest[i++];
}

void TestIntegratorOrder::keplerOrder() {
    QFETCH(QString, integrator);
    QFETCH(double, order);
    QFETCH(int, coarsestSteps);
    std::vector<double> h, error;
    for (int k = 0; k < 4; ++k) {
        const int steps = coarsestSteps << k;
        const double dt = kKeplerPeriod / steps;
        const double e =
            keplerError(keplerScene(integrator.toStdString(), dt, kEccentricity), steps);
        QVERIFY2(std::isfinite(e) && e > 0.0, qPrintable(QString("error %1").arg(e)));
        h.push_back(dt);
        error.push_back(e);
    }
    const double observed = fittedOrder(h, error);
    qInfo("kepler     %-18s observed order %.3f (errors %.3e .. %.3e)", qPrintable(integrator),
          observed, error.front(), error.back());
    QVERIFY2(std::abs(observed - order) <= kOrderTolerance,
             qPrintable(QString("observed order %1, theory %2").arg(observed).arg(order)));
}

// Error against tolerance. With error-per-step control the accepted local error is about the
// tolerance, and the step count goes as the local error's inverse root:
//  - adaptive_euler keeps the two half steps (no extrapolation): local error ~ h² ~ tol, about
//    T/√tol steps, so the global error goes as tol^(1/2);
//  - rk45 propagates the fifth-order solution while its error estimate is fourth order
//    (local extrapolation): h ~ tol^(1/5), true local error ~ h⁶ ~ tol^(6/5), about tol^(-1/5)
//    steps, so the global error goes as tol¹ ("tolerance proportionality").
void TestIntegratorOrder::adaptiveErrorFollowsTolerance_data() {
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<bool>("kepler");
    QTest::addColumn<double>("exponent");
    QTest::addColumn<double>("loosestTolerance");
    // Four tolerances, each 100× tighter, from the loosest one at which the error is already in
    // its asymptotic regime (the e = 0.5 orbit needs tighter ones than the oscillator).
    QTest::newRow("rk45 oscillator") << QString("rk45") << false << 1.0 << 1e-4;
    QTest::newRow("rk45 kepler") << QString("rk45") << true << 1.0 << 1e-7;
    QTest::newRow("adaptive_euler oscillator") << QString("adaptive_euler") << false << 0.5 << 1e-3;
    QTest::newRow("adaptive_euler kepler") << QString("adaptive_euler") << true << 0.5 << 1e-4;
}

void TestIntegratorOrder::adaptiveErrorFollowsTolerance() {
    QFETCH(QString, integrator);
    QFETCH(bool, kepler);
    QFETCH(double, exponent);
    QFETCH(double, loosestTolerance);
    // Few, long frames, so the methods choose their own internal steps.
    const double duration = kepler ? kKeplerPeriod : kOscillatorTime;
    const int frames = kepler ? 16 : 10;
    std::vector<double> tolerances, errors;
    for (int k = 0; k < 4; ++k) {
        const double tol = loosestTolerance * std::pow(10.0, -2.0 * k);
        SceneDesc scene =
            kepler ? keplerScene(integrator.toStdString(), duration / frames, kEccentricity)
                   : oscillatorScene(integrator.toStdString(), duration / frames, {1.0, 0.0},
                                     {0.0, 0.5});
        scene.simulation.tolerance = tol;
        const double e = kepler ? keplerError(scene, frames) : oscillatorError(scene, frames);
        QVERIFY2(std::isfinite(e), "the run failed");
        tolerances.push_back(tol);
        errors.push_back(e);
        qInfo("%-14s %s tol %.0e error %.3e", qPrintable(integrator),
              kepler ? "kepler    " : "oscillator", tol, e);
    }
    // A tighter tolerance always buys a smaller error, by a factor in line with the exponent
    // (each tolerance is 100× tighter: at least 100^(exponent − 0.25)).
    for (std::size_t i = 1; i < errors.size(); ++i)
        QVERIFY2(errors[i] * std::pow(100.0, exponent - 0.25) <= errors[i - 1],
                 qPrintable(QString("tol %1 → error %2, tol %3 → error %4")
                                .arg(tolerances[i - 1])
                                .arg(errors[i - 1])
                                .arg(tolerances[i])
                                .arg(errors[i])));
    const double observed = fittedOrder(tolerances, errors);
    qInfo("%-14s %s error ~ tol^%.3f", qPrintable(integrator), kepler ? "kepler    " : "oscillator",
          observed);
    QVERIFY2(std::abs(observed - exponent) <= 0.25,
             qPrintable(QString("error ~ tol^%1, theory tol^%2").arg(observed).arg(exponent)));
    if (!kepler) {
        // On the oscillator the flow is a rotation in each (x, v) plane, so local errors add
        // up without amplification. With the tolerance scaled by (1 + |y|) ≤ 2 the global error
        // is at most about 2·T·tol for rk45; for adaptive_euler each accepted step has local
        // error ≤ tol and the step is ≈ 1.8·√tol (|x''| ≤ 1), so T·√tol bounds the sum.
        for (std::size_t i = 0; i < errors.size(); ++i) {
            const double bound = integrator == "rk45" ? 2.0 * duration * tolerances[i]
                                                      : duration * std::sqrt(tolerances[i]);
            QVERIFY2(errors[i] <= bound, qPrintable(QString("tol %1: error %2 > bound %3")
                                                        .arg(tolerances[i])
                                                        .arg(errors[i])
                                                        .arg(bound)));
        }
    }
}

void TestIntegratorOrder::adaptiveLandsOnStepBoundaries_data() {
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<double>("dt");
    QTest::addColumn<double>("tolerance");
    QTest::newRow("rk45 dt=0.1") << QString("rk45") << 0.1 << 1e-8;
    QTest::newRow("rk45 dt=0.37") << QString("rk45") << 0.37 << 1e-8;
    QTest::newRow("adaptive_euler dt=0.1") << QString("adaptive_euler") << 0.1 << 1e-7;
    QTest::newRow("adaptive_euler dt=1/60") << QString("adaptive_euler") << 1.0 / 60.0 << 1e-7;
}

// A stiff-ish spring (ω = 10) forces many internal steps per frame, while a free "clock"
// particle moving at 1 m/s integrates x' = 1 exactly whatever the step sizes: its x is the sum
// of the internal steps taken. So after each frame its x must equal the world time exactly
// (up to the round-off of adding up the steps), and the spring particle must match the exact
// solution at that time, i.e. the method stopped on the frame boundary, not before or after.
void TestIntegratorOrder::adaptiveLandsOnStepBoundaries() {
    QFETCH(QString, integrator);
    QFETCH(double, dt);
    QFETCH(double, tolerance);
    SceneDesc scene = oscillatorScene(integrator.toStdString(), dt, {1.0, 0.0}, {0.0, 0.0}, 100.0);
    scene.simulation.tolerance = tolerance;
    ParticleDesc clock;
    clock.id = "clock";
    clock.position = {0.0, 5.0};
    clock.velocity = {1.0, 0.0};
    clock.radius = 0.0;
    scene.particles.push_back(clock);
    auto world = build(scene);
    const int clockDof = world->particles()[1].dof;
    long long accepted = 0;
    const int frames = static_cast<int>(std::ceil(2.0 / dt));
    for (int i = 0; i < frames; ++i) {
        QVERIFY(world->step());
        // The world's clock advances by dt per step (to the round-off of accumulating it).
        const double t = world->time();
        QVERIFY2(std::abs(t - (i + 1) * dt) <= 1e-14 * (i + 1),
                 qPrintable(QString("after %1 steps t = %2").arg(i + 1).arg(t, 0, 'g', 17)));
        QVERIFY2(std::abs(world->positions()[clockDof] - t) <= 1e-13 * (1.0 + t),
                 qPrintable(QString("frame %1: clock particle at %2, world time %3")
                                .arg(i)
                                .arg(world->positions()[clockDof], 0, 'g', 17)
                                .arg(t, 0, 'g', 17)));
        QCOMPARE(world->positions()[clockDof + 1], 5.0);
        // Exact oscillator at the frame time, to within the tolerance-driven error (a missed
        // boundary would show at the clock particle long before it shows here).
        const double x = world->positions()[0];
        QVERIFY2(std::abs(x - std::cos(10.0 * t)) < 1e-2,
                 qPrintable(QString("t=%1 x=%2 exact %3").arg(t).arg(x).arg(std::cos(10.0 * t))));
    }
    accepted = world->integrator().stats().acceptedSteps;
    // The test is only meaningful if the method did subdivide the frames.
    QVERIFY2(accepted > 2 * frames, qPrintable(QString("only %1 internal steps").arg(accepted)));
}

void TestIntegratorOrder::adaptiveResultIndependentOfFrameSplitting_data() {
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<double>("tolerance");
    QTest::newRow("rk45") << QString("rk45") << 1e-9;
    QTest::newRow("adaptive_euler") << QString("adaptive_euler") << 1e-8;
}

// The same one second of a Kepler orbit in 1, 4 or 20 frames: the internal steps differ, so
// every splitting must agree with the exact state at t = 1 to the tolerance-controlled error;
// a mis-placed end time would show as an error of order speed × time offset.
void TestIntegratorOrder::adaptiveResultIndependentOfFrameSplitting() {
    QFETCH(QString, integrator);
    QFETCH(double, tolerance);
    std::vector<Eigen::VectorXd> ends;
    for (int frames : {1, 4, 20}) {
        SceneDesc scene = keplerScene(integrator.toStdString(), 1.0 / frames, kEccentricity);
        scene.simulation.tolerance = tolerance;
        auto world = build(scene);
        for (int i = 0; i < frames; ++i) QVERIFY(world->step());
        Eigen::VectorXd y(4);
        y << world->positions(), world->velocities();
        ends.push_back(y);
    }
    // Global error bounds from adaptiveErrorFollowsTolerance, with room for the orbit's
    // amplification: 1e3·tol for rk45, 10·√tol for adaptive_euler.
    const double bound = integrator == "rk45" ? 1e3 * tolerance : 10.0 * std::sqrt(tolerance);
    const Eigen::Vector4d exact = keplerState(kEccentricity, kPi / 2.0, 1.0);
    for (std::size_t i = 0; i < ends.size(); ++i) {
        const double diff = (ends[i] - exact).lpNorm<Eigen::Infinity>();
        QVERIFY2(diff <= bound,
                 qPrintable(QString("split %1 is %2 from the exact state").arg(i).arg(diff)));
    }
}

void TestIntegratorOrder::positionWeightIsTheStepsDisplacement_data() {
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<double>("tolerance");
    for (const IntegratorInfo& info : integratorRegistry())
        for (double tolerance : {1.0, 1e-9}) {
            const QString name = QString::fromLatin1(info.name.data(), info.name.size());
            QTest::newRow(qPrintable(QString("%1, tolerance %2").arg(name).arg(tolerance)))
                << name << tolerance;
        }
}

// Under a constant acceleration a, one step of h moves a body by h·v + w·a·h², and w is what the
// method reports (Integrator::positionWeight()): the contacts move a resting body by it. Gravity
// alone on a particle, frame after frame. Adaptive Euler's w depends on how it cut the frame: one
// accepted step at a loose tolerance (¼), thousands at a tight one (close to ½).
void TestIntegratorOrder::positionWeightIsTheStepsDisplacement() {
    QFETCH(QString, integrator);
    QFETCH(double, tolerance);
    const double g = 9.81, h = 1.0 / 60.0;
    SceneDesc scene;
    scene.simulation = simulation(integrator.toStdString(), h);
    scene.simulation.tolerance = tolerance;
    scene.effects.gravity = GravityDesc{{0.0, -g}};
    ParticleDesc p;
    p.id = "ball";
    p.position = {0.0, 0.0};
    p.velocity = {1.0, 2.0};
    p.radius = 0.0;
    scene.particles.push_back(p);
    auto world = build(scene);
    double weights[2] = {0.0, 0.0};
    for (int frame = 0; frame < 3; ++frame) {
        const double y0 = world->positions()[1], v0 = world->velocities()[1];
        const long long before = world->integrator().stats().acceptedSteps;
        QVERIFY(world->step());
        const double w = world->integrator().positionWeight();
        const double moved = world->positions()[1] - (y0 + h * v0);
        qInfo("frame %d: %lld internal steps, w %.15f, moved/(-g h^2) %.15f", frame,
              world->integrator().stats().acceptedSteps - before, w, moved / (-g * h * h));
        QVERIFY2(std::abs(moved - w * (-g) * h * h) <= 1e-12 * g * h * h,
                 qPrintable(QString("moved %1, w·a·h² %2").arg(moved).arg(w * -g * h * h)));
        weights[std::min(frame, 1)] = w;
    }
    const IntegratorInfo& info = world->integrator().info();
    if (!info.adaptive || integrator == "rk45") {
        QCOMPARE(weights[1], info.positionWeight);
    } else if (tolerance >= 1.0) {
        QCOMPARE(weights[1], 0.25);  // one accepted step of two half steps
    } else {
        QVERIFY2(weights[1] > 0.49 && weights[1] < 0.5, qPrintable(QString::number(weights[1])));
    }
}

QTEST_APPLESS_MAIN(TestIntegratorOrder)
#include "tst_integrator_order.moc"
