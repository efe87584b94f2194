// The adaptive methods' work bound (core/WorkUnits.h): a frame's evaluations times the scene's
// work units. The bound is a time estimate, so it must count what an evaluation costs (a joint
// or rigid body as kCostlyWorkUnits particles), not the coordinates: a scene of few coordinates
// and costly evaluations (a long chain of rods) otherwise ran a frame for minutes before the
// method gave up. The same stiff oscillator is stepped with the units of a small scene and of a
// large one; only the large one reaches the bound, and gives up at once.

#include "physics/core/OdeSystem.h"
#include "physics/core/WorkUnits.h"
#include "physics/integrators/Integrator.h"

#include <QElapsedTimer>
#include <QTest>

#include <string>

using namespace phasebox;

namespace {

// x'' = −ω²·x for one coordinate, claiming `units` of work an evaluation.
class StiffOscillator final : public OdeSystem {
public:
    StiffOscillator(double omega, double units) : omega2_(omega * omega), units_(units) {
        mass_ = Vec::Ones(1);
    }
    int dimension() const override { return 1; }
    const Vec& inverseMass() const override { return mass_; }
    const Vec& mass() const override { return mass_; }
    double workUnits() const override { return units_; }
    double acceleration(double, const Vec& q, const Vec&, Vec& accel) override {
        ++evaluations;
        accel[0] = -omega2_ * q[0];
        return 0.0;
    }
    double nonConservativePower(double, const Vec&, const Vec&) override { return 0.0; }
    double forces(double t, const Vec& q, const Vec& u, Vec& force) override {
        return acceleration(t, q, u, force);
    }
    double forcesAndJacobians(double t, const Vec& q, const Vec& u, Vec& force,
                              ForceJacobians&) override {
        return acceleration(t, q, u, force);
    }
    long long evaluations = 0;

private:
    double omega2_, units_;
    Vec mass_;
};

}  // namespace

class TestAdaptiveWork : public QObject {
    Q_OBJECT

private slots:
    void boundCountsTheWorkOfAnEvaluation() {
        for (const char* name : {"adaptive_euler", "rk45"}) {
            // ω·h = 10 at dt 1/60: each method needs hundreds of internal steps a frame.
            const auto stepOnce = [&](double units, long long* evaluations) {
                StiffOscillator system(600.0, units);
                auto method = makeIntegrator(name);
                method->reset(1);
                Vec q0 = Vec::Ones(1), u0 = Vec::Zero(1), q(1), u(1);
                double work = 0.0;
                const bool ok = method->step(system, 0.0, 1.0 / 60.0, q0, u0, q, u, work);
                *evaluations = system.evaluations;
                return ok;
            };
            long long small = 0, large = 0;
            QVERIFY2(stepOnce(1.0, &small), name);
            QVERIFY(small > 100);
            // Units that make even a tenth of those evaluations exceed the bound.
            const double units = 10.0 * kMaxEvaluationWork / static_cast<double>(small);
            QVERIFY2(!stepOnce(units, &large), name);
            qInfo(
                "%s: %lld evaluations for a frame of a small scene; at %.3g units it gave up "
                "after %lld",
                name, small, units, large);
            QVERIFY(large * units <= kMaxEvaluationWork + 6.0 * units);
        }
    }
};

QTEST_APPLESS_MAIN(TestAdaptiveWork)
#include "tst_adaptive_work.moc"
