#pragma once
// cos and sin of one angle together, without the C library's call.
//
// Every turning body's rotation is taken once a step or more (the joints' rows, the contacts'
// shapes), and glibc's sin, cos and sincos save and restore the rounding mode on each call:
// on the 100-link chain of bench_box2d_chain that was 5% of the step. Here the angle is reduced
// by π/2 in three parts (Cody and Waite; the first two products are exact while the multiple
// of π/2 stays below 2¹⁹) and fdlibm's kernels give cos and sin on [−π/4, π/4], within an ulp
// there. Beyond kCosSinReach (and for infinities and NaN) the library's functions answer.
// The same instructions on every platform give the same bits, as Box2D v3's own cosine and
// sine do for its cross-platform determinism.

#include <cmath>
#include <cstdint>

namespace phasebox {

struct CosSin {
    double c;
    double s;
};

// |x| below this (about 2¹⁹·π/2) is reduced here.
inline constexpr double kCosSinReach = 8.0e5;

inline CosSin cosSin(double x) {
    if (!(std::abs(x) < kCosSinReach)) return {std::cos(x), std::sin(x)};
    if (std::abs(x) < 0x1p-27) return {1.0, x};  // exact to rounding there (and sin(−0) = −0)
    constexpr double twoOverPi = 6.36619772367581382433e-01;
    constexpr double pio2Part1 = 1.57079632673412561417e+00;  // π/2's first 33 bits
    constexpr double pio2Part2 = 6.07710050630396597660e-11;  // its next 33 bits
    constexpr double pio2Part3 = 2.02226624879595063154e-21;  // π/2 − the two above
    constexpr double roundingShift = 6755399441055744.0;      // 1.5·2⁵²: adds to integer
    const double k = (x * twoOverPi + roundingShift) - roundingShift;  // nearest integer
    const double r = ((x - k * pio2Part1) - k * pio2Part2) - k * pio2Part3;
    const double z = r * r;
    // fdlibm's __kernel_sin and __kernel_cos (the reduced angle's tail left out).
    const double sinR =
        r +
        r * z *
            (-1.66666666666666324348e-01 +
             z * (8.33333333332248946124e-03 +
                  z * (-1.98412698298579493134e-04 +
                       z * (2.75573137070700676789e-06 +
                            z * (-2.50507602534068634195e-08 + z * 1.58969099521155010221e-10)))));
    const double poly =
        z * (4.16666666666666019037e-02 +
             z * (-1.38888888888741095749e-03 +
                  z * (2.48015872894767294178e-05 +
                       z * (-2.75573143513906633035e-07 +
                            z * (2.08757232129817482790e-09 + z * -1.13596475577881948265e-11)))));
    const double half = 0.5 * z;
    const double w = 1.0 - half;
    const double cosR = w + (((1.0 - w) - half) + z * poly);
    switch (static_cast<std::int64_t>(k) & 3) {
        case 0:
            return {cosR, sinR};
        case 1:
            return {-sinR, cosR};
        case 2:
            return {-cosR, -sinR};
        default:
            return {sinR, -cosR};
    }
}

}  // namespace phasebox
