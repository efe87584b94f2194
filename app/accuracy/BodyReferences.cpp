// Closed forms of single bodies that go on through their contacts: a ball bouncing straight on
// a plane (penalty or impulse contacts), boxes and disks sliding or rolling on a static box.

#include "app/accuracy/ExactReference.h"

#include "app/accuracy/ExactReferenceDetail.h"
#include "physics/contacts/ContactModel.h"
#include "physics/contacts/ContactSolver.h"
#include "physics/core/EffectNames.h"
#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace phasebox {

using namespace exact_detail;

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
    const auto& boxes = world.rigidBodies();

    ExactReference::Parts ref;
    ref.dimension = world.dimension();
    ref.kind = "rolling and sliding";
    double until = endTime;
    constexpr double kMargin = 0.02;  // m, the contact stage's speculative distance
    constexpr double kTouch = 1e-5;   // m: a body placed on a face to this
    constexpr int kSamples = 400;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const RigidBody& body = boxes[i];
        if (body.dof < 0 || body.shape == RigidShape::Polygon || u[body.dof + 2] != 0.0) continue;
        const bool disk = body.shape == RigidShape::Disk;
        const Vec2 c0 = q.segment<2>(body.dof), v0 = u.segment<2>(body.dof);
        const double angle0 = q[body.dof + 2];
        // The support: a static rectangle's face, facing up at most 60° from the vertical, that
        // the body lies on (a disk touching it, a box with a face flat on it).
        const RigidBody* support = nullptr;
        Vec2 n, t;
        double depth = 0.0;     // from the body's centre to the face along −n
        double faceHalf = 0.0;  // half the face's length
        for (const RigidBody& s : boxes) {
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
            for (const RigidBody& other : boxes) {
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
        ref.bounces.push_back({body.dof, c0, t, motion});
        ref.coordinates.push_back({body.dof + 2, LinearMotion{0.0, 0.0, alpha, angle0, 0.0}});
    }
    if (ref.bounces.empty()) return std::nullopt;
    if (until < endTime) ref.validUntil = until;
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
    const auto& boxes = world.rigidBodies();
    std::vector<char> attachedParticle(particles.size(), 0), attachedBox(boxes.size(), 0);
    const auto attach = [&](SpringEnd::Kind kind, int index) {
        if (kind == SpringEnd::Kind::Particle) attachedParticle[index] = 1;
        if (kind == SpringEnd::Kind::Rigid) attachedBox[index] = 1;
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
        const RigidBody& b = boxes[i];
        const Vec2 x = b.dof >= 0 ? Vec2(q.segment<2>(b.dof)) : b.position;
        const double reach = b.shape == RigidShape::Disk ? b.radius : 0.5 * b.size.norm();
        others.emplace_back(x, reach);
        if (b.dof >= 0 && b.shape == RigidShape::Disk && !attachedBox[i] && u[b.dof + 2] == 0.0)
            candidates.push_back({b.dof, x, u.segment<2>(b.dof), b.radius, b.mass, b.restitution});
    }

    ExactReference::Parts ref;
    ref.dimension = world.dimension();
    ref.kind = penalty ? "penalty bounce" : "bounce";
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
            penalty ? PenaltyBounceMotion::fromState(height, body.velocity.dot(up), g.norm(),
                                                     body.radius, k, c, body.mass, endTime)
                    : PenaltyBounceMotion::impulse(
                          height, body.velocity.dot(up), g.norm(), body.radius,
                          std::max(body.restitution, floor->restitution),
                          world.settings().contacts.restitutionThreshold, endTime);
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
        if (clear) ref.bounces.push_back({body.dof, base, up, motion});
    }
    if (ref.bounces.empty()) return std::nullopt;
    return ref;
}

}  // namespace phasebox
