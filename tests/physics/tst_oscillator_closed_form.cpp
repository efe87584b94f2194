// Step-by-step closed forms and energy laws of the integrators on the linear oscillator
// (m = k = 1, spring of rest length 0 to the origin, so the force is exactly −x).
//
// On a linear problem every fixed-step method is a 2×2 matrix M acting on (x, v) of each
// coordinate, so after N steps the state is exactly M^N·(x₀, v₀). The matrices below are
// derived by hand from the formulas of CONTRACT.md §3 with a(x) = −x; the powers are computed
// here independently of the engine (binary powering, or trigonometric closed forms).

#include "PhysicsTestSupport.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <string>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

using Mat = Eigen::Matrix2d;

// The one-step matrix of each method on x'' = −x, acting on (x, v).
Mat stepMatrix(const std::string& name, double h) {
    Mat J;  // (x, v)' = J·(x, v)
    J << 0.0, 1.0, -1.0, 0.0;
    const Mat I = Mat::Identity();
    const Mat hJ = h * J;
    Mat m;
    if (name == "explicit_euler") {
        m << 1.0, h, -h, 1.0;
    } else if (name == "symplectic_euler") {
        // v' = v − h·x; x' = x + h·v' = (1 − h²)·x + h·v.
        m << 1.0 - h * h, h, -h, 1.0;
    } else if (name == "midpoint" || name == "heun") {
        // Both explicit second-order Runge–Kutta methods have the stability polynomial
        // 1 + z + z²/2.
        m = I + hJ + hJ * hJ / 2.0;
    } else if (name == "rk4") {
        m = I + hJ + hJ * hJ / 2.0 + hJ * hJ * hJ / 6.0 + hJ * hJ * hJ * hJ / 24.0;
    } else if (name == "velocity_verlet") {
        // x' = x + h·v − h²/2·x;  v' = v − h/2·(x + x').
        m << 1.0 - h * h / 2.0, h, -h + h * h * h / 4.0, 1.0 - h * h / 2.0;
    } else if (name == "implicit_euler") {
        m = (I - hJ).inverse();
    } else if (name == "implicit_midpoint") {
        m = (I - hJ / 2.0).inverse() * (I + hJ / 2.0);
    }
    return m;
}

Mat power(Mat base, long long n) {
    Mat result = Mat::Identity();
    while (n > 0) {
        if (n & 1) result = result * base;
        base = base * base;
        n >>= 1;
    }
    return result;
}

// The two independent coordinates of oscillatorScene(…, x0 = (1, 0), v0 = (0, 0.5)).
const Eigen::Vector2d kXStart{1.0, 0.0};  // (x, vx)
const Eigen::Vector2d kYStart{0.0, 0.5};  // (y, vy)

std::unique_ptr<World> oscillator(const std::string& integrator, double h, int newton = 1) {
    SceneDesc scene = oscillatorScene(integrator, h, {1.0, 0.0}, {0.0, 0.5});
    scene.simulation.newtonIterations = newton;
    return build(scene);
}

// Largest difference between the world's state and the expected (x, vx), (y, vy), relative to
// the expected amplitude (explicit Euler's grows, implicit Euler's shrinks).
double relativeDeviation(const World& world, const Eigen::Vector2d& x, const Eigen::Vector2d& y) {
    const double scale = std::max(x.norm(), y.norm());
    const double dx =
        std::max(std::abs(world.positions()[0] - x[0]), std::abs(world.velocities()[0] - x[1]));
    const double dy =
        std::max(std::abs(world.positions()[1] - y[0]), std::abs(world.velocities()[1] - y[1]));
    return std::max(dx, dy) / scale;
}

// A method whose step is amplitude·(rotation by −angle) has, from (1, 0) and (0, 0.5):
// x_N = a^N·cos(Nφ), v_N = −a^N·sin(Nφ) and y_N = 0.5·a^N·sin(Nφ), vy_N = 0.5·a^N·cos(Nφ).
void checkRotationClosedForm(const std::string& integrator, double h, double amplitude,
                             double angle, int steps, double tolerance) {
    auto world = oscillator(integrator, h);
    for (int n = 1; n <= steps; ++n) {
        QVERIFY(world->step());
        const double a = std::pow(amplitude, n), c = std::cos(n * angle), s = std::sin(n * angle);
        const double dev = relativeDeviation(*world, {a * c, -a * s}, {0.5 * a * s, 0.5 * a * c});
        QVERIFY2(dev <= tolerance, qPrintable(QString("%1 step %2: relative deviation %3")
                                                  .arg(integrator.c_str())
                                                  .arg(n)
                                                  .arg(dev)));
    }
}

}  // namespace

