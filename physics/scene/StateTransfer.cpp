#include "physics/scene/StateTransfer.h"

#include <string_view>
#include <unordered_map>

namespace phasebox {

namespace {
// Index of every dynamic particle and box of a world by id. Views into the world's own
// strings: the maps live no longer than the call.
struct DynamicIndex {
    std::unordered_map<std::string_view, int> particles, boxes;

    explicit DynamicIndex(const World& world) {
        particles.reserve(world.particles().size());
        for (int i = 0; i < static_cast<int>(world.particles().size()); ++i)
            if (!world.particles()[i].pinned) particles.emplace(world.particles()[i].id, i);
        for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i)
            if (!world.rigidBodies()[i].isStatic) boxes.emplace(world.rigidBodies()[i].id, i);
    }
    static int find(const std::unordered_map<std::string_view, int>& map, std::string_view id) {
        const auto it = map.find(id);
        return it == map.end() ? -1 : it->second;
    }
};

Point2 point(const Vec2& v) {
    return {v.x(), v.y()};
}
}  // namespace

void transferState(const World& from, World& to, const std::unordered_set<std::string>& keepSetup) {
    to.commit();  // the dofs of `to` must be assigned before its state is written
    const DynamicIndex source(from);
    Vec q = to.positions();
    Vec u = to.velocities();
    for (const Particle& p : to.particles()) {
        if (p.dof < 0 || keepSetup.count(p.id)) continue;
        const int k = DynamicIndex::find(source.particles, p.id);
        if (k < 0) continue;
        q.segment<2>(p.dof) = from.particlePosition(k);
        u.segment<2>(p.dof) = from.particleVelocity(k);
    }
    for (const RigidBody& b : to.rigidBodies()) {
        if (b.dof < 0 || keepSetup.count(b.id)) continue;
        const int k = DynamicIndex::find(source.boxes, b.id);
        if (k < 0) continue;
        q.segment<2>(b.dof) = from.bodyPosition(k);
        q[b.dof + 2] = from.bodyAngle(k);
        u.segment<2>(b.dof) = from.bodyVelocity(k);
        u[b.dof + 2] = from.bodyAngularVelocity(k);
    }
    to.setState(q, u);
    to.setTime(from.time());
    to.resetEnergyBaseline();
}

SceneDesc snapshotScene(const World& world, const SceneDesc& setup) {
    SceneDesc scene = setup;
    const DynamicIndex live(world);
    for (std::size_t i = 0; i < scene.particles.size(); ++i) {
        ParticleDesc& p = scene.particles[i];
        if (p.pinned) continue;
        const int k = DynamicIndex::find(live.particles, particleId(setup, i));
        if (k < 0) continue;
        p.position = point(world.particlePosition(k));
        p.velocity = point(world.particleVelocity(k));
    }
    for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
        BoxDesc& b = scene.boxes[i];
        if (b.isStatic) continue;
        const int k = DynamicIndex::find(live.boxes, boxId(setup, i));
        if (k < 0) continue;
        b.position = point(world.bodyPosition(k));
        b.angle = world.bodyAngle(k);
        b.velocity = point(world.bodyVelocity(k));
        b.angularVelocity = world.bodyAngularVelocity(k);
    }
    return scene;
}

}  // namespace phasebox
