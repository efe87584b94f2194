// The closed form of two free bodies through one impact (the lesson "Impulse and spin"): each
// flies until they touch, one impulse along the normal changes both momenta and spins, and each
// flies on.

#include "app/accuracy/ExactReference.h"

#include "app/accuracy/ExactReferenceDetail.h"
#include "physics/contacts/ContactModel.h"
#include "physics/core/EffectNames.h"
#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace phasebox {

using namespace exact_detail;

const ExactReference::Flight::Phase& ExactReference::Flight::at(double t) const {
    std::size_t k = 0;
    while (k + 1 < phases.size() && phases[k + 1].start <= t) ++k;
    return phases[k];
}

Vec2 ExactReference::Flight::position(double t) const {
    const Phase& p = at(t);
    const double tau = t - p.start;
    return p.x + tau * p.v + 0.5 * tau * tau * g;
}

double ExactReference::Flight::angle(double t) const {
    const Phase& p = at(t);
    return p.angle + (t - p.start) * p.omega;
}

namespace {

// One of the two bodies: a circle (a particle or a disk) or a rectangle.
struct Mover {
    int dof = -1;
    bool rigid = false, circle = true;
    double radius = 0.0;
    Vec2 half{0.0, 0.0};
    double inverseMass = 0.0, inverseInertia = 0.0, friction = 0.0, restitution = 0.0;
    Vec2 x, v;
    double angle = 0.0, omega = 0.0;
};

// The gap between shape `a` (at x, turned by angle) and a circle of radius r centred at c,
// negative when they overlap; at a touch, the normal from a toward the circle and the point.
double gap(const Mover& a, const Vec2& x, double angle, const Vec2& c, double r, Vec2* normal,
           Vec2* point) {
    if (a.circle) {
        const Vec2 d = c - x;
        const double length = d.norm();
        if (normal) *normal = length > 0.0 ? Vec2(d / length) : Vec2(0.0, 1.0);
        if (point && normal) *point = x + a.radius * *normal;
        return length - a.radius - r;
    }
    const Mat2 turn = rotation(angle);
    const Vec2 local = turn.transpose() * (c - x);
    const Vec2 closest(std::clamp(local.x(), -a.half.x(), a.half.x()),
                       std::clamp(local.y(), -a.half.y(), a.half.y()));
    const Vec2 outside = local - closest;
    const double length = outside.norm();
    // Inside (or on a face, for a circle of radius 0): the nearest face.
    const double depthX = a.half.x() - std::abs(local.x()),
                 depthY = a.half.y() - std::abs(local.y());
    if (normal) {
        Vec2 n = length > 1e-12    ? Vec2(outside / length)
                 : depthX < depthY ? Vec2(local.x() < 0.0 ? -1.0 : 1.0, 0.0)
                                   : Vec2(0.0, local.y() < 0.0 ? -1.0 : 1.0);
        *normal = turn * n;
    }
    if (point) *point = x + turn * closest;
    return (length > 0.0 ? length : -std::min(depthX, depthY)) - r;
}

// The bodies of the world: the moving ones, and the fixed ones they must keep away from.
// False when a moving body is a polygon (no closed form here).
struct ImpactBodies {
    std::vector<Mover> movers;
    std::vector<std::pair<Vec2, double>> fixedCircles;  // pinned particles, static disks, polygons
    std::vector<const RigidBody*> fixedBoxes;
};
bool collectBodies(const World& world, ImpactBodies& out) {
    const Vec& q = world.positions();
    const Vec& u = world.velocities();
    for (const Particle& p : world.particles()) {
        if (p.dof < 0) {
            out.fixedCircles.emplace_back(p.position, p.radius);
            continue;
        }
        Mover m;
        m.dof = p.dof;
        m.radius = p.radius;
        m.inverseMass = 1.0 / p.mass;
        m.friction = p.friction;
        m.restitution = p.restitution;
        m.x = q.segment<2>(p.dof);
        m.v = u.segment<2>(p.dof);
        out.movers.push_back(m);
    }
    for (const RigidBody& b : world.rigidBodies()) {
        if (b.dof < 0) {
            if (b.shape == RigidShape::Rectangle)
                out.fixedBoxes.push_back(&b);
            else
                out.fixedCircles.emplace_back(
                    b.position, b.shape == RigidShape::Disk ? b.radius : 0.5 * b.size.norm());
            continue;
        }
        if (b.shape == RigidShape::Polygon) return false;
        Mover m;
        m.dof = b.dof;
        m.rigid = true;
        m.circle = b.shape == RigidShape::Disk;
        m.radius = m.circle ? b.radius : 0.0;
        m.half = 0.5 * b.size;
        m.inverseMass = 1.0 / b.mass;
        m.inverseInertia = 1.0 / b.inertia;
        m.friction = b.friction;
        m.restitution = b.restitution;
        m.x = q.segment<2>(b.dof);
        m.v = u.segment<2>(b.dof);
        m.angle = q[b.dof + 2];
        m.omega = u[b.dof + 2];
        out.movers.push_back(m);
    }
    return true;
}

// The first time gapAt(t) reaches 0 in [0, endTime], or nullopt when it never does. gapAt is the
// gap between a point moving uniformly relative to a convex shape and that shape: convex in
// time, so its least value is found by golden sections, then the first touch before it by
// bisection.
template <typename Gap>
std::optional<double> firstTouch(const Gap& gapAt, double endTime) {
    double lo = 0.0, hi = endTime;
    const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int i = 0; i < 200 && hi - lo > 1e-15 * endTime; ++i) {
        const double m1 = hi - ratio * (hi - lo), m2 = lo + ratio * (hi - lo);
        if (gapAt(m1) < gapAt(m2))
            hi = m2;
        else
            lo = m1;
    }
    if (gapAt(lo) > 0.0) return std::nullopt;
    double apart = 0.0, touching = lo;
    for (int i = 0; i < 200 && touching - apart > 1e-15 * endTime; ++i) {
        const double mid = 0.5 * (apart + touching);
        (gapAt(mid) > 0.0 ? apart : touching) = mid;
    }
    return touching;
}

}  // namespace

