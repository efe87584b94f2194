#include "app/accuracy/ExactReference.h"

#include "physics/contacts/ContactModel.h"
#include "physics/contacts/ContactSolver.h"
#include "physics/core/EffectNames.h"
#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace phasebox {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Relative tolerance for "this vector lies along that axis": the along-axis closed form is
// exact only when the motion never leaves the axis, and a scene whose numbers merely come close
// (a velocity typed to six digits) must fall back to rk45 rather than be judged against a
// slightly wrong "exact" answer.
constexpr double kAlongAxis = 1e-12;

bool alongAxis(const Vec2& v, const Vec2& axis) {
    return std::abs(cross(v, axis)) <= kAlongAxis * std::max(1.0, v.norm());
}

}  // namespace

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

double jacobiSn(double u, double k) {
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

std::optional<PendulumMotion> PendulumMotion::fromState(const Vec2& centre, double length,
                                                        const Vec2& g, const Vec2& position,
                                                        const Vec2& velocity) {
    const double gn = g.norm();
    if (!(length > 0.0) || !(gn > 0.0)) return std::nullopt;
    PendulumMotion m;
    m.centre = centre;
    m.length = length;
    m.down = g / gn;
    m.side = perp(m.down);
    m.omega0 = std::sqrt(gn / length);
    const Vec2 r = (position - centre) / length;
    const double theta = std::atan2(r.dot(m.side), r.dot(m.down));
    const double rate = velocity.dot(-std::sin(theta) * m.down + std::cos(theta) * m.side) / length;
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

Vec2 PendulumMotion::at(double t) const {
    const double theta =
        2.0 * std::asin(std::clamp(k * jacobiSn(omega0 * t + phase, k), -1.0, 1.0));
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

Vec ExactReference::positions(double t) const {
    Vec q = Vec::Zero(dimension_);
    for (const Pendulum& p : pendulums_) q.segment<2>(p.dof) = p.motion.at(t);
    for (const Coordinate& c : coordinates_) q[c.dof] = c.motion.at(t);
    for (const AxisMotion& a : axes_) q.segment<2>(a.dof) = a.anchor + a.s.at(t) * a.axis;
    for (const Orbit& o : orbits_) q.segment<2>(o.dof) = o.orbit.at(t);
    for (const Bounce& b : bounces_) q.segment<2>(b.dof) = b.base + b.motion.height(t) * b.normal;
    for (const Modes& m : modes_)
        for (std::size_t i = 0; i < m.dofs.size(); ++i)
            q.segment<2>(m.dofs[i]) = m.origin + m.along(i, t) * m.axis;
    return q;
}

double ExactReference::Modes::along(std::size_t i, double t) const {
    double s = equilibrium[static_cast<Eigen::Index>(i)];
    for (Eigen::Index k = 0; k < omega.size(); ++k)
        s += shapes(static_cast<Eigen::Index>(i), k) *
             (a[k] * std::cos(omega[k] * t) + b[k] * std::sin(omega[k] * t) / omega[k]);
    return s;
}

double ExactReference::position(int dof, double t) const {
    for (const Pendulum& p : pendulums_)
        if (dof == p.dof || dof == p.dof + 1) return p.motion.at(t)[dof - p.dof];
    for (const Coordinate& c : coordinates_)
        if (dof == c.dof) return c.motion.at(t);
    for (const AxisMotion& a : axes_)
        if (dof == a.dof || dof == a.dof + 1)
            return a.anchor[dof - a.dof] + a.s.at(t) * a.axis[dof - a.dof];
    for (const Orbit& o : orbits_)
        if (dof == o.dof || dof == o.dof + 1) return o.orbit.at(t)[dof - o.dof];
    for (const Bounce& b : bounces_)
        if (dof == b.dof || dof == b.dof + 1)
            return b.base[dof - b.dof] + b.motion.height(t) * b.normal[dof - b.dof];
    for (const Modes& m : modes_)
        for (std::size_t i = 0; i < m.dofs.size(); ++i)
            if (dof == m.dofs[i] || dof == m.dofs[i] + 1)
                return m.origin[dof - m.dofs[i]] + m.along(i, t) * m.axis[dof - m.dofs[i]];
    return 0.0;
}

bool ExactReference::covers(int dof) const {
    const auto pair = [dof](int first) { return dof == first || dof == first + 1; };
    return std::any_of(pendulums_.begin(), pendulums_.end(),
                       [&](auto& p) { return pair(p.dof); }) ||
           std::any_of(coordinates_.begin(), coordinates_.end(),
                       [&](auto& c) { return dof == c.dof; }) ||
           std::any_of(axes_.begin(), axes_.end(), [&](auto& a) { return pair(a.dof); }) ||
           std::any_of(orbits_.begin(), orbits_.end(), [&](auto& o) { return pair(o.dof); }) ||
           std::any_of(bounces_.begin(), bounces_.end(), [&](auto& b) { return pair(b.dof); }) ||
           std::any_of(modes_.begin(), modes_.end(), [&](const Modes& m) {
               return std::any_of(m.dofs.begin(), m.dofs.end(), pair);
           });
}

double ExactReference::velocity(int dof, double t) const {
    // h ≈ ε^(1/3)·time scale balances rounding against the h² truncation.
    const double h = 1e-5 * std::max(1.0, std::abs(t));
    return (position(dof, t + h) - position(dof, t - h)) / (2.0 * h);
}

std::vector<double> ExactReference::periods() const {
    std::vector<double> out;
    const auto oscillator = [&](const LinearMotion& m) {
        if (m.omega2 > 0.0 && m.gamma == 0.0) out.push_back(kTwoPi / std::sqrt(m.omega2));
    };
    for (const Coordinate& c : coordinates_) oscillator(c.motion);
    for (const AxisMotion& a : axes_) oscillator(a.s);
    for (const Orbit& o : orbits_)
        if (!o.orbit.hyperbolic) out.push_back(kTwoPi / o.orbit.meanMotion);
    for (const Pendulum& p : pendulums_)
        out.push_back(4.0 * std::comp_ellint_1(p.motion.k) / p.motion.omega0);
    for (const Modes& m : modes_)
        for (Eigen::Index k = 0; k < m.omega.size(); ++k) out.push_back(kTwoPi / m.omega[k]);
    return out;
}

namespace {

// Contacts act as impulses, not smooth forces: no closed form survives them. But a contact that
// never happens changes nothing (a bead on its hoop above a floor it cannot reach): the closed
// form holds when, along it, no moving body comes within reach of a plane or of another body.
// Bounding circles and a margin of the speculative distance plus the largest move between two
// samples make the test conservative: a contact it misses cannot happen.
// A body within reach that moves away (a weight lifted off the floor by its rope) is not
// touched: contacts push, they do not pull. Returns the first sample time at which a contact
// can happen, +∞ when none can before endTime.
double contactFreeUntil(const ExactReference& ref, const World& world, double endTime) {
    struct Body {
        int dof;
        double reach;
    };
    std::vector<Body> moving;
    std::vector<std::pair<Vec2, double>> fixed;  // centre and reach of what does not move
    for (const Particle& p : world.particles()) {
        if (p.dof >= 0)
            moving.push_back({p.dof, p.radius});
        else
            fixed.emplace_back(p.position, p.radius);
    }
    for (const Box& b : world.boxes()) {
        const double reach = b.shape == RigidShape::Disk ? b.radius : 0.5 * b.size.norm();
        if (b.dof >= 0)
            moving.push_back({b.dof, reach});
        else
            fixed.emplace_back(b.position, reach);
    }
    constexpr std::size_t kMaxBodies = 64;  // pairs are checked at every sample
    constexpr int kSamples = 4000;
    constexpr double kMargin = 0.02;  // m, the contact stage's speculative distance
    constexpr double kNone = std::numeric_limits<double>::infinity();
    if (moving.size() > kMaxBodies || !(endTime > 0.0)) return 0.0;
    std::vector<Vec2> previous(moving.size()), now(moving.size());
    // Within reach and closer than at the last sample (at the first sample: within reach and
    // closer at the second, checked there).
    const auto touches = [&](double gap, double before, double reach, int sample) {
        return gap < reach && (sample == 0 ? false : gap < before);
    };
    for (int i = 0; i <= kSamples; ++i) {
        const double t = endTime * i / kSamples;
        double largestMove = 0.0;
        for (std::size_t k = 0; k < moving.size(); ++k) {
            now[k] = Vec2(ref.position(moving[k].dof, t), ref.position(moving[k].dof + 1, t));
            if (!now[k].allFinite()) return t;
            if (i > 0) largestMove = std::max(largestMove, (now[k] - previous[k]).norm());
        }
        const double margin = kMargin + largestMove;
        for (std::size_t k = 0; k < moving.size(); ++k) {
            for (const Plane& plane : world.planes())
                if (touches((now[k] - plane.point).dot(plane.normal),
                            (previous[k] - plane.point).dot(plane.normal), moving[k].reach + margin,
                            i))
                    return t;
            for (const auto& [centre, reach] : fixed)
                if (touches((now[k] - centre).norm(), (previous[k] - centre).norm(),
                            moving[k].reach + reach + margin, i))
                    return t;
            for (std::size_t j = k + 1; j < moving.size(); ++j)
                if (touches((now[k] - now[j]).norm(), (previous[k] - previous[j]).norm(),
                            moving[k].reach + moving[j].reach + margin, i))
                    return t;
        }
        previous.swap(now);
    }
    return kNone;
}

}  // namespace

std::optional<ExactReference> findExactReference(const SceneDesc& scene, const World& world,
                                                 double endTime) {
    std::optional<ExactReference> ref = ExactReference::ignoringContacts(scene, world, endTime);
    if (ref && world.contacts() && contactFreeUntil(*ref, world, endTime) <= endTime)
        return std::nullopt;
    return ref;
}

namespace {

// Distance from a point to a static rectangle (zero inside).
double distanceToBox(const Box& box, const Vec2& point) {
    const Vec2 local = rotation(-box.angle) * (point - box.position);
    const Vec2 half = 0.5 * box.size;
    const Vec2 outside(std::max(std::abs(local.x()) - half.x(), 0.0),
                       std::max(std::abs(local.y()) - half.y(), 0.0));
    return outside.norm();
}

}  // namespace

std::optional<ExactReference> findSupportedReferences(const SceneDesc& scene, const World& world,
                                                      double endTime) {
    if (!world.contacts() || world.settings().contactModel != ContactModel::Impulse ||
        !scene.effects.gravity || !world.springs().empty() || !world.joints().empty())
        return std::nullopt;
    for (const auto& effect : world.effects())
        if (effect->name() != effectName::gravity) return std::nullopt;
    const Vec2 g(scene.effects.gravity->g[0], scene.effects.gravity->g[1]);
    if (!(g.norm() > 0.0) || !(endTime > 0.0)) return std::nullopt;
    const Vec& q = world.positions();
    const Vec& u = world.velocities();
    const auto& boxes = world.boxes();

    ExactReference ref;
    ref.dimension_ = world.dimension();
    ref.kind_ = "rolling and sliding";
    double until = endTime;
    constexpr double kMargin = 0.02;  // m, the contact stage's speculative distance
    constexpr double kTouch = 1e-5;   // m: a body placed on a face to this
    constexpr int kSamples = 400;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Box& body = boxes[i];
        if (body.dof < 0 || body.shape == RigidShape::Polygon || u[body.dof + 2] != 0.0) continue;
        const bool disk = body.shape == RigidShape::Disk;
        const Vec2 c0 = q.segment<2>(body.dof), v0 = u.segment<2>(body.dof);
        const double angle0 = q[body.dof + 2];
        // The support: a static rectangle's face, facing up at most 60° from the vertical, that
        // the body lies on (a disk touching it, a box with a face flat on it).
        const Box* support = nullptr;
        Vec2 n, t;
        double depth = 0.0;     // from the body's centre to the face along −n
        double faceHalf = 0.0;  // half the face's length
        for (const Box& s : boxes) {
            if (s.dof >= 0 || s.shape != RigidShape::Rectangle) continue;
            const Mat2 r = rotation(s.angle);
            for (int side = 0; side < 4 && !support; ++side) {
                const Vec2 normal = (side < 2 ? 1.0 : -1.0) * r.col(side % 2);
                if (normal.dot(-g.normalized()) < 0.5) continue;
                const double half = 0.5 * s.size[side % 2];
                const double along = 0.5 * s.size[1 - side % 2];
                const Vec2 tangent = r.col(1 - side % 2);
                double reach = body.radius;
                if (!disk) {
                    // Flat on the face: one of the box's axes along the normal.
                    const Mat2 b = rotation(angle0);
                    const double ax = std::abs(b.col(0).dot(normal)),
                                 ay = std::abs(b.col(1).dot(normal));
                    if (std::abs(std::max(ax, ay) - 1.0) > 1e-9) continue;
                    reach = 0.5 * (ax > ay ? body.size.x() : body.size.y());
                }
                const double height = (c0 - s.position).dot(normal) - half;
                const double offset = (c0 - s.position).dot(tangent);
                if (std::abs(height - reach) > kTouch || std::abs(offset) > along) continue;
                support = &s;
                n = normal;
                t = tangent;
                depth = reach;
                faceHalf = along;
            }
            if (support) break;
        }
        if (!support || std::abs(v0.dot(n)) > 1e-9) continue;
        // Down the slope (or along the start velocity on the level).
        if (g.dot(t) < 0.0 || (g.dot(t) == 0.0 && v0.dot(t) < 0.0)) t = -t;
        const double gt = g.dot(t), gn = -g.dot(n);  // gn > 0: pressed on
        const double mu = std::sqrt(body.friction * support->friction);
        const double s0v = v0.dot(t);
        std::vector<PenaltyBounceMotion::Phase> phases;
        double alpha = 0.0;  // a disk's angular acceleration
        const auto phase = [&](double start, double x, double v, double a) {
            phases.push_back({start, LinearMotion{0.0, 0.0, a, x, v}, false});
        };
        const double kinetic = gt - mu * gn;  // sliding down (or along v on the level)
        if (disk) {
            if (s0v != 0.0) continue;  // from rest only: rolling starts at once or never
            // Rolling needs the friction m·(a − g_t) with a = g_t/(1 + I/(m·r²)).
            const double rolling =
                gt / (1.0 + body.inertia / (body.mass * body.radius * body.radius));
            const bool rolls = std::abs(body.mass * (rolling - gt)) <= mu * body.mass * gn;
            const double a = rolls ? rolling : std::max(kinetic, 0.0);
            const double friction = body.mass * (a - gt);  // along t, at the contact −r·n
            alpha = cross(Vec2(-depth * n), Vec2(friction * t)) / body.inertia;
            phase(0.0, 0.0, 0.0, a);
        } else if (s0v == 0.0) {
            phase(0.0, 0.0, 0.0, kinetic > 0.0 ? kinetic : 0.0);
        } else {
            // Moving along t (down, or along the level) or up the slope: friction opposes it
            // until the box stops, then it rests or slides down.
            const double a1 = s0v > 0.0 ? kinetic : gt + mu * gn;
            if ((s0v > 0.0) == (a1 >= 0.0)) {
                phase(0.0, 0.0, s0v, a1);
            } else {
                const double stop = -s0v / a1;
                phase(0.0, 0.0, s0v, a1);
                phase(stop, 0.5 * s0v * stop, 0.0, kinetic > 0.0 ? kinetic : 0.0);
            }
        }
        PenaltyBounceMotion motion;
        motion.phases = phases;
        // Until it leaves the face, and only if nothing else lies within reach of its path.
        const double along0 = (c0 - support->position).dot(t);
        const double reach = disk ? body.radius : 0.5 * body.size.norm();
        double leaves = endTime;
        bool clear = true;
        for (int k = 0; k <= kSamples && clear; ++k) {
            const double time = endTime * k / kSamples;
            const double sNow = motion.height(time);
            if (std::abs(along0 + sNow) > faceHalf) {
                leaves = time;
                break;
            }
            const Vec2 c = c0 + sNow * t;
            for (const Box& other : boxes) {
                if (&other == &body || &other == support) continue;
                if (other.dof < 0 && other.shape == RigidShape::Rectangle) {
                    if (distanceToBox(other, c) < reach + kMargin) clear = false;
                    continue;
                }
                const Vec2 centre = other.dof >= 0 ? Vec2(q.segment<2>(other.dof)) : other.position;
                const double otherReach =
                    other.shape == RigidShape::Disk ? other.radius : 0.5 * other.size.norm();
                if ((c - centre).norm() < reach + otherReach + kMargin) clear = false;
            }
            for (const Particle& p : world.particles()) {
                const Vec2 x = p.dof >= 0 ? Vec2(q.segment<2>(p.dof)) : p.position;
                if ((c - x).norm() < reach + p.radius + kMargin) clear = false;
            }
            for (const Plane& plane : world.planes())
                if ((c - plane.point).dot(plane.normal) < reach + kMargin) clear = false;
        }
        if (!clear || leaves < 10.0 * scene.simulation.dt) continue;
        until = std::min(until, leaves);
        ref.bounces_.push_back({body.dof, c0, t, motion});
        ref.coordinates_.push_back({body.dof + 2, LinearMotion{0.0, 0.0, alpha, angle0, 0.0}});
    }
    if (ref.bounces_.empty()) return std::nullopt;
    if (until < endTime) ref.validUntil_ = until;
    return ref;
}

std::optional<ExactReference> findDisplayReference(const SceneDesc& scene, const World& world,
                                                   double endTime) {
    // A closed form for the whole run first, then single bodies' (which go on through their
    // contacts: bounces, rolling and sliding), then the scene's up to its first contact.
    if (auto whole = findExactReference(scene, world, endTime)) return whole;
    std::optional<ExactReference> bodies = findBodyReferences(scene, world, endTime);
    if (auto supported = findSupportedReferences(scene, world, endTime)) {
        if (!bodies) return supported;
        bodies->kind_ += ", " + supported->kind_;
        bodies->validUntil_ = std::min(bodies->validUntil_, supported->validUntil_);
        for (const auto& b : supported->bounces_) bodies->bounces_.push_back(b);
        for (const auto& c : supported->coordinates_) bodies->coordinates_.push_back(c);
    }
    if (bodies) return bodies;
    std::optional<ExactReference> ref = ExactReference::ignoringContacts(scene, world, endTime);
    if (ref && world.contacts()) {
        const double until = contactFreeUntil(*ref, world, endTime);
        // Drawn up to the first contact that can happen, when that leaves ten steps or more to
        // draw (bodies resting on one another at the start meet at once).
        if (until < 10.0 * scene.simulation.dt) return std::nullopt;
        if (until <= endTime) ref->validUntil_ = until;
    }
    return ref;
}

std::optional<ExactReference> coupledOnALine(const World& world, double endTime) {
    // Springs alone (undamped), particles only, everything on one line and moving along it:
    // each spring's force is then linear in the coordinates along the line while no spring's
    // ends pass each other (checked along the solution).
    for (const auto& effect : world.effects())
        if (effect->name() != effectName::springs) return std::nullopt;
    if (!world.joints().empty() || !(endTime > 0.0)) return std::nullopt;
    const auto& particles = world.particles();
    for (const Box& b : world.boxes())
        if (b.dof >= 0) return std::nullopt;
    const Vec& q = world.positions();
    const Vec& u = world.velocities();
    std::vector<int> index(particles.size(), -1);  // particle → unknown
    std::vector<int> dofs;
    for (std::size_t i = 0; i < particles.size(); ++i)
        if (particles[i].dof >= 0) {
            index[i] = static_cast<int>(dofs.size());
            dofs.push_back(particles[i].dof);
        }
    const int n = static_cast<int>(dofs.size());
    if (n < 2 || n > 64 || world.springs().empty()) return std::nullopt;
    // The line: through the first two moving particles.
    const Vec2 origin = q.segment<2>(dofs[0]);
    const Vec2 span = Vec2(q.segment<2>(dofs[1])) - origin;
    if (!(span.norm() > 0.0)) return std::nullopt;
    const Vec2 axis = span.normalized();
    const auto onLine = [&](const Vec2& x) {
        const Vec2 d = x - origin;
        return std::abs(d.x() * axis.y() - d.y() * axis.x()) <= 1e-12 * std::max(1.0, d.norm());
    };
    for (const int dof : dofs)
        if (!onLine(q.segment<2>(dof)) || !alongAxis(u.segment<2>(dof), axis)) return std::nullopt;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n), mass(n);
    for (std::size_t i = 0; i < particles.size(); ++i)
        if (index[i] >= 0) mass[index[i]] = particles[i].mass;
    // Each spring end: an unknown, or a fixed coordinate along the line.
    struct End {
        int unknown;
        double at;
    };
    const auto endOf = [&](const SpringEnd& end) -> std::optional<End> {
        if (end.kind == SpringEnd::Kind::Particle) {
            const Particle& p = particles[end.index];
            const Vec2 x = p.dof >= 0 ? Vec2(q.segment<2>(p.dof)) : p.position;
            if (!onLine(x)) return std::nullopt;
            return End{index[end.index], (x - origin).dot(axis)};
        }
        if (end.kind == SpringEnd::Kind::Anchor && onLine(end.point))
            return End{-1, (end.point - origin).dot(axis)};
        return std::nullopt;  // a static box's point: left to the general search
    };
    std::vector<std::tuple<End, End, double>> sides;  // ends and the sign of b − a at the start
    for (const Spring& sp : world.springs()) {
        const auto a = endOf(sp.a), b = endOf(sp.b);
        if (!a || !b || sp.damping != 0.0) return std::nullopt;
        const double sign = b->at > a->at ? 1.0 : -1.0;
        if (b->at == a->at && sp.restLength != 0.0) return std::nullopt;
        // Tension k·(|s_b − s_a| − L) pulls b towards a: on b −k·(s_b − s_a − σL), on a the
        // opposite.
        const double k = sp.stiffness, L = sign * sp.restLength;
        const auto add = [&](const End& e, double side) {
            if (e.unknown < 0) return;
            // side = +1 for b, −1 for a: force side·(−k)·(s_b − s_a − L).
            for (const auto& [other, weight] : {std::pair{*b, 1.0}, std::pair{*a, -1.0}}) {
                if (other.unknown >= 0)
                    K(e.unknown, other.unknown) += side * k * weight;
                else
                    f[e.unknown] -= side * k * weight * other.at;
            }
            f[e.unknown] += side * k * L;
        };
        add(*b, 1.0);
        add(*a, -1.0);
        sides.push_back({*a, *b, sign});
    }
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eigen(
        K, Eigen::MatrixXd(mass.asDiagonal()));
    if (eigen.info() != Eigen::Success) return std::nullopt;
    const Eigen::VectorXd omega2 = eigen.eigenvalues();
    if (!(omega2.minCoeff() > 1e-12 * std::max(1.0, omega2.maxCoeff()))) return std::nullopt;
    ExactReference ref;
    ref.dimension_ = world.dimension();
    ref.kind_ = "coupled oscillators";
    ExactReference::Modes m;
    m.dofs = dofs;
    m.origin = origin;
    m.axis = axis;
    m.omega = omega2.cwiseSqrt();
    m.shapes = eigen.eigenvectors();
    m.equilibrium = K.ldlt().solve(f);
    Eigen::VectorXd s0(n), v0(n);
    for (int i = 0; i < n; ++i) {
        s0[i] = (Vec2(q.segment<2>(dofs[i])) - origin).dot(axis);
        v0[i] = Vec2(u.segment<2>(dofs[i])).dot(axis);
    }
    m.a = m.shapes.transpose() * mass.asDiagonal() * (s0 - m.equilibrium);
    m.b = m.shapes.transpose() * mass.asDiagonal() * v0;
    // No spring's ends may pass each other, or its force turns round.
    constexpr int kSamples = 4000;
    for (int k = 0; k <= kSamples; ++k) {
        const double t = endTime * k / kSamples;
        for (const auto& [a, b, sign] : sides) {
            const double sa = a.unknown >= 0 ? m.along(a.unknown, t) : a.at;
            const double sb = b.unknown >= 0 ? m.along(b.unknown, t) : b.at;
            if (!((sb - sa) * sign > 0.0)) return std::nullopt;
        }
    }
    ref.modes_.push_back(std::move(m));
    return ref;
}

std::optional<ExactReference> ExactReference::ignoringContacts(const SceneDesc& scene,
                                                               const World& world, double endTime) {
    for (const auto& effect : world.effects()) {
        const std::string& name = effect->name();
        if (name != effectName::gravity && name != effectName::drag && name != effectName::wind &&
            name != effectName::springs && name != effectName::newtonianGravity)
            return std::nullopt;
    }
    const EffectsDesc& fx = scene.effects;
    const Vec& q = world.positions();
    const Vec& u = world.velocities();
    ExactReference ref;
    ref.dimension_ = world.dimension();
    const auto coordinate = [&](int dof, double omega2, double gamma, double force) {
        ref.coordinates_.push_back({dof, {omega2, gamma, force, q[dof], u[dof]}});
    };

    if (!world.joints().empty() &&
        std::all_of(world.joints().begin(), world.joints().end(),
                    [](const Joint& j) { return j.type == Joint::Type::Pulley; })) {
        // Atwood machines: every dynamic body hangs on one pulley rope straight below its
        // ground point, under gravity alone along the ropes, moving along them. The rope keeps
        // y_a + r·y_b fixed, so m_a·ÿ_a = m_a·g + T and m_b·ÿ_b = m_b·g + r·T with ÿ_a = −r·ÿ_b
        // give constant accelerations ÿ_b = g·(m_b − r·m_a)/(m_b + r²·m_a) (g signed, along y).
        if (world.effects().size() != 1 || !fx.gravity || fx.gravity->g[0] != 0.0)
            return std::nullopt;
        const double g = fx.gravity->g[1];
        std::vector<int> held(static_cast<std::size_t>(world.dimension()), 0);
        const auto bodyOf = [&](const JointBody& body, int& dof, double& mass) {
            if (body.kind == JointBody::Kind::Particle) {
                const Particle& p = world.particles()[body.index];
                dof = p.dof;
                mass = p.mass;
                return true;
            }
            if (body.kind != JointBody::Kind::Rigid) return false;
            const Box& b = world.boxes()[body.index];
            dof = b.dof;
            mass = b.mass;
            return true;
        };
        const auto& joints = world.joints();
        for (int j = 0; j < static_cast<int>(joints.size()); ++j) {
            const Joint& joint = joints[j];
            int dofA = -1, dofB = -1;
            double massA = 0.0, massB = 0.0;
            if (!bodyOf(joint.a, dofA, massA) || !bodyOf(joint.b, dofB, massB) || dofA < 0 ||
                dofB < 0 || held[dofA] || held[dofB] || !(massA > 0.0) || !(massB > 0.0))
                return std::nullopt;
            const Vec2 pa = world.jointSolver()->pointA(j, q),
                       pb = world.jointSolver()->pointB(j, q);
            const Vec2 ca = q.segment<2>(dofA), cb = q.segment<2>(dofB);
            const double r = joint.ratio;
            // Straight ropes from points on the vertical through each centre (no torque), taut,
            // and a start that moves along them as the rope allows.
            const auto vertical = [](const Vec2& ground, const Vec2& point, const Vec2& centre) {
                const double tolerance = 1e-9 * std::max(1.0, std::abs(ground.y() - point.y()));
                return std::abs(ground.x() - point.x()) <= tolerance &&
                       std::abs(point.x() - centre.x()) <= tolerance && ground.y() > point.y();
            };
            if (!vertical(joint.groundA, pa, ca) || !vertical(joint.groundB, pb, cb))
                return std::nullopt;
            const double va = u[dofA + 1], vb = u[dofB + 1];
            if (u[dofA] != 0.0 || u[dofB] != 0.0 ||
                std::abs(va + r * vb) > 1e-12 * std::max(1.0, std::abs(va)))
                return std::nullopt;
            const double rotating = [&] {
                double w = 0.0;
                for (const JointBody* body : {&joint.a, &joint.b})
                    if (body->kind == JointBody::Kind::Rigid)
                        w = std::max(w, std::abs(u[world.boxes()[body->index].dof + 2]));
                return w;
            }();
            if (rotating != 0.0) return std::nullopt;
            const double accelerationB = g * (massB - r * massA) / (massB + r * r * massA);
            for (const auto& [dof, acceleration, kind] :
                 {std::tuple{dofA, -r * accelerationB, joint.a.kind},
                  std::tuple{dofB, accelerationB, joint.b.kind}}) {
                held[dof] = 1;
                coordinate(dof, 0.0, 0.0, 0.0);
                coordinate(dof + 1, 0.0, 0.0, acceleration);
                if (kind == JointBody::Kind::Rigid) coordinate(dof + 2, 0.0, 0.0, 0.0);
            }
        }
        for (const Particle& p : world.particles())
            if (p.dof >= 0 && !held[p.dof]) return std::nullopt;
        for (const Box& b : world.boxes())
            if (b.dof >= 0 && !held[b.dof]) return std::nullopt;
        ref.kind_ = "Atwood machine";
        return ref;
    }

    if (!world.joints().empty()) {
        // Simple pendulums only: every dynamic body a particle held by one rod to a fixed
        // point or one circular track, under gravity alone.
        if (world.effects().size() != 1 || !fx.gravity) return std::nullopt;
        const Vec2 g(fx.gravity->g[0], fx.gravity->g[1]);
        std::vector<int> heldBy(world.particles().size(), -1);
        for (const Box& b : world.boxes())
            if (b.dof >= 0) return std::nullopt;
        const auto& joints = world.joints();
        for (int j = 0; j < static_cast<int>(joints.size()); ++j) {
            const Joint& joint = joints[j];
            const bool rod = joint.type == Joint::Type::Rod;
            const bool hoop = joint.type == Joint::Type::Track && joint.circle;
            if ((!rod && !hoop) || joint.a.kind != JointBody::Kind::Particle) return std::nullopt;
            const Particle& p = world.particles()[joint.a.index];
            if (p.dof < 0 || heldBy[joint.a.index] >= 0) return std::nullopt;
            Vec2 centre = joint.center;
            double length = joint.radius;
            if (rod) {
                // The other end must be fixed: the world, a pinned particle or a static body.
                const JointBody& b = joint.b;
                if (b.kind == JointBody::Kind::Particle && world.particles()[b.index].dof >= 0)
                    return std::nullopt;
                if (b.kind == JointBody::Kind::Rigid && world.boxes()[b.index].dof >= 0)
                    return std::nullopt;
                centre = world.jointSolver()->pointB(j, q);
                length = joint.length;
            }
            const auto motion = PendulumMotion::fromState(centre, length, g, q.segment<2>(p.dof),
                                                          u.segment<2>(p.dof));
            if (!motion) return std::nullopt;
            heldBy[joint.a.index] = j;
            ref.pendulums_.push_back({p.dof, *motion});
        }
        for (std::size_t i = 0; i < world.particles().size(); ++i)
            if (world.particles()[i].dof >= 0 && heldBy[i] < 0) return std::nullopt;
        ref.kind_ = "simple pendulum";
        return ref;
    }

    if (world.findEffect(std::string(effectName::newtonianGravity))) {
        // Kepler: one fixed attractor and nothing else, so every body moves on its own conic.
        if (world.effects().size() != 1 || !fx.newtonianGravity) return std::nullopt;
        const NewtonianGravityDesc& ng = *fx.newtonianGravity;
        if (ng.mutual || ng.softening != 0.0 || ng.attractors.size() != 1) return std::nullopt;
        const double mu = ng.G * ng.attractors[0].mass;
        const Vec2 centre(ng.attractors[0].position[0], ng.attractors[0].position[1]);
        ref.kind_ = mu != 0.0 ? "Kepler orbit" : "free motion";
        const auto body = [&](int dof) {
            if (mu == 0.0) {
                coordinate(dof, 0.0, 0.0, 0.0);
                coordinate(dof + 1, 0.0, 0.0, 0.0);
                return true;
            }
            const auto orbit =
                KeplerMotion::fromState(centre, q.segment<2>(dof), u.segment<2>(dof), mu);
            if (orbit) ref.orbits_.push_back({dof, *orbit});
            return orbit.has_value();
        };
        for (const Particle& p : world.particles())
            if (p.dof >= 0 && !body(p.dof)) return std::nullopt;
        for (const Box& b : world.boxes()) {
            if (b.dof < 0) continue;
            if (!body(b.dof)) return std::nullopt;
            coordinate(b.dof + 2, 0.0, 0.0, 0.0);  // no torque about the centre: θ = θ₀ + ω₀t
        }
        return ref;
    }

    const Vec2 g = fx.gravity ? Vec2(fx.gravity->g[0], fx.gravity->g[1]) : Vec2::Zero();
    const DragDesc drag = fx.drag ? *fx.drag : DragDesc{};
    if (drag.quadratic != 0.0) return std::nullopt;
    const Vec2 windVelocity =
        fx.wind ? Vec2(fx.wind->velocity[0], fx.wind->velocity[1]) : Vec2::Zero();
    const double windDrag = fx.wind ? fx.wind->drag : 0.0;

    // Each dynamic particle may hang on springs whose other end is fixed; any spring touching
    // a dynamic box or joining two moving particles couples bodies and ends the search.
    struct Anchored {
        const Spring* spring;
        Vec2 anchor;
    };
    const auto& particles = world.particles();
    const auto& boxes = world.boxes();
    std::vector<std::vector<Anchored>> springsOf(particles.size());
    const auto fixedPoint = [&](const SpringEnd& end) -> std::optional<Vec2> {
        switch (end.kind) {
            case SpringEnd::Kind::Anchor:
                return end.point;
            case SpringEnd::Kind::Particle:
                if (particles[end.index].pinned) return particles[end.index].position;
                return std::nullopt;
            case SpringEnd::Kind::Box: {
                const Box& b = boxes[end.index];
                if (b.isStatic) return Vec2(b.position + rotation(b.angle) * end.point);
                return std::nullopt;
            }
        }
        return std::nullopt;
    };
    const auto movingParticle = [&](const SpringEnd& end) {
        return end.kind == SpringEnd::Kind::Particle && !particles[end.index].pinned ? end.index
                                                                                     : -1;
    };
    for (const Spring& s : world.springs()) {
        const std::optional<Vec2> fixedA = fixedPoint(s.a), fixedB = fixedPoint(s.b);
        if (fixedA && fixedB) continue;  // moves nothing
        const int pa = movingParticle(s.a), pb = movingParticle(s.b);
        if (pa >= 0 && fixedB)
            springsOf[pa].push_back({&s, *fixedB});
        else if (pb >= 0 && fixedA)
            springsOf[pb].push_back({&s, *fixedA});
        else
            return coupledOnALine(world, endTime);
    }

    bool anySpring = false, damped = drag.linear > 0.0 || drag.angular > 0.0 || windDrag > 0.0;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Particle& p = particles[i];
        if (p.dof < 0) continue;
        const double m = p.mass;
        const Vec2 force = g + (windDrag / m) * windVelocity;  // per unit mass
        const double gamma = (drag.linear + windDrag) / m;
        const std::vector<Anchored>& springs = springsOf[i];
        anySpring = anySpring || !springs.empty();
        const bool linear2d = std::all_of(springs.begin(), springs.end(), [](const Anchored& a) {
            return a.spring->restLength == 0.0 && a.spring->damping == 0.0;
        });
        if (linear2d) {
            // Σ −kᵢ·(x − aᵢ) = −K·(x − c) with K = Σkᵢ, c = Σkᵢ·aᵢ/K: one isotropic oscillator.
            double K = 0.0;
            Vec2 weighted = Vec2::Zero();
            for (const Anchored& a : springs) {
                K += a.spring->stiffness;
                weighted += a.spring->stiffness * a.anchor;
            }
            for (int k = 0; k < 2; ++k)
                coordinate(p.dof + k, K / m, gamma, force[k] + weighted[k] / m);
            continue;
        }
        // A rest length or axial damping is linear only along the spring's axis: demand that
        // the particle starts on it, moves along it, is pushed along it, and (with a rest
        // length) never reaches the anchor, where the force would turn round.
        if (springs.size() != 1) return std::nullopt;
        const Spring& s = *springs.front().spring;
        const Vec2 anchor = springs.front().anchor;
        const Vec2 offset = q.segment<2>(p.dof) - anchor;
        const double length = offset.norm();
        if (!(length > 0.0)) return std::nullopt;
        const Vec2 axis = offset / length;
        const Vec2 v0 = u.segment<2>(p.dof);
        if (!alongAxis(v0, axis) || !alongAxis(force, axis)) return std::nullopt;
        const double k = s.stiffness / m;
        const LinearMotion along{k, gamma + s.damping / m, force.dot(axis) + k * s.restLength,
                                 length, v0.dot(axis)};
        if (s.restLength != 0.0 && !(along.lowerBound(endTime) > 0.0)) return std::nullopt;
        damped = damped || s.damping > 0.0;
        ref.axes_.push_back({p.dof, anchor, axis, along});
    }
    for (const Box& b : boxes) {
        if (b.dof < 0) continue;
        for (int k = 0; k < 2; ++k) coordinate(b.dof + k, 0.0, drag.linear / b.mass, g[k]);
        coordinate(b.dof + 2, 0.0, drag.angular / b.inertia, 0.0);
    }

    if (anySpring)
        ref.kind_ = damped ? "damped harmonic oscillator" : "harmonic oscillator";
    else if (g != Vec2::Zero())
        ref.kind_ = damped ? "free fall with linear drag" : "free fall";
    else
        ref.kind_ = damped ? "motion with linear drag" : "free motion";
    return ref;
}

