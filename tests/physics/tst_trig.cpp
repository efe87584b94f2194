// cosSin (physics/core/Trig.h) against the C library and against what cos and sin must be:
// within 2 ulp of glibc's values (its reduction leaves at most an ulp of the reduced angle, the
// kernels are within an ulp on [−π/4, π/4], and glibc's own are within one), exact where the
// answer is exact, the library's own answer beyond the reach, and NaN for NaN and infinities.

#include "physics/core/Trig.h"
#include "physics/core/Types.h"

#include <QTest>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

using namespace phasebox;

namespace {

// How many units in the last place of the exact value b lie between a and b.
double ulps(double a, double b) {
    const double magnitude = std::max(std::abs(b), std::numeric_limits<double>::min());
    const double ulp =
        std::nextafter(magnitude, std::numeric_limits<double>::infinity()) - magnitude;
    return std::abs(a - b) / ulp;
}

}  // namespace

class TestTrig : public QObject {
    Q_OBJECT

private slots:
    void matchesTheLibraryWithinTwoUlp_data() {
        QTest::addColumn<double>("low");
        QTest::addColumn<double>("high");
        QTest::newRow("a turn") << -7.0 << 7.0;
        QTest::newRow("a few hundred turns") << -2000.0 << 2000.0;
        QTest::newRow("up to the reach") << -kCosSinReach << kCosSinReach;
    }
    void matchesTheLibraryWithinTwoUlp() {
        QFETCH(double, low);
        QFETCH(double, high);
        std::mt19937_64 random(20261129);
        std::uniform_real_distribution<double> angle(low, high);
        double worst = 0.0;
        for (int i = 0; i < 200000; ++i) {
            const double x = angle(random);
            const CosSin t = cosSin(x);
            worst = std::max({worst, ulps(t.c, std::cos(x)), ulps(t.s, std::sin(x))});
        }
        qInfo("largest difference from glibc: %.2f ulp", worst);
        QVERIFY(worst <= 2.0);
    }

    // Next to the multiples of π/2, where one of the two nearly vanishes and the reduction must
    // keep its relative accuracy: every multiple up to 10⁵ and its neighbours either side.
    void keepsRelativeAccuracyNearMultiplesOfAQuarterTurn() {
        double worst = 0.0;
        for (int k = -100000; k <= 100000; ++k) {
            const double exact = k * (0.5 * std::numbers::pi);
            for (const double x :
                 {std::nextafter(exact, -1e9), exact, std::nextafter(exact, 1e9)}) {
                const CosSin t = cosSin(x);
                worst = std::max({worst, ulps(t.c, std::cos(x)), ulps(t.s, std::sin(x))});
            }
        }
        qInfo("largest difference from glibc: %.2f ulp", worst);
        QVERIFY(worst <= 2.0);
    }

    void smallAnglesAreExact() {
        std::mt19937_64 random(7);
        std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
        for (int e = 27; e < 1070; e += 7) {
            const double x = std::ldexp(mantissa(random), -e);
            const CosSin t = cosSin(x);
            QCOMPARE(t.c, 1.0);
            QCOMPARE(t.s, x);
        }
        const CosSin zero = cosSin(0.0), negativeZero = cosSin(-0.0);
        QCOMPARE(zero.c, 1.0);
        QVERIFY(zero.s == 0.0 && !std::signbit(zero.s));
        QCOMPARE(negativeZero.c, 1.0);
        QVERIFY(negativeZero.s == 0.0 && std::signbit(negativeZero.s));
    }

    void aUnitVector() {
        std::mt19937_64 random(11);
        std::uniform_real_distribution<double> angle(-1e4, 1e4);
        for (int i = 0; i < 100000; ++i) {
            const CosSin t = cosSin(angle(random));
            QVERIFY(std::abs(t.c * t.c + t.s * t.s - 1.0) <=
                    4.0 * std::numeric_limits<double>::epsilon());
        }
    }

    void beyondTheReachTheLibraryAnswers() {
        for (const double x : {kCosSinReach, -kCosSinReach, 1e6, -3.5e9, 1e300}) {
            const CosSin t = cosSin(x);
            QCOMPARE(t.c, std::cos(x));
            QCOMPARE(t.s, std::sin(x));
        }
        for (const double x :
             {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
              -std::numeric_limits<double>::infinity()}) {
            const CosSin t = cosSin(x);
            QVERIFY(std::isnan(t.c) && std::isnan(t.s));
        }
    }

    // rotation() takes its entries from cosSin: a quarter turn takes x̂ to ŷ.
    void rotationTurnsAQuarter() {
        const Vec2 y = rotation(0.5 * std::numbers::pi) * Vec2(1.0, 0.0);
        QVERIFY(std::abs(y.x()) < 1e-16);
        QCOMPARE(y.y(), 1.0);
    }
};

QTEST_GUILESS_MAIN(TestTrig)
#include "tst_trig.moc"
