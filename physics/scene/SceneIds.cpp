// The default ids of a scene's objects (p0, b1, ... by position in their list) and of a
// cloth's nodes (cloth[i,j]): spelled here once, for the validator, the world and the app.
#include "physics/scene/SceneDesc.h"

#include <string>

namespace phasebox {

namespace {
std::string defaultOr(const std::string& id, const char* prefix, std::size_t index) {
    return id.empty() ? prefix + std::to_string(index) : id;
}
}  // namespace

std::string particleId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.particles[i].id, "p", i);
}
std::string boxId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.boxes[i].id, "b", i);
}
std::string diskId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.disks[i].id, "d", i);
}
std::string polygonId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.polygons[i].id, "poly", i);
}
std::string planeId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.planes[i].id, "plane", i);
}
std::string springId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.springs[i].id, "s", i);
}
std::string jointId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.joints[i].id, "j", i);
}
std::string clothNodeId(const std::string& clothId, int i, int j) {
    return clothId + "[" + std::to_string(i) + "," + std::to_string(j) + "]";
}

}  // namespace phasebox
