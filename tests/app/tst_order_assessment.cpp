// What the Accuracy Lab says about a measured order (app/accuracy/OrderAssessment): on studies
// made up here, whose errors follow a law chosen by the test, the order is measured on the pairs
// of steps in the asymptotic range only, and round-off, instability, too few steps and errors
// that cancel are each recognised and explained.

#include "app/accuracy/OrderAssessment.h"

#include <QTest>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

using namespace phasebox;

namespace {

const std::vector<double> kDts = {1.0 / 60, 1.0 / 120, 1.0 / 240, 1.0 / 480, 1.0 / 960, 1.0 / 1920};

// A study of one fixed-step method whose error at dt is error(dt) (∞ = the run diverged).
AccuracyResult study(const std::string& integrator, const std::function<double(double)>& error,
                     const std::vector<double>& dts = kDts) {
    AccuracyResult result;
    result.reference = "exact: test";
    result.referenceExact = true;
    result.positionScale = 1.0;
    for (double dt : dts) {
        AccuracyRecord r;
        r.integrator = integrator;
        r.dt = dt;
        r.positionError = error(dt);
        r.diverged = std::isinf(r.positionError);
        result.records.push_back(r);
    }
    return result;
}

// The same with the errors listed, one per step of kDts.
AccuracyResult study(const std::string& integrator, const std::vector<double>& errors) {
    return study(integrator, [&](double dt) {
        for (std::size_t i = 0; i < kDts.size(); ++i)
            if (kDts[i] == dt) return errors[i];
        return std::numeric_limits<double>::quiet_NaN();
    });
}

OrderAssessment only(const AccuracyResult& result) {
    const std::vector<OrderAssessment> all = assessOrders(result);
    if (all.size() != 1) qFatal("one integrator expected, got %zu", all.size());
    return all.front();
}

bool contains(const std::string& text, const char* part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

class TestOrderAssessment : public QObject {
    Q_OBJECT

private slots:
    void cleanFourthOrderIsAsExpected() {
        // 1e3·dt⁴ falls to 7e-11 at the finest step: small, but still falling at the method's
        // own rate, so no floor is claimed.
        const OrderAssessment a =
            only(study("rk4", [](double dt) { return 1e3 * std::pow(dt, 4); }));
        QCOMPARE(a.theory, 4);
        QVERIFY(a.measured && std::abs(*a.measured - 4.0) < 1e-9);
        QCOMPARE(a.kind, OrderAssessment::Kind::AsExpected);
        QCOMPARE(a.pairsInRange, 5);
        QVERIFY(!a.floorFromDt && !a.unstableUpToDt);
        QVERIFY(contains(a.note, "as expected"));
    }

    void roundOffFloorIsLeftOutAndNamed() {
        // RK4 falling like dt⁴ until 1/480, then at the floor of a few 1e-13: the pair into the
        // floor measures 3.17 and the last one −0.37 (rounding wanders up and down), so the
        // median of every pair would say 3.6.
        const std::vector<double> e = {1.5e-8, 9.4e-10, 5.9e-11, 3.7e-12, 4.1e-13, 5.3e-13};
        const AccuracyResult result = study("rk4", e);
        const OrderAssessment a = only(result);
        QVERIFY(a.floorFromDt);
        QCOMPARE(formatStep(*a.floorFromDt), std::string("1/960"));
        QVERIFY(!a.unstableUpToDt);  // the floor's wobble is not instability
        QCOMPARE(a.pairsInRange, 3);
        QVERIFY(a.measured && std::abs(*a.measured - 4.0) < 0.02);
        QCOMPARE(a.kind, OrderAssessment::Kind::AsExpected);
        QVERIFY(contains(a.note, "round-off floor reached at dt ≤ 1/960"));
        QVERIFY(contains(a.explanation, "rounding errors"));
    }

    void floorOfAnRk45ReferenceIsNamedAsSuch() {
        AccuracyResult result =
            study("rk4", [](double dt) { return std::max(0.2 * std::pow(dt, 4), 2e-10); });
        result.referenceExact = false;
        result.reference = "rk45 tol 1e-12";
        const OrderAssessment a = only(result);
        QVERIFY(a.floorFromDt);
        QVERIFY(contains(a.note, "reference's accuracy"));
        QVERIFY(!contains(a.note, "round-off"));
    }

    void growingErrorAtLargeStepsIsUnstable() {
        // Explicit Euler whose coarsest step is unstable: the error there is smaller than at
        // the next (order −1.7), then halves with every halving of dt.
        const std::vector<double> e = {0.5, 1.6, 0.8, 0.4, 0.2, 0.1};
        const AccuracyResult result = study("explicit_euler", e);
        const OrderAssessment a = only(result);
        QVERIFY(a.unstableUpToDt);
        QCOMPARE(formatStep(*a.unstableUpToDt), std::string("1/60"));
        QVERIFY(a.measured && std::abs(*a.measured - 1.0) < 1e-9);
        QCOMPARE(a.pairsInRange, 4);
        QVERIFY(contains(a.note, "unstable at dt ≥ 1/60"));
        QVERIFY(contains(a.explanation, "grew instead of shrinking"));
    }

    void divergedRunsAreUnstable() {
        // Blows up at the two largest steps, second order below.
        const AccuracyResult partly = study("velocity_verlet", [](double dt) {
            return dt > 1.0 / 200 ? std::numeric_limits<double>::infinity() : 50.0 * dt * dt;
        });
        const OrderAssessment a = only(partly);
        QCOMPARE(a.diverged, 2);
        QCOMPARE(formatStep(*a.unstableUpToDt), std::string("1/120"));
        QVERIFY(a.measured && std::abs(*a.measured - 2.0) < 1e-9);
        QVERIFY(contains(a.explanation, "blew up"));

        const OrderAssessment all = only(study(
            "explicit_euler", [](double) { return std::numeric_limits<double>::infinity(); }));
        QCOMPARE(all.kind, OrderAssessment::Kind::Unstable);
        QVERIFY(!all.measured);
        QVERIFY(contains(all.note, "unstable"));
    }

    void coarseStepsOutsideTheAsymptoticRangeAreLeftOut() {
        // RK4 on a stiff spring (the stiff-spring example at 1 s): diverged at 1/60, slopes 0.93
        // and 0.10 while ω·dt is still about 1, then 3.80 and 4.06.
        const std::vector<double> e = {std::numeric_limits<double>::infinity(),
                                       4.214e-05,
                                       2.210e-05,
                                       2.064e-05,
                                       1.485e-06,
                                       8.911e-08};
        const OrderAssessment a = only(study("rk4", e));
        QCOMPARE(formatStep(*a.unstableUpToDt), std::string("1/60"));
        QCOMPARE(formatStep(*a.preAsymptoticUpToDt), std::string("1/240"));
        QCOMPARE(a.pairsInRange, 2);
        QVERIFY(a.measured && std::abs(*a.measured - 3.93) < 0.01);
        QCOMPARE(a.kind, OrderAssessment::Kind::AsExpected);
        QVERIFY(contains(a.note, "dt ≥ 1/240 too large"));
        QVERIFY(contains(a.explanation, "asymptotic range"));
    }

    void tooFewAndNotAsymptotic() {
        const OrderAssessment one = only(study("rk4", [](double dt) { return dt; }, {1.0 / 60}));
        QCOMPARE(one.kind, OrderAssessment::Kind::TooFewSteps);
        QVERIFY(!one.measured);

        // A fourth-order method measured at 2.6: the steps are too large for dt⁴ to decide.
        const OrderAssessment early =
            only(study("rk4", [](double dt) { return std::pow(dt, 2.6); }));
        QCOMPARE(early.kind, OrderAssessment::Kind::NotAsymptotic);
        QVERIFY(contains(early.note, "not yet small enough"));

        const OrderAssessment high =
            only(study("explicit_euler", [](double dt) { return dt * dt; }));
        QCOMPARE(high.kind, OrderAssessment::Kind::ErrorsCancel);
    }

    void adaptiveAndContactsAreNotMeasured() {
        AccuracyResult adaptive = study("rk45", [](double dt) { return dt; });
        for (AccuracyRecord& r : adaptive.records) r.tolerance = 1e-6;
        QCOMPARE(only(adaptive).kind, OrderAssessment::Kind::NotMeasured);
        AccuracyResult contacts = study("rk4", [](double dt) { return dt; });
        contacts.contacts = true;
        const OrderAssessment c = only(contacts);
        QCOMPARE(c.kind, OrderAssessment::Kind::NotMeasured);
        QVERIFY(contains(c.explanation, "contacts"));
    }
};

QTEST_APPLESS_MAIN(TestOrderAssessment)
#include "tst_order_assessment.moc"
