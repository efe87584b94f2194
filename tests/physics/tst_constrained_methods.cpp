// Each method is the method it is named after on a jointed scene (CONTRACT §3, §6): the
// constraint forces belong to the method's step. On a rod pendulum, against the exact
// (elliptic) solution θ(t) = 2·asin(k·sn(K(k) − ω0·t, k)), k = sin(θ0/2), the eight fixed-step
// methods converge with their theoretical order, and implicit Euler, which takes the rod's force
// at the step's end, damps the pendulum as backward Euler damps it in its angle, where
// symplectic Euler keeps its energy.

#include "JointTestSupport.h"

#include "physics/core/Elliptic.h"
#include "physics/integrators/Integrator.h"
#include "physics/world/World.h"

#include <QTest>

#include <cmath>
#include <vector>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

// A 1 m rod pendulum of a 1 kg bob released from rest at θ0 (from straight down).
SceneDesc rodPendulum(const char* integrator, double dt, double theta0) {
    SceneDesc s = scene(integrator, dt);
    s.particles = {particle("bob", {std::sin(theta0), -std::cos(theta0)})};
    s.particles[0].radius = 0.0;
    JointDesc rod = joint(JointType::Rod, "bob");
    rod.anchor = Point2{0.0, 0.0};
    s.joints = {rod};
    return s;
}

// The largest |θ − θ_exact| over a run of `duration`.
double angleError(const char* integrator, double dt, double theta0, double duration) {
    auto world = buildWorld(rodPendulum(integrator, dt, theta0)).world;
    const double k = std::sin(0.5 * theta0);
    const double K = std::comp_ellint_1(k);
    const double omega0 = std::sqrt(kG / 1.0);
    double worst = 0.0;
    while (world->time() < duration - 0.5 * dt) {
        if (!world->step()) return std::numeric_limits<double>::infinity();
        const Vec2 p = world->particlePosition(0);
        const double theta = std::atan2(p.x(), -p.y());
        const double exact = 2.0 * std::asin(k * jacobiSn(K - omega0 * world->time(), k));
        worst = std::max(worst, std::abs(theta - exact));
    }
    return worst;
}

}  // namespace

class TestConstrainedMethods : public QObject {
    Q_OBJECT
private slots:
    // The closed form itself: sn against its special values and the period.
    void ellipticSolutionIsExact() {
        const double k = std::sin(0.5 * 10.0 * kPi / 180.0);
        const double K = std::comp_ellint_1(k);
        QVERIFY(std::abs(jacobiSn(K, k) - 1.0) < 1e-15);
        QVERIFY(std::abs(jacobiSn(0.0, k)) < 1e-15);
        QVERIFY(std::abs(jacobiSn(0.3, 0.0) - std::sin(0.3)) < 1e-15);
        // sn² + cn² = 1 with cn from the incomplete integral: F(φ, k) = u ⇔ sn(u) = sin φ.
        const double phi = 0.7;
        QVERIFY(std::abs(jacobiSn(std::ellint_1(k, phi), k) - std::sin(phi)) < 1e-14);
    }

    // Over 10 s of a 10° swing at dt 1/120 to 1/960 each halving of dt divides the largest
    // angle error by 2^p, p the method's order, within 0.2.
    void rodPendulumConvergesWithTheMethodsOrder_data() {
        QTest::addColumn<QString>("integrator");
        for (const IntegratorInfo& info : integratorRegistry())
            if (!info.adaptive)
                QTest::newRow(std::string(info.name).c_str()) << QString::fromLatin1(
                    info.name.data(), static_cast<qsizetype>(info.name.size()));
    }
    void rodPendulumConvergesWithTheMethodsOrder() {
        QFETCH(QString, integrator);
        const IntegratorInfo* info = findIntegrator(integrator.toStdString());
        QVERIFY(info);
        const double theta0 = 10.0 * kPi / 180.0;
        std::vector<double> errors;
        for (double dt : {1.0 / 120, 1.0 / 240, 1.0 / 480, 1.0 / 960})
            errors.push_back(angleError(qPrintable(integrator), dt, theta0, 10.0));
        QString orders;
        double worst = 0.0;
        for (std::size_t i = 1; i < errors.size(); ++i) {
            const double observed = std::log2(errors[i - 1] / errors[i]);
            orders += QString(" %1").arg(observed, 0, 'f', 3);
            worst = std::max(worst, std::abs(observed - info->order));
        }
        qInfo("%s: largest angle error %.3e .. %.3e rad, orders%s (theory %d)",
              qPrintable(integrator), errors.front(), errors.back(), qPrintable(orders),
              info->order);
        QVERIFY2(worst <= 0.2, qPrintable(orders));
    }

    // A rod pendulum released level with its pivot (dt 1/60, 30 s): implicit Euler loses more
    // than half its energy, as backward Euler does on the pendulum in its angle; symplectic
    // Euler, the same step with the rod's force at the step's start, keeps it within 5%; and
    // the two trajectories differ.
    void implicitEulerDampsTheRodPendulum() {
        auto implicitRun = buildWorld(rodPendulum("implicit_euler", 1.0 / 60, 0.5 * kPi)).world;
        auto symplecticRun = buildWorld(rodPendulum("symplectic_euler", 1.0 / 60, 0.5 * kPi)).world;
        const double e0 = implicitRun->kineticEnergy() + implicitRun->potentialEnergy();
        const double swing = kG * 1.0;  // J: from level with the pivot to the bottom
        double gained = 0.0, apart = 0.0;
        while (implicitRun->time() < 30.0 - 1e-9) {
            QVERIFY(implicitRun->step());
            QVERIFY(symplecticRun->step());
            gained = std::max(gained,
                              implicitRun->kineticEnergy() + implicitRun->potentialEnergy() - e0);
            apart = std::max(
                apart,
                (implicitRun->particlePosition(0) - symplecticRun->particlePosition(0)).norm());
        }
        const double implicitLoss =
            e0 - implicitRun->kineticEnergy() - implicitRun->potentialEnergy();
        const double symplecticChange =
            symplecticRun->kineticEnergy() + symplecticRun->potentialEnergy() - e0;
        qInfo(
            "90 deg rod pendulum, 30 s at 1/60: implicit Euler lost %.3f J of %.3f J (never "
            "gained more than %.1e J), symplectic Euler changed by %.3f J; %.3f m apart at most",
            implicitLoss, swing, gained, symplecticChange, apart);
        QVERIFY(implicitLoss > 0.5 * swing);
        QVERIFY(gained < 1e-9);
        QVERIFY(std::abs(symplecticChange) < 0.05 * swing);
        QVERIFY(apart > 0.1);
        // The books say where it went: the method's own error, not a force's work.
        QVERIFY(std::abs(implicitRun->energy().workNc) < 1e-12);
        QVERIFY(implicitRun->energy().drift < -0.5 * swing);
    }
};

QTEST_APPLESS_MAIN(TestConstrainedMethods)
#include "tst_constrained_methods.moc"
