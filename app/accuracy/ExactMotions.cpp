// The closed forms themselves: damped oscillators and free motion, Kepler orbits, pendulums
// (Jacobi's sn), and a ball bouncing on a plane under penalty or impulse contacts.

#include "app/accuracy/ExactReference.h"

#include "app/accuracy/ExactReferenceDetail.h"
#include "physics/core/Elliptic.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace phasebox {

using namespace exact_detail;

// y = x − f/ω² obeys y'' + γ·y' + ω²·y = 0, so y = e^{−αt}·(y₀·C(t) + B·S(t)) with α = γ/2,
// B = v₀ + α·y₀ and (C, S) = (cos βt, sin βt / β), (cosh κt, sinh κt / κ) or (1, t) for
// β² = ω² − α² positive, negative or zero. S(t) → t as β → 0, so the cases join smoothly.
double LinearMotion::at(double t) const {
    if (omega2 == 0.0) {
        if (gamma == 0.0) return x0 + v0 * t + 0.5 * force * t * t;
        // Velocity relaxes to the terminal f/γ; expm1 keeps small γ·t accurate.
        const double terminal = force / gamma;
        return x0 + terminal * t - (v0 - terminal) * std::expm1(-gamma * t) / gamma;
    }
    const double equilibrium = force / omega2;
    const double alpha = 0.5 * gamma;
    const double y0 = x0 - equilibrium;
    const double B = v0 + alpha * y0;
    const double beta2 = omega2 - alpha * alpha;
    double y = 0.0;
    if (beta2 > 0.0) {
        const double beta = std::sqrt(beta2);
        y = std::exp(-alpha * t) * (y0 * std::cos(beta * t) + B * std::sin(beta * t) / beta);
    } else if (beta2 < 0.0) {
        // Over-damped: e^{−αt}·cosh(κt) written as exponentials that cannot overflow (κ < α).
        const double kappa = std::sqrt(-beta2);
        const double slow = std::exp((kappa - alpha) * t), fast = std::exp(-(kappa + alpha) * t);
        const double c = 0.5 * (slow + fast);
        const double s = kappa * t < 1.0 ? std::exp(-alpha * t) * std::sinh(kappa * t) / kappa
                                         : 0.5 * (slow - fast) / kappa;
        y = y0 * c + B * s;
    } else {
        y = std::exp(-alpha * t) * (y0 + B * t);
    }
    return equilibrium + y;
}

double LinearMotion::lowerBound(double T) const {
    double lowest = std::min(at(0.0), at(T));
    if (omega2 == 0.0) {
        // Velocity v(t) = terminal + (v₀ − terminal)·e^{−γt} (or v₀ + f·t) changes sign at most
        // once: the extremum is there.
        double tStar = -1.0;
        if (gamma == 0.0 && force != 0.0) tStar = -v0 / force;
        if (gamma > 0.0 && force != 0.0 && v0 != force / gamma) {
            const double ratio = -(force / gamma) / (v0 - force / gamma);
            if (ratio > 0.0) tStar = -std::log(ratio) / gamma;
        }
        if (tStar > 0.0 && tStar < T) lowest = std::min(lowest, at(tStar));
        return lowest;
    }
    const double equilibrium = force / omega2;
    const double alpha = 0.5 * gamma;
    const double y0 = x0 - equilibrium;
    const double B = v0 + alpha * y0;
    const double beta2 = omega2 - alpha * alpha;
    if (beta2 > 0.0) {
        // |y| ≤ e^{−αt}·√(y₀² + (B/β)²) ≤ √(y₀² + (B/β)²): exact when undamped.
        return equilibrium - std::hypot(y0, B / std::sqrt(beta2));
    }
    // Critical or over-damped: y has at most one extremum; find it.
    double tStar = -1.0;
    if (beta2 == 0.0) {
        if (B != 0.0 && alpha > 0.0) tStar = 1.0 / alpha - y0 / B;
    } else {
        const double kappa = std::sqrt(-beta2);
        const double r1 = -alpha + kappa, r2 = -alpha - kappa;
        const double c1 = (v0 - r2 * y0) / (r1 - r2), c2 = y0 - c1;
        const double ratio = c1 * r1 != 0.0 ? -(c2 * r2) / (c1 * r1) : -1.0;
        if (ratio > 0.0) tStar = std::log(ratio) / (r1 - r2);
    }
    if (tStar > 0.0 && tStar < T) lowest = std::min(lowest, at(tStar));
    return lowest;
}