class TestOscillatorClosedForm : public QObject {
    Q_OBJECT

private slots:
    void explicitEulerClosedForm();
    void implicitEulerClosedForm();
    void implicitMidpointClosedForm();
    void symplecticAndVerletChebyshevClosedForm_data();
    void symplecticAndVerletChebyshevClosedForm();
    void stepMatrixPowers_data();
    void stepMatrixPowers();
    void explicitEulerEnergyGrowsByOnePlusHSquared();
    void implicitEulerEnergyShrinksByOnePlusHSquared_data();
    void implicitEulerEnergyShrinksByOnePlusHSquared();
    void symplecticEulerEnergyBounded();
    void velocityVerletEnergyBounded();
    void implicitMidpointConservesEnergy();
};

// Explicit Euler's step is [[1, h], [−h, 1]] = √(1 + h²)·R(−atan h):
// x_N = (1 + h²)^{N/2}·cos(N·atan h).
void TestOscillatorClosedForm::explicitEulerClosedForm() {
    for (double h : {0.1, 1.0 / 60.0})
        checkRotationClosedForm("explicit_euler", h, std::sqrt(1.0 + h * h), std::atan(h), 500,
                                1e-12);
}

// Backward Euler's step is [[1, h], [−h, 1]]⁻¹ applied the other way round:
// x_N = (1 + h²)^{−N/2}·cos(N·atan h). The spring is linear, so the single Newton iteration
// of the default (Baraff & Witkin) is the exact backward Euler step. The runs stop while the
// amplitude is still above 1e-6: the spring deliberately exerts no force below a length of
// 1e-12 (its direction is undefined there), which a longer run would reach.
void TestOscillatorClosedForm::implicitEulerClosedForm() {
    checkRotationClosedForm("implicit_euler", 0.1, 1.0 / std::sqrt(1.01), std::atan(0.1), 500,
                            1e-12);
    checkRotationClosedForm("implicit_euler", 0.5, 1.0 / std::sqrt(1.25), std::atan(0.5), 100,
                            1e-12);
}

// The implicit midpoint rule is the Cayley transform of hJ: a pure rotation by 2·atan(h/2).
void TestOscillatorClosedForm::implicitMidpointClosedForm() {
    for (double h : {0.1, 0.5})
        checkRotationClosedForm("implicit_midpoint", h, 1.0, 2.0 * std::atan(h / 2.0), 500, 1e-12);
}

void TestOscillatorClosedForm::symplecticAndVerletChebyshevClosedForm_data() {
    QTest::addColumn<QString>("integrator");
    QTest::newRow("symplectic_euler") << QString("symplectic_euler");
    QTest::newRow("velocity_verlet") << QString("velocity_verlet");
}

// Both steps have determinant 1 and trace 2 − h², so with cos θ = 1 − h²/2 the Cayley–Hamilton
// theorem gives M^N = (sin(Nθ)·M − sin((N − 1)θ)·I) / sin θ.
void TestOscillatorClosedForm::symplecticAndVerletChebyshevClosedForm() {
    QFETCH(QString, integrator);
    const double h = 0.1;
    const Mat m = stepMatrix(integrator.toStdString(), h);
    QVERIFY(std::abs(m.determinant() - 1.0) < 1e-15);
    const double theta = std::acos(1.0 - h * h / 2.0);
    auto world = oscillator(integrator.toStdString(), h);
    for (int n = 1; n <= 1000; ++n) {
        QVERIFY(world->step());
        const Mat mn = (std::sin(n * theta) * m - std::sin((n - 1) * theta) * Mat::Identity()) /
                       std::sin(theta);
        const double dev = relativeDeviation(*world, mn * kXStart, mn * kYStart);
        QVERIFY2(dev <= 1e-12,
                 qPrintable(QString("step %1: relative deviation %2").arg(n).arg(dev)));
    }
}

void TestOscillatorClosedForm::stepMatrixPowers_data() {
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<double>("h");
    QTest::addColumn<int>("steps");
    // At h = 0.7 explicit Euler's energy grows 1.49× per step and implicit Euler's amplitude
    // shrinks likewise; 40 steps keep implicit Euler far from the spring's 1e-12 length
    // cut-off. Explicit Euler's drift (1.49^n) passes 10³·E₀ before step 40, which CONTRACT §2
    // calls a divergence: it is checked to step 16.
    for (const char* name : {"explicit_euler", "symplectic_euler", "midpoint", "heun", "rk4",
                             "velocity_verlet", "implicit_euler", "implicit_midpoint"}) {
        const int steps = std::string(name) == "explicit_euler" ? 16 : 40;
        QTest::newRow(qPrintable(QString("%1 h=0.1").arg(name))) << QString(name) << 0.1 << 200;
        QTest::newRow(qPrintable(QString("%1 h=0.7").arg(name))) << QString(name) << 0.7 << steps;
    }
}

