#pragma once
// Jacobi's elliptic sine, for the closed forms of pendulums (the Accuracy Lab's reference, the
// exact overlay, the tests): θ(t) = 2·asin(k·sn(ω0·t + φ, k)) with k = sin(θ0/2).

#include <cmath>

namespace phasebox {

// sn(u, k), 0 ≤ k < 1, by the arithmetic–geometric mean and the descending Landen
// transformation (Abramowitz & Stegun 16.4), to about 1e-15.
inline double jacobiSn(double u, double k) {
    if (k == 0.0) return std::sin(u);
    double a[16], c[16];
    a[0] = 1.0;
    double b = std::sqrt(1.0 - k * k);
    c[0] = k;
    int n = 0;
    while (n < 15 && std::abs(c[n]) > 1e-16) {
        a[n + 1] = 0.5 * (a[n] + b);
        c[n + 1] = 0.5 * (a[n] - b);
        b = std::sqrt(a[n] * b);
        ++n;
    }
    double phi = std::ldexp(a[n] * u, n);
    for (int i = n; i > 0; --i) phi = 0.5 * (phi + std::asin(c[i] / a[i] * std::sin(phi)));
    return std::sin(phi);
}

}  // namespace phasebox