std::optional<KeplerMotion> KeplerMotion::fromState(const Vec2& centre, const Vec2& position,
                                                    const Vec2& velocity, double mu) {
    const Vec2 r = position - centre;
    const double radius = r.norm(), speed2 = velocity.squaredNorm();
    if (!(radius > 0.0) || !(mu > 0.0)) return std::nullopt;
    const double h = cross(r, velocity);
    // A radial orbit falls into the centre (a singularity the integrators cannot pass either).
    if (std::abs(h) <= 1e-10 * radius * std::sqrt(speed2)) return std::nullopt;
    const Vec2 eccentricity = ((speed2 - mu / radius) * r - r.dot(velocity) * velocity) / mu;
    KeplerMotion k;
    k.centre = centre;
    k.e = eccentricity.norm();
    // Near e = 1 both anomaly equations degenerate; a parabola is left to rk45.
    if (std::abs(k.e - 1.0) < 1e-6) return std::nullopt;
    if (k.e < 1e-13) k.e = 0.0;  // circular: the periapsis is wherever we start
    k.periapsis = k.e > 0.0 ? Vec2(eccentricity / k.e) : Vec2(r / radius);
    k.normal = h > 0.0 ? perp(k.periapsis) : Vec2(-perp(k.periapsis));
    const double x0 = r.dot(k.periapsis), y0 = r.dot(k.normal);
    const double semiMajor = 1.0 / (2.0 / radius - speed2 / mu);  // vis-viva; < 0: hyperbola
    k.hyperbolic = k.e > 1.0;
    k.a = std::abs(semiMajor);
    k.meanMotion = std::sqrt(mu / (k.a * k.a * k.a));
    if (!k.hyperbolic) {
        k.b = k.a * std::sqrt(1.0 - k.e * k.e);
        const double E0 = std::atan2(y0 / k.b, x0 / k.a + k.e);
        k.meanAnomaly0 = E0 - k.e * std::sin(E0);
    } else {
        k.b = k.a * std::sqrt(k.e * k.e - 1.0);
        const double H0 = std::asinh(y0 / k.b);
        k.meanAnomaly0 = k.e * std::sinh(H0) - H0;
    }
    return k;
}

Vec2 KeplerMotion::at(double t) const {
    if (!hyperbolic) {
        // Kepler's equation E − e·sin E = M by Newton's method, with M reduced to [−π, π] so
        // that many revolutions lose no accuracy; starting from π for eccentric orbits avoids
        // Newton's overshoot near the periapsis.
        const double M = std::remainder(meanAnomaly0 + meanMotion * t, kTwoPi);
        double E = e < 0.8 ? M : (M >= 0.0 ? std::numbers::pi : -std::numbers::pi);
        for (int i = 0; i < 100; ++i) {
            const double dE = (E - e * std::sin(E) - M) / (1.0 - e * std::cos(E));
            E -= dE;
            if (std::abs(dE) <= 1e-15 * std::max(1.0, std::abs(E))) break;
        }
        return centre + a * (std::cos(E) - e) * periapsis + b * std::sin(E) * normal;
    }
    // Hyperbolic: e·sinh H − H = M.
    const double M = meanAnomaly0 + meanMotion * t;
    double H = std::asinh(M / e);
    for (int i = 0; i < 200; ++i) {
        const double dH = (e * std::sinh(H) - H - M) / (e * std::cosh(H) - 1.0);
        H -= dH;
        if (std::abs(dH) <= 1e-15 * std::max(1.0, std::abs(H))) break;
    }
    return centre + a * (e - std::cosh(H)) * periapsis + b * std::sinh(H) * normal;
}

std::optional<PendulumMotion> PendulumMotion::fromState(const Vec2& centre, double length,
                                                        const Vec2& g, const Vec2& position,
                                                        const Vec2& velocity,
                                                        double equivalentLength) {
    const double gn = g.norm();
    if (!(length > 0.0) || !(gn > 0.0)) return std::nullopt;
    PendulumMotion m;
    m.centre = centre;
    m.length = length;
    m.down = g / gn;
    m.side = perp(m.down);
    m.omega0 = std::sqrt(gn / (equivalentLength > 0.0 ? equivalentLength : length));
    const Vec2 r = (position - centre) / length;
    const double theta = std::atan2(r.dot(m.side), r.dot(m.down));
    const double rate = velocity.dot(-std::sin(theta) * m.down + std::cos(theta) * m.side) / length;
    m.startAngle = theta;
    const double s0 = std::sin(0.5 * theta);
    // The energy fixes k: k² = sin²(θ₀/2) + θ'₀²/(4ω₀²).
    m.k = std::sqrt(s0 * s0 + rate * rate / (4.0 * m.omega0 * m.omega0));
    if (!(m.k < 1.0 - 1e-9)) return std::nullopt;  // over the top: not a libration
    if (m.k == 0.0) return m;                      // at rest at the bottom
    const double first = std::ellint_1(m.k, std::asin(std::clamp(s0 / m.k, -1.0, 1.0)));
    // sn rises on (−K, K): a pendulum swinging back starts in the mirrored half, 2K − φ.
    m.phase = rate >= 0.0 ? first : 2.0 * std::comp_ellint_1(m.k) - first;
    return m;
}

