#include "physics/world/FreeBody.h"

#include "physics/core/EffectNames.h"
#include "physics/world/World.h"

namespace phasebox {

std::optional<FreeBody> freeBodyOf(const World& world, std::string_view id) {
    const std::optional<ProbeObject> object = findProbeObject(world, id);
    if (!object) return std::nullopt;
    const int dof = object->rigid ? world.rigidBodies()[object->index].dof
                                  : world.particles()[object->index].dof;
    const Vec& q = world.positions();
    const Vec& u = world.velocities();
    if (dof < 0 || q.size() < dof + 2 || u.size() < dof + 2) return std::nullopt;

    FreeBody body;
    body.body = *object;
    body.position = q.segment<2>(dof);
    body.mass = world.mass()[dof];
    body.momentum = body.mass * u.segment<2>(dof);

    Vec scratch = Vec::Zero(q.size());
    for (const auto& effect : world.effects()) {
        // The spring effect is every spring at once: its springs are listed one by one below.
        if (effect->name() == effectName::springs) continue;
        scratch.setZero();
        effect->addForces(world.time(), q, u, scratch);
        const Vec2 f = scratch.segment<2>(dof);
        if (f != Vec2::Zero())
            body.forces.push_back({BodyForce::Source::Effect, effect->name(), f});
    }

    const auto isBody = [&](bool rigid, int index) {
        return rigid == object->rigid && index == object->index;
    };
    const auto& springs = world.springs();
    for (int i = 0; i < static_cast<int>(springs.size()); ++i) {
        const Spring& s = springs[i];
        const auto on = [&](const SpringEnd& end) {
            return end.kind != SpringEnd::Kind::Anchor &&
                   isBody(end.kind == SpringEnd::Kind::Rigid, end.index);
        };
        if (!on(s.a) && !on(s.b)) continue;
        const Vec2 d = world.springEndPosition(s.b) - world.springEndPosition(s.a);
        // Stretched (positive tension): a is pulled toward b, b toward a.
        const Vec2 pull =
            d.norm() > 0.0 ? Vec2(world.springTension(i) * d.normalized()) : Vec2::Zero();
        Vec2 f = Vec2::Zero();
        if (on(s.a)) f += pull;
        if (on(s.b)) f -= pull;
        body.forces.push_back({BodyForce::Source::Spring, s.id, f});
    }

    const Vec2 contact = world.contactForce(dof);
    if (contact != Vec2::Zero())
        body.forces.push_back({BodyForce::Source::Contact, "contact", contact});

    if (world.jointSolver()) {
        const auto on = [&](const JointBody& b) {
            return b.kind != JointBody::Kind::World &&
                   isBody(b.kind == JointBody::Kind::Rigid, b.index);
        };
        for (int i = 0; i < static_cast<int>(world.joints().size()); ++i) {
            const Joint& j = world.joints()[i];
            if (!on(j.a) && !on(j.b)) continue;
            Vec2 f = Vec2::Zero();
            if (on(j.a)) f += world.jointForceOn(i, false);
            if (on(j.b)) f += world.jointForceOn(i, true);
            body.forces.push_back({BodyForce::Source::Joint, j.id, f});
        }
    }
    return body;
}

}  // namespace phasebox
