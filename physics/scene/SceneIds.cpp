// The default ids of a scene's objects (p0, b1, ... by position in their list, with the
// prefixes of ObjectKinds.h) and of a cloth's nodes (cloth[i,j]), for the validator, the world
// and the app.
#include "physics/scene/ObjectKinds.h"

#include <string>

namespace phasebox {

namespace {
std::string defaultOr(const std::string& id, ObjectKind kind, std::size_t index) {
    return id.empty() ? std::string(schema::kindInfo(kind).idPrefix) + std::to_string(index) : id;
}
}  // namespace

std::string particleId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.particles[i].id, ObjectKind::Particle, i);
}
std::string boxId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.boxes[i].id, ObjectKind::Box, i);
}
std::string diskId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.disks[i].id, ObjectKind::Disk, i);
}
std::string polygonId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.polygons[i].id, ObjectKind::Polygon, i);
}
std::string planeId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.planes[i].id, ObjectKind::Plane, i);
}
std::string springId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.springs[i].id, ObjectKind::Spring, i);
}
std::string jointId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.joints[i].id, ObjectKind::Joint, i);
}
std::string clothNodeId(const std::string& clothId, int i, int j) {
    return clothId + "[" + std::to_string(i) + "," + std::to_string(j) + "]";
}

}  // namespace phasebox