double PendulumMotion::angle(double t) const {
    return 2.0 * std::asin(std::clamp(k * jacobiSn(omega0 * t + phase, k), -1.0, 1.0));
}

Vec2 PendulumMotion::at(double t) const {
    const double theta = angle(t);
    return centre + length * (std::cos(theta) * down + std::sin(theta) * side);
}

namespace {
// The rate of a LinearMotion, by a central difference on its own time scale.
double rateOf(const LinearMotion& m, double t) {
    const double h = 1e-6 / std::max({std::sqrt(m.omega2), m.gamma, 1.0});
    return (m.at(t + h) - m.at(t - h)) / (2.0 * h);
}
}  // namespace

PenaltyBounceMotion PenaltyBounceMotion::impulse(double s0, double v0, double g, double radius,
                                                 double restitution, double threshold,
                                                 double endTime) {
    // Free flights s'' = −g joined at the impacts (s = r), where v ← −e·v; an impact slower
    // than threshold·(1 − e) does not bounce (ContactSettings::restitutionThreshold) and the
    // ball rests on the plane from then on.
    constexpr int kMaxPhases = 10000;
    PenaltyBounceMotion out;
    double t = 0.0, s = std::max(s0, radius), v = v0;
    while (static_cast<int>(out.phases.size()) < kMaxPhases) {
        out.phases.push_back({t, LinearMotion{0.0, 0.0, -g, s, v}, false});
        // When the flight comes down to s = r: r = s + v·τ − g·τ²/2.
        const double tau = (v + std::sqrt(v * v + 2.0 * g * (s - radius))) / g;
        if (!(t + tau < endTime) || !std::isfinite(tau)) break;
        t += tau;
        const double impact = v - g * tau;  // < 0
        s = radius;
        if (-impact <= threshold * (1.0 - restitution)) {
            out.phases.push_back({t, LinearMotion{0.0, 0.0, 0.0, radius, 0.0}, true});
            break;
        }
        v = -restitution * impact;
    }
    return out;
}

PenaltyBounceMotion PenaltyBounceMotion::fromState(double s0, double v0, double g, double radius,
                                                   double k, double c, double m, double endTime) {
    constexpr int kMaxPhases = 10000;
    PenaltyBounceMotion out;
    double t = 0.0, s = s0, v = v0;
    const double omega2 = k / m, gamma = c / m;
    while (t < endTime && static_cast<int>(out.phases.size()) < kMaxPhases) {
        if (s > radius || (s == radius && v >= 0.0)) {
            // Flight until the centre is back at one radius above the plane.
            const LinearMotion flight{0.0, 0.0, -g, s, v};
            out.phases.push_back({t, flight, false});
            double tau = 0.0;
            if (g > 0.0)
                tau = (v + std::sqrt(v * v + 2.0 * g * (s - radius))) / g;
            else if (v < 0.0)
                tau = (s - radius) / -v;
            else
                break;  // rising or still with nothing pulling it down
            t += tau;
            v -= g * tau;
            s = radius;
            continue;
        }
        // Contact: s'' + γ·s' + ω²·s = ω²·r − g, until s is back at r on its way up.
        const LinearMotion contact{omega2, gamma, omega2 * radius - g, s, v};
        out.phases.push_back({t, contact, true});
        const double step = 2.0 * std::numbers::pi / std::sqrt(omega2) / 400.0;
        double a = 0.0, b = -1.0;
        for (double tau = step; t + tau < endTime; tau += step)
            if (contact.at(tau) >= radius) {
                a = tau - step;
                b = tau;
                break;
            }
        if (b < 0.0) break;  // still in contact at the end (or come to rest)
        for (int i = 0; i < 80; ++i) {
            const double mid = 0.5 * (a + b);
            (contact.at(mid) >= radius ? b : a) = mid;
        }
        t += b;
        v = rateOf(contact, b);
        s = radius;
        if (v <= 0.0) break;  // touching the surface with no speed: rests from here
    }
    return out;
}

double PenaltyBounceMotion::height(double t) const {
    if (phases.empty()) return 0.0;
    auto phase = std::upper_bound(phases.begin(), phases.end(), t,
                                  [](double x, const Phase& p) { return x < p.start; });
    if (phase != phases.begin()) --phase;
    return phase->s.at(t - phase->start);
}

}  // namespace phasebox