std::optional<ExactReference> findImpactReference(const SceneDesc& scene, const World& world,
                                                  double endTime) {
    if (!world.contacts() || world.settings().contactModel != ContactModel::Impulse ||
        !world.springs().empty() || !world.joints().empty() || !(endTime > 0.0))
        return std::nullopt;
    for (const auto& effect : world.effects())
        if (effect->name() != effectName::gravity && effect->name() != effectName::springs)
            return std::nullopt;
    const Vec2 g = scene.effects.gravity
                       ? Vec2(scene.effects.gravity->g[0], scene.effects.gravity->g[1])
                       : Vec2(0.0, 0.0);

    // Exactly two moving bodies; everything else is fixed and must stay out of their reach.
    ImpactBodies bodies;
    if (!collectBodies(world, bodies)) return std::nullopt;
    std::vector<Mover>& movers = bodies.movers;
    const auto& fixedCircles = bodies.fixedCircles;
    const auto& fixedBoxes = bodies.fixedBoxes;
    if (movers.size() != 2) return std::nullopt;
    // A is the shape, B the circle that hits it. Two particles meet only with
    // particle_collisions, an effect left out above; a rectangle's gap is a convex function of
    // time only while it does not turn.
    if (!movers[1].circle) std::swap(movers[0], movers[1]);
    Mover a = movers[0], b = movers[1];
    if (!b.circle || (!a.rigid && !b.rigid) || (!a.circle && a.omega != 0.0)) return std::nullopt;

    const auto flight = [&g](const Mover& m, double t) {
        return Vec2(m.x + t * m.v + 0.5 * t * t * g);
    };
    const auto gapAt = [&](double t) {
        return gap(a, flight(a, t), a.angle, flight(b, t), b.radius, nullptr, nullptr);
    };
    if (!(gapAt(0.0) > 0.0)) return std::nullopt;
    const std::optional<double> touch = firstTouch(gapAt, endTime);
    if (!touch) return std::nullopt;  // they never meet: ignoringContacts' case
    const double tc = *touch;

    // The impulse (ContactStage: e = max(e₁, e₂), μ = √(μ₁·μ₂); ContactBounce: no bounce
    // below the threshold·(1 − e)).
    Vec2 n, point;
    const Vec2 xa = flight(a, tc), xb = flight(b, tc);
    gap(a, xa, a.angle, xb, b.radius, &n, &point);
    const Vec2 va = a.v + tc * g, vb = b.v + tc * g;
    const Vec2 ra = point - xa, rb = point - xb;
    const auto pointVelocity = [](const Vec2& v, double omega, const Vec2& r) {
        return Vec2(v + omega * perp(r));
    };
    const Vec2 relative = pointVelocity(vb, b.omega, rb) - pointVelocity(va, a.omega, ra);
    const double vn = relative.dot(n);
    const double e = std::max(a.restitution, b.restitution);
    if (!(vn < -world.settings().contacts.restitutionThreshold * (1.0 - e)) || !(e > 0.0))
        return std::nullopt;  // resting or plastic: they stay together, and may meet again
    const double ca = cross(ra, n), cb = cross(rb, n);
    const double effective =
        a.inverseMass + b.inverseMass + ca * ca * a.inverseInertia + cb * cb * b.inverseInertia;
    const double j = -(1.0 + e) * vn / effective;
    Mover a2 = a, b2 = b;
    a2.x = xa;
    b2.x = xb;
    a2.v = va - j * a.inverseMass * n;
    b2.v = vb + j * b.inverseMass * n;
    a2.omega = a.omega - j * ca * a.inverseInertia;
    b2.omega = b.omega + j * cb * b.inverseInertia;
    a2.angle = a.angle + tc * a.omega;
    b2.angle = b.angle + tc * b.omega;
    // Friction changes nothing only when nothing slides at the point, before and after.
    const Vec2 tangent(-n.y(), n.x());
    const Vec2 relative2 = pointVelocity(b2.v, b2.omega, rb) - pointVelocity(a2.v, a2.omega, ra);
    if (std::sqrt(a.friction * b.friction) > 0.0 && (std::abs(relative.dot(tangent)) > 1e-9 * -vn ||
                                                     std::abs(relative2.dot(tangent)) > 1e-9 * -vn))
        return std::nullopt;

    ExactReference::Parts ref;
    ref.dimension = world.dimension();
    ref.kind = "impact";
    for (const auto& [m0, m1] : {std::pair{a, a2}, std::pair{b, b2}})
        ref.flights.push_back(
            {m0.dof,
             m0.rigid,
             g,
             {{0.0, m0.x, m0.v, m0.angle, m0.omega}, {tc, m1.x, m1.v, m1.angle, m1.omega}}});
    const ExactReference::Flight &fa = ref.flights[0], &fb = ref.flights[1];

    // They must not meet again, and neither may come within reach of anything fixed.
    constexpr double kMargin = 0.02;  // m, the contact stage's speculative distance
    constexpr int kSamples = 2000;
    for (int k = 0; k <= kSamples; ++k) {
        const double t = endTime * k / kSamples;
        if (t > tc && !(gap(a, fa.position(t), fa.angle(t), fb.position(t), b.radius, nullptr,
                            nullptr) > 0.0))
            return std::nullopt;
        for (const auto* f : {&fa, &fb}) {
            const Mover& m = f == &fa ? a : b;
            const Vec2 c = f->position(t);
            const double reach = (m.circle ? m.radius : m.half.norm()) + kMargin;
            for (const Plane& plane : world.planes())
                if ((c - plane.point).dot(plane.normal) < reach) return std::nullopt;
            for (const auto& [centre, radius] : fixedCircles)
                if ((c - centre).norm() < reach + radius) return std::nullopt;
            for (const RigidBody* box : fixedBoxes)
                if (distanceToBox(*box, c) < reach) return std::nullopt;
        }
    }
    return ref;
}

}  // namespace phasebox
