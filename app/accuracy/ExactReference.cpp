#include "app/accuracy/ExactReference.h"

#include "app/accuracy/ExactReferenceDetail.h"

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

using namespace exact_detail;

Vec ExactReference::positions(double t) const {
    Vec q = Vec::Zero(parts_.dimension);
    for (const Pendulum& p : parts_.pendulums) q.segment<2>(p.dof) = p.motion.at(t);
    for (const RigidPendulum& p : parts_.rigidPendulums) {
        q.segment<2>(p.dof) = p.motion.at(t);
        q[p.dof + 2] = p.angle(t);
    }
    for (const Coordinate& c : parts_.coordinates) q[c.dof] = c.motion.at(t);
    for (const AxisMotion& a : parts_.axes) q.segment<2>(a.dof) = a.anchor + a.s.at(t) * a.axis;
    for (const Orbit& o : parts_.orbits) q.segment<2>(o.dof) = o.orbit.at(t);
    for (const Bounce& b : parts_.bounces)
        q.segment<2>(b.dof) = b.base + b.motion.height(t) * b.normal;
    for (const Modes& m : parts_.modes)
        for (std::size_t i = 0; i < m.dofs.size(); ++i)
            q.segment<2>(m.dofs[i]) = m.origin + m.along(i, t) * m.axis;
    for (const Flight& f : parts_.flights) {
        q.segment<2>(f.dof) = f.position(t);
        if (f.rigid) q[f.dof + 2] = f.angle(t);
    }
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
    for (const Pendulum& p : parts_.pendulums)
        if (dof == p.dof || dof == p.dof + 1) return p.motion.at(t)[dof - p.dof];
    for (const RigidPendulum& p : parts_.rigidPendulums) {
        if (dof == p.dof || dof == p.dof + 1) return p.motion.at(t)[dof - p.dof];
        if (dof == p.dof + 2) return p.angle(t);
    }
    for (const Coordinate& c : parts_.coordinates)
        if (dof == c.dof) return c.motion.at(t);
    for (const AxisMotion& a : parts_.axes)
        if (dof == a.dof || dof == a.dof + 1)
            return a.anchor[dof - a.dof] + a.s.at(t) * a.axis[dof - a.dof];
    for (const Orbit& o : parts_.orbits)
        if (dof == o.dof || dof == o.dof + 1) return o.orbit.at(t)[dof - o.dof];
    for (const Bounce& b : parts_.bounces)
        if (dof == b.dof || dof == b.dof + 1)
            return b.base[dof - b.dof] + b.motion.height(t) * b.normal[dof - b.dof];
    for (const Modes& m : parts_.modes)
        for (std::size_t i = 0; i < m.dofs.size(); ++i)
            if (dof == m.dofs[i] || dof == m.dofs[i] + 1)
                return m.origin[dof - m.dofs[i]] + m.along(i, t) * m.axis[dof - m.dofs[i]];
    for (const Flight& f : parts_.flights) {
        if (dof == f.dof || dof == f.dof + 1) return f.position(t)[dof - f.dof];
        if (f.rigid && dof == f.dof + 2) return f.angle(t);
    }
    return 0.0;
}