std::optional<ExactReference> findBodyReferences(const SceneDesc& scene, const World& world,
                                                 double endTime) {
    if (!world.contacts()) return std::nullopt;
    const ContactModel model = world.settings().contactModel;
    if (model != ContactModel::Penalty && model != ContactModel::Impulse) return std::nullopt;
    const bool penalty = model == ContactModel::Penalty;
    // Gravity alone moves a free body (springs move only what they hold, left out below).
    for (const auto& effect : world.effects())
        if (effect->name() != effectName::gravity && effect->name() != effectName::springs)
            return std::nullopt;
    if (!scene.effects.gravity) return std::nullopt;
    const Vec2 g(scene.effects.gravity->g[0], scene.effects.gravity->g[1]);
    if (!(g.norm() > 0.0)) return std::nullopt;
    const Vec2 up = -g.normalized();
    const double k = world.penaltyStiffness(), c = world.settings().contactDamping;
    if (penalty && !(k > 0.0)) return std::nullopt;

    // What is attached to something cannot move on its own.
    const auto& particles = world.particles();
    const auto& boxes = world.boxes();
    std::vector<char> attachedParticle(particles.size(), 0), attachedBox(boxes.size(), 0);
    const auto attach = [&](SpringEnd::Kind kind, int index) {
        if (kind == SpringEnd::Kind::Particle) attachedParticle[index] = 1;
        if (kind == SpringEnd::Kind::Box) attachedBox[index] = 1;
    };
    for (const Spring& sp : world.springs()) {
        attach(sp.a.kind, sp.a.index);
        attach(sp.b.kind, sp.b.index);
    }
    for (const Joint& j : world.joints())
        for (const JointBody* body : {&j.a, &j.b}) {
            if (body->kind == JointBody::Kind::Particle) attachedParticle[body->index] = 1;
            if (body->kind == JointBody::Kind::Rigid) attachedBox[body->index] = 1;
        }

    struct Candidate {
        int dof;
        Vec2 position, velocity;
        double radius, mass, restitution;
    };
    std::vector<Candidate> candidates;
    std::vector<std::pair<Vec2, double>> others;  // every body's start and reach
    const Vec& q = world.positions();
    const Vec& u = world.velocities();
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Particle& p = particles[i];
        const Vec2 x = p.dof >= 0 ? Vec2(q.segment<2>(p.dof)) : p.position;
        others.emplace_back(x, p.radius);
        if (p.dof >= 0 && p.cloth < 0 && !attachedParticle[i])
            candidates.push_back({p.dof, x, u.segment<2>(p.dof), p.radius, p.mass, p.restitution});
    }
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Box& b = boxes[i];
        const Vec2 x = b.dof >= 0 ? Vec2(q.segment<2>(b.dof)) : b.position;
        const double reach = b.shape == RigidShape::Disk ? b.radius : 0.5 * b.size.norm();
        others.emplace_back(x, reach);
        if (b.dof >= 0 && b.shape == RigidShape::Disk && !attachedBox[i] && u[b.dof + 2] == 0.0)
            candidates.push_back({b.dof, x, u.segment<2>(b.dof), b.radius, b.mass, b.restitution});
    }

    ExactReference ref;
    ref.dimension_ = world.dimension();
    ref.kind_ = penalty ? "penalty bounce" : "bounce";
    constexpr double kMargin = 0.02;  // m, the contact stage's speculative distance
    constexpr int kSamples = 2000;
    for (const Candidate& body : candidates) {
        if (!alongAxis(body.velocity, up)) continue;
        // The plane it falls on: the nearest below, facing up.
        const Plane* floor = nullptr;
        double height = HUGE_VAL;
        for (const Plane& plane : world.planes()) {
            const double s = (body.position - plane.point).dot(plane.normal);
            if (plane.normal.dot(up) > 1.0 - 1e-12 && s > 0.0 && s < height) {
                floor = &plane;
                height = s;
            }
        }
        if (!floor) continue;
        // Impulses: the pair's restitution is the larger of the two (ContactStage).
        const PenaltyBounceMotion motion =
            penalty
                ? PenaltyBounceMotion::fromState(height, body.velocity.dot(up), g.norm(),
                                                 body.radius, k, c, body.mass, endTime)
                : PenaltyBounceMotion::impulse(height, body.velocity.dot(up), g.norm(), body.radius,
                                               std::max(body.restitution, floor->restitution),
                                               ContactSettings{}.restitutionThreshold, endTime);
        double lo = height, hi = height;
        for (int i = 0; i <= kSamples; ++i) {
            const double s = motion.height(endTime * i / kSamples);
            lo = std::min(lo, s);
            hi = std::max(hi, s);
        }
        // The column it sweeps must stay clear of every other body and plane.
        const Vec2 base = body.position - height * up;
        const Vec2 bottom = base + lo * up, top = base + hi * up;
        bool clear = std::isfinite(hi) && hi - lo < 1e6;
        for (const Plane& plane : world.planes()) {
            if (&plane == floor) continue;
            const double reach = body.radius + kMargin;
            if ((bottom - plane.point).dot(plane.normal) < reach ||
                (top - plane.point).dot(plane.normal) < reach)
                clear = false;
        }
        for (const auto& [centre, reach] : others) {
            if ((centre - body.position).norm() < 1e-12) continue;  // itself
            // Distance from the centre to the segment bottom–top.
            const double along = std::clamp((centre - bottom).dot(up), 0.0, hi - lo);
            if ((centre - (bottom + along * up)).norm() < body.radius + reach + kMargin)
                clear = false;
        }
        if (clear) ref.bounces_.push_back({body.dof, base, up, motion});
    }
    if (ref.bounces_.empty()) return std::nullopt;
    return ref;
}

}  // namespace phasebox