// Every fixed-step method against its own step matrix raised to the N-th power: this pins
// down each method's formula (a wrong stage weight changes M), not just its order.
void TestOscillatorClosedForm::stepMatrixPowers() {
    QFETCH(QString, integrator);
    QFETCH(double, h);
    QFETCH(int, steps);
    const Mat m = stepMatrix(integrator.toStdString(), h);
    auto world = oscillator(integrator.toStdString(), h);
    int done = 0;
    for (int checkpoint : {1, 2, 3, 10, 37, steps}) {
        if (checkpoint > steps) continue;
        for (; done < checkpoint; ++done) QVERIFY(world->step());
        const Mat mn = power(m, checkpoint);
        const double dev = relativeDeviation(*world, mn * kXStart, mn * kYStart);
        QVERIFY2(
            dev <= 1e-12,
            qPrintable(QString("after %1 steps: relative deviation %2").arg(checkpoint).arg(dev)));
    }
}

// E_{n+1} = (1 + h²)·E_n exactly: |M·y|² = (1 + h²)·|y|² for M = [[1, h], [−h, 1]].
void TestOscillatorClosedForm::explicitEulerEnergyGrowsByOnePlusHSquared() {
    const double h = 0.05;
    auto world = oscillator("explicit_euler", h);
    const double e0 = mechanicalEnergy(*world);
    QCOMPARE(e0, 0.5 * (1.0 + 0.25));
    double previous = e0;
    for (int n = 1; n <= 400; ++n) {
        QVERIFY(world->step());
        const double e = mechanicalEnergy(*world);
        QVERIFY2(std::abs(e / previous - (1.0 + h * h)) < 1e-13,
                 qPrintable(QString("step %1: ratio %2").arg(n).arg(e / previous, 0, 'g', 17)));
        // No non-conservative force: the ledger's drift is exactly the energy gained.
        QCOMPARE(world->energy().workNc, 0.0);
        QVERIFY(std::abs(world->energy().drift - (e - e0)) <= 1e-13 * e);
        previous = e;
    }
    QVERIFY(std::abs(previous / e0 - std::pow(1.0 + h * h, 400)) < 1e-11);
}

void TestOscillatorClosedForm::implicitEulerEnergyShrinksByOnePlusHSquared_data() {
    QTest::addColumn<int>("newtonIterations");
    QTest::newRow("newton_iterations=1") << 1;
    QTest::newRow("newton_iterations=4") << 4;
}

// E_{n+1} = E_n / (1 + h²) for backward Euler; on a linear spring extra Newton iterations find
// nothing left to correct, so the factor is the same.
void TestOscillatorClosedForm::implicitEulerEnergyShrinksByOnePlusHSquared() {
    QFETCH(int, newtonIterations);
    const double h = 0.2;
    auto world = oscillator("implicit_euler", h, newtonIterations);
    QCOMPARE(world->settings().newtonIterations, newtonIterations);
    double previous = mechanicalEnergy(*world);
    for (int n = 1; n <= 300; ++n) {
        QVERIFY(world->step());
        const double e = mechanicalEnergy(*world);
        QVERIFY2(std::abs(e / previous * (1.0 + h * h) - 1.0) < 1e-13,
                 qPrintable(QString("step %1: ratio %2").arg(n).arg(e / previous, 0, 'g', 17)));
        previous = e;
    }
}