bool ExactReference::covers(int dof) const {
    const auto pair = [dof](int first) { return dof == first || dof == first + 1; };
    return std::any_of(parts_.pendulums.begin(), parts_.pendulums.end(),
                       [&](auto& p) { return pair(p.dof); }) ||
           std::any_of(parts_.rigidPendulums.begin(), parts_.rigidPendulums.end(),
                       [&](auto& p) { return pair(p.dof) || dof == p.dof + 2; }) ||
           std::any_of(parts_.coordinates.begin(), parts_.coordinates.end(),
                       [&](auto& c) { return dof == c.dof; }) ||
           std::any_of(parts_.axes.begin(), parts_.axes.end(),
                       [&](auto& a) { return pair(a.dof); }) ||
           std::any_of(parts_.orbits.begin(), parts_.orbits.end(),
                       [&](auto& o) { return pair(o.dof); }) ||
           std::any_of(parts_.bounces.begin(), parts_.bounces.end(),
                       [&](auto& b) { return pair(b.dof); }) ||
           std::any_of(
               parts_.modes.begin(), parts_.modes.end(),
               [&](const Modes& m) { return std::any_of(m.dofs.begin(), m.dofs.end(), pair); }) ||
           std::any_of(parts_.flights.begin(), parts_.flights.end(), [&](const Flight& f) {
               return pair(f.dof) || (f.rigid && dof == f.dof + 2);
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
    for (const Coordinate& c : parts_.coordinates) oscillator(c.motion);
    for (const AxisMotion& a : parts_.axes) oscillator(a.s);
    for (const Orbit& o : parts_.orbits)
        if (!o.orbit.hyperbolic) out.push_back(kTwoPi / o.orbit.meanMotion);
    for (const Pendulum& p : parts_.pendulums)
        out.push_back(4.0 * std::comp_ellint_1(p.motion.k) / p.motion.omega0);
    for (const RigidPendulum& p : parts_.rigidPendulums)
        out.push_back(4.0 * std::comp_ellint_1(p.motion.k) / p.motion.omega0);
    for (const Modes& m : parts_.modes)
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
    for (const RigidBody& b : world.rigidBodies()) {
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

// Whether the other end of joint j is fixed: the world, a pinned particle or a static body.
bool heldToFixed(const World& world, const Joint& joint) {
    const JointBody& b = joint.b;
    if (b.kind == JointBody::Kind::Particle) return world.particles()[b.index].dof < 0;
    if (b.kind == JointBody::Kind::Rigid) return world.rigidBodies()[b.index].dof < 0;
    return true;
}

// A rope swings like a rod while it stays taut: from rest at θ0 its tension m·g·(3·cos θ −
// 2·cos θ0) stays ≥ 0 throughout when θ0 ≤ 90°, that is k = sin(θ0/2) ≤ √½.
bool ropeStaysTaut(const PendulumMotion& motion) {
    return motion.k * motion.k <= 0.5 + 1e-12;
}

// A rigid body held to a fixed point by joint j under gravity g: a physical pendulum on a hinge
// (ω₀² = m·g·d/I_pivot, I_pivot = I + m·d², d from the pivot to the centre), a simple pendulum
// of its centre on a rod or taut rope at the centre (the pull passes through the centre: the
// spin stays). nullopt otherwise (a rod at another point makes a double pendulum).
std::optional<ExactReference::RigidPendulum> rigidPendulum(const World& world, int j,
                                                           const Vec2& g) {
    const Joint& joint = world.joints()[j];
    const RigidBody& body = world.rigidBodies()[joint.a.index];
    if (body.dof < 0 || !heldToFixed(world, joint) || !world.jointSolver()) return std::nullopt;
    const Vec& q = world.positions();
    const Vec& u = world.velocities();
    const Vec2 pivot = world.jointSolver()->pointB(j, q);
    const Vec2 centre = q.segment<2>(body.dof), velocity = u.segment<2>(body.dof);
    const double omega = u[body.dof + 2];
    ExactReference::RigidPendulum out;
    out.dof = body.dof;
    out.angle0 = q[body.dof + 2];
    std::optional<PendulumMotion> motion;
    if (joint.type == Joint::Type::Hinge) {
        const double d = (centre - pivot).norm();
        if (joint.hasLimits || joint.hasMotor || !(d > 0.0)) return std::nullopt;
        // The body turns about the pivot: its centre moves at ω × (c − pivot).
        const Vec2 turning = omega * perp(Vec2(centre - pivot));
        if ((velocity - turning).norm() > 1e-9 * std::max(1.0, velocity.norm()))
            return std::nullopt;
        const double lengthEq = (body.inertia + body.mass * d * d) / (body.mass * d);
        motion = PendulumMotion::fromState(pivot, d, g, centre, velocity, lengthEq);
    } else if (joint.type == Joint::Type::Rod || joint.type == Joint::Type::Rope) {
        if (joint.a.point != Vec2::Zero()) return std::nullopt;
        motion = PendulumMotion::fromState(pivot, joint.length, g, centre, velocity);
        const double distance = (centre - pivot).norm();
        if (motion && joint.type == Joint::Type::Rope &&
            (!ropeStaysTaut(*motion) || std::abs(distance - joint.length) > 1e-9 * joint.length))
            return std::nullopt;
        out.hinged = false;
        out.spin = omega;
    }
    if (!motion) return std::nullopt;
    out.motion = *motion;
    return out;
}

// A closed form of the world's coordinates, with no motion in it yet.
ExactReference::Parts emptyParts(const World& world) {
    ExactReference::Parts parts;
    parts.dimension = world.dimension();
    return parts;
}

// Adds a coordinate's closed form to ref: ẍ = −ω²·x − γ·ẋ + force from the world's start.
auto coordinateAdder(ExactReference::Parts& ref, const Vec& q, const Vec& u) {
    return [&ref, &q, &u](int dof, double omega2, double gamma, double force) {
        ref.coordinates.push_back({dof, {omega2, gamma, force, q[dof], u[dof]}});
    };
}

// Atwood machines: every dynamic body hangs on one pulley rope straight below its
// ground point, under gravity alone along the ropes, moving along them. The rope keeps
// y_a + r·y_b fixed, so m_a·ÿ_a = m_a·g + T and m_b·ÿ_b = m_b·g + r·T with ÿ_a = −r·ÿ_b
// give constant accelerations ÿ_b = g·(m_b − r·m_a)/(m_b + r²·m_a) (g signed, along y).
std::optional<ExactReference> atwoodMachines(const SceneDesc& scene, const World& world, double) {
    const EffectsDesc& fx = scene.effects;
    const Vec &q = world.positions(), &u = world.velocities();
    ExactReference::Parts ref = emptyParts(world);
    const auto coordinate = coordinateAdder(ref, q, u);
    if (world.effects().size() != 1 || !fx.gravity || fx.gravity->g[0] != 0.0) return std::nullopt;
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
        const RigidBody& b = world.rigidBodies()[body.index];
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
        const Vec2 pa = world.jointSolver()->pointA(j, q), pb = world.jointSolver()->pointB(j, q);
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
                    w = std::max(w, std::abs(u[world.rigidBodies()[body->index].dof + 2]));
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
    for (const RigidBody& b : world.rigidBodies())
        if (b.dof >= 0 && !held[b.dof]) return std::nullopt;
    ref.kind = "Atwood machine";
    return ref;
}

// Pendulums only: every dynamic body held by one joint to a fixed point under gravity
// alone: a particle by a rod, a taut rope or a circular track, a rigid body as
// rigidPendulum() says.
std::optional<ExactReference> pendulums(const SceneDesc& scene, const World& world, double) {
    const EffectsDesc& fx = scene.effects;
    const Vec &q = world.positions(), &u = world.velocities();
    ExactReference::Parts ref = emptyParts(world);
    if (world.effects().size() != 1 || !fx.gravity) return std::nullopt;
    const Vec2 g(fx.gravity->g[0], fx.gravity->g[1]);
    std::vector<int> heldBy(world.particles().size(), -1);
    std::vector<char> rigidHeld(world.rigidBodies().size(), 0);
    const auto& joints = world.joints();
    for (int j = 0; j < static_cast<int>(joints.size()); ++j) {
        const Joint& joint = joints[j];
        if (joint.a.kind == JointBody::Kind::Rigid) {
            const auto motion = rigidPendulum(world, j, g);
            if (!motion || rigidHeld[joint.a.index]) return std::nullopt;
            rigidHeld[joint.a.index] = 1;
            ref.rigidPendulums.push_back(*motion);
            continue;
        }
        const bool rope = joint.type == Joint::Type::Rope;
        const bool rod = joint.type == Joint::Type::Rod || rope;
        const bool hoop = joint.type == Joint::Type::Track && joint.circle;
        if ((!rod && !hoop) || joint.a.kind != JointBody::Kind::Particle) return std::nullopt;
        const Particle& p = world.particles()[joint.a.index];
        if (p.dof < 0 || heldBy[joint.a.index] >= 0) return std::nullopt;
        Vec2 centre = joint.center;
        double length = joint.radius;
        if (rod) {
            if (!heldToFixed(world, joint)) return std::nullopt;
            centre = world.jointSolver()->pointB(j, q);
            length = joint.length;
        }
        const auto motion =
            PendulumMotion::fromState(centre, length, g, q.segment<2>(p.dof), u.segment<2>(p.dof));
        if (!motion) return std::nullopt;
        const double distance = (q.segment<2>(p.dof) - centre).norm();
        if (rope && (!ropeStaysTaut(*motion) || std::abs(distance - length) > 1e-9 * length))
            return std::nullopt;
        heldBy[joint.a.index] = j;
        ref.pendulums.push_back({p.dof, *motion});
    }
    for (std::size_t i = 0; i < world.particles().size(); ++i)
        if (world.particles()[i].dof >= 0 && heldBy[i] < 0) return std::nullopt;
    for (std::size_t i = 0; i < world.rigidBodies().size(); ++i)
        if (world.rigidBodies()[i].dof >= 0 && !rigidHeld[i]) return std::nullopt;
    const bool physical =
        std::any_of(ref.rigidPendulums.begin(), ref.rigidPendulums.end(),
                    [](const ExactReference::RigidPendulum& p) { return p.hinged; });
    ref.kind = physical ? "physical pendulum" : "simple pendulum";
    return ref;
}

// Kepler: one fixed attractor and nothing else, so every body moves on its own conic.
std::optional<ExactReference> keplerOrbits(const SceneDesc& scene, const World& world, double) {
    const EffectsDesc& fx = scene.effects;
    const Vec &q = world.positions(), &u = world.velocities();
    ExactReference::Parts ref = emptyParts(world);
    const auto coordinate = coordinateAdder(ref, q, u);
    if (world.effects().size() != 1 || !fx.newtonianGravity) return std::nullopt;
    const NewtonianGravityDesc& ng = *fx.newtonianGravity;
    if (ng.mutual || ng.softening != 0.0 || ng.attractors.size() != 1) return std::nullopt;
    const double mu = ng.G * ng.attractors[0].mass;
    const Vec2 centre(ng.attractors[0].position[0], ng.attractors[0].position[1]);
    ref.kind = mu != 0.0 ? "Kepler orbit" : "free motion";
    const auto body = [&](int dof) {
        if (mu == 0.0) {
            coordinate(dof, 0.0, 0.0, 0.0);
            coordinate(dof + 1, 0.0, 0.0, 0.0);
            return true;
        }
        const auto orbit =
            KeplerMotion::fromState(centre, q.segment<2>(dof), u.segment<2>(dof), mu);
        if (orbit) ref.orbits.push_back({dof, *orbit});
        return orbit.has_value();
    };
    for (const Particle& p : world.particles())
        if (p.dof >= 0 && !body(p.dof)) return std::nullopt;
    for (const RigidBody& b : world.rigidBodies()) {
        if (b.dof < 0) continue;
        if (!body(b.dof)) return std::nullopt;
        coordinate(b.dof + 2, 0.0, 0.0, 0.0);  // no torque about the centre: θ = θ₀ + ω₀t
    }
    return ref;
}

// Oscillators on fixed springs, free fall and free motion, with linear drag and wind: each
// coordinate on its own (or along its spring's axis), or the coupled modes of springs on a line.
std::optional<ExactReference> oscillatorsAndFalls(const SceneDesc& scene, const World& world,
                                                  double endTime) {
    const EffectsDesc& fx = scene.effects;
    const Vec &q = world.positions(), &u = world.velocities();
    ExactReference::Parts ref = emptyParts(world);
    const auto coordinate = coordinateAdder(ref, q, u);
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
    const auto& boxes = world.rigidBodies();
    std::vector<std::vector<Anchored>> springsOf(particles.size());
    const auto fixedPoint = [&](const SpringEnd& end) -> std::optional<Vec2> {
        switch (end.kind) {
            case SpringEnd::Kind::Anchor:
                return end.point;
            case SpringEnd::Kind::Particle:
                if (particles[end.index].pinned) return particles[end.index].position;
                return std::nullopt;
            case SpringEnd::Kind::Rigid: {
                const RigidBody& b = boxes[end.index];
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
        ref.axes.push_back({p.dof, anchor, axis, along});
    }
    for (const RigidBody& b : boxes) {
        if (b.dof < 0) continue;
        for (int k = 0; k < 2; ++k) coordinate(b.dof + k, 0.0, drag.linear / b.mass, g[k]);
        coordinate(b.dof + 2, 0.0, drag.angular / b.inertia, 0.0);
    }

    if (anySpring)
        ref.kind = damped ? "damped harmonic oscillator" : "harmonic oscillator";
    else if (g != Vec2::Zero())
        ref.kind = damped ? "free fall with linear drag" : "free fall";
    else
        ref.kind = damped ? "motion with linear drag" : "free motion";
    return ref;
}

bool onlyPulleys(const World& world) {
    return !world.joints().empty() &&
           std::all_of(world.joints().begin(), world.joints().end(),
                       [](const Joint& j) { return j.type == Joint::Type::Pulley; });
}
bool anyJoint(const World& world) {
    return !world.joints().empty();
}
bool attractors(const World& world) {
    return world.findEffect(std::string(effectName::newtonianGravity)) != nullptr;
}
bool anyWorld(const World&) {
    return true;
}

// The recognisers of closed forms, in the order they are tried. The first whose case the world
// is answers for it, with its closed form or with nullopt when the world is its case but not
// exactly (a pulley rope at an angle, a pendulum on a moving pivot): a world is one case only, so
// trying the next would only find a weaker answer. A new closed form is one more row.
struct Recogniser {
    bool (*isItsCase)(const World&);
    std::optional<ExactReference> (*recognise)(const SceneDesc&, const World&, double endTime);
};
constexpr Recogniser kRecognisers[] = {
    {onlyPulleys, atwoodMachines},
    {anyJoint, pendulums},
    {attractors, keplerOrbits},
    {anyWorld, oscillatorsAndFalls},
};

// The closed form as if no contact ever happened; findExactReference checks that none does.
std::optional<ExactReference> ignoringContacts(const SceneDesc& scene, const World& world,
                                               double endTime) {
    for (const auto& effect : world.effects()) {
        const std::string& name = effect->name();
        if (name != effectName::gravity && name != effectName::drag && name != effectName::wind &&
            name != effectName::springs && name != effectName::newtonianGravity)
            return std::nullopt;
    }
    for (const Recogniser& recogniser : kRecognisers)
        if (recogniser.isItsCase(world)) return recogniser.recognise(scene, world, endTime);
    return std::nullopt;
}

}  // namespace

std::optional<ExactReference> findExactReference(const SceneDesc& scene, const World& world,
                                                 double endTime) {
    std::optional<ExactReference> ref = ignoringContacts(scene, world, endTime);
    if (ref && world.contacts() && contactFreeUntil(*ref, world, endTime) <= endTime)
        return std::nullopt;
    return ref;
}

std::optional<ExactReference> findDisplayReference(const SceneDesc& scene, const World& world,
                                                   double endTime) {
    // A closed form for the whole run first, then single bodies' (which go on through their
    // contacts: bounces, rolling and sliding), then the scene's up to its first contact.
    if (auto whole = findExactReference(scene, world, endTime)) return whole;
    if (auto impact = findImpactReference(scene, world, endTime)) return impact;
    std::optional<ExactReference> bodies = findBodyReferences(scene, world, endTime);
    if (auto supported = findSupportedReferences(scene, world, endTime)) {
        if (!bodies) return supported;
        ExactReference::Parts both = bodies->parts();
        const ExactReference::Parts& more = supported->parts();
        both.kind += ", " + more.kind;
        both.validUntil = std::min(both.validUntil, more.validUntil);
        for (const auto& b : more.bounces) both.bounces.push_back(b);
        for (const auto& c : more.coordinates) both.coordinates.push_back(c);
        bodies = std::move(both);
    }
    if (bodies) return bodies;
    std::optional<ExactReference> ref = ignoringContacts(scene, world, endTime);
    if (ref && world.contacts()) {
        const double until = contactFreeUntil(*ref, world, endTime);
        // Drawn up to the first contact that can happen, when that leaves ten steps or more to
        // draw (bodies resting on one another at the start meet at once).
        if (until < 10.0 * scene.simulation.dt) return std::nullopt;
        if (until <= endTime) {
            ExactReference::Parts upToContact = ref->parts();
            upToContact.validUntil = until;
            ref = std::move(upToContact);
        }
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
    for (const RigidBody& b : world.rigidBodies())
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
    ExactReference::Parts ref = emptyParts(world);
    ref.kind = "coupled oscillators";
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
    ref.modes.push_back(std::move(m));
    return ref;
}

}  // namespace phasebox