// Symplectic Euler conserves the modified energy Q = x² − h·x·v + v² exactly (per coordinate),
// so E = ½Q + (h/2)·Σx·v with |Σx·v| ≤ E stays within a factor (1 ± h/2)/(1 ∓ h/2) of E₀:
// |E − E₀| ≤ h/(1 − h/2)·E₀ for ever, and no secular drift.
void TestOscillatorClosedForm::symplecticEulerEnergyBounded() {
    const double h = 0.05;
    const int steps = 100000;
    auto world = oscillator("symplectic_euler", h);
    const auto modified = [&] {
        const Eigen::VectorXd& x = world->positions();
        const Eigen::VectorXd& v = world->velocities();
        return x.squaredNorm() - h * x.dot(v) + v.squaredNorm();
    };
    const double e0 = mechanicalEnergy(*world), q0 = modified();
    double firstWindow = 0.0, lastWindow = 0.0, worst = 0.0;
    for (int n = 1; n <= steps; ++n) {
        QVERIFY(world->step());
        const double deviation = std::abs(mechanicalEnergy(*world) - e0);
        worst = std::max(worst, deviation);
        if (n <= steps / 10) firstWindow = std::max(firstWindow, deviation);
        if (n > steps - steps / 10) lastWindow = std::max(lastWindow, deviation);
    }
    // Round-off only: a few ulps per step, 1e5 steps.
    QVERIFY2(std::abs(modified() - q0) <= 1e-10 * q0,
             qPrintable(QString("modified energy moved by %1").arg(modified() - q0)));
    QVERIFY2(worst <= h / (1.0 - h / 2.0) * e0,
             qPrintable(QString("max |E − E0| = %1, bound %2").arg(worst).arg(h * e0)));
    // The oscillation is real (O(h), not round-off), and it does not grow.
    QVERIFY(firstWindow > 0.1 * h * e0);
    QVERIFY2(lastWindow <= 1.1 * firstWindow,
             qPrintable(QString("first 10%: %1, last 10%: %2").arg(firstWindow).arg(lastWindow)));
    QVERIFY(std::abs(world->energy().drift - (mechanicalEnergy(*world) - e0)) < 1e-12);
    QVERIFY(world->energy().maxAbsDrift >= worst * (1.0 - 1e-12));
}

// Velocity Verlet conserves Q = (1 − h²/4)·x² + v² exactly, so E = ½Q + (h²/8)·Σx² and
// |E − E₀| ≤ (h²/4)/(1 − h²/4)·E₀: second order, bounded for ever.
void TestOscillatorClosedForm::velocityVerletEnergyBounded() {
    const double h = 0.1;
    const int steps = 100000;
    auto world = oscillator("velocity_verlet", h);
    const auto modified = [&] {
        return (1.0 - h * h / 4.0) * world->positions().squaredNorm() +
               world->velocities().squaredNorm();
    };
    const double e0 = mechanicalEnergy(*world), q0 = modified();
    double firstWindow = 0.0, lastWindow = 0.0, worst = 0.0;
    for (int n = 1; n <= steps; ++n) {
        QVERIFY(world->step());
        const double deviation = std::abs(mechanicalEnergy(*world) - e0);
        worst = std::max(worst, deviation);
        if (n <= steps / 10) firstWindow = std::max(firstWindow, deviation);
        if (n > steps - steps / 10) lastWindow = std::max(lastWindow, deviation);
    }
    QVERIFY2(std::abs(modified() - q0) <= 1e-10 * q0,
             qPrintable(QString("modified energy moved by %1").arg(modified() - q0)));
    const double bound = (h * h / 4.0) / (1.0 - h * h / 4.0) * e0;
    QVERIFY2(worst <= bound,
             qPrintable(QString("max |E − E0| = %1, bound %2").arg(worst).arg(bound)));
    QVERIFY(firstWindow > 0.1 * bound);
    QVERIFY2(lastWindow <= 1.1 * firstWindow,
             qPrintable(QString("first 10%: %1, last 10%: %2").arg(firstWindow).arg(lastWindow)));
}

// The implicit midpoint rule conserves every quadratic invariant, so a linear spring's energy
// is kept to round-off even at a step far too large for accuracy.
void TestOscillatorClosedForm::implicitMidpointConservesEnergy() {
    const double h = 0.5;
    auto world = oscillator("implicit_midpoint", h);
    const double e0 = mechanicalEnergy(*world);
    for (int n = 1; n <= 1000; ++n) {
        QVERIFY(world->step());
        const double e = mechanicalEnergy(*world);
        QVERIFY2(
            std::abs(e - e0) < 1e-12 * e0,
            qPrintable(QString("step %1: |E − E0|/E0 = %2").arg(n).arg(std::abs(e - e0) / e0)));
    }
    QVERIFY(std::abs(world->energy().drift) < 1e-12 * e0);
    QVERIFY(world->energy().maxAbsDrift < 1e-12 * e0);
    // It did move: 1000 steps of 2·atan(1/4) each is many turns.
    QVERIFY(std::abs(world->positions()[0] - std::cos(1000 * 2.0 * std::atan(0.25))) < 1e-9);
}

QTEST_APPLESS_MAIN(TestOscillatorClosedForm)
#include "tst_oscillator_closed_form.moc"
