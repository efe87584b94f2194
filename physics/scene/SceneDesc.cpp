// What a scene description works out of itself besides ids (SceneIds.cpp), polygon mass
// (PolygonMass.cpp) and work budgets (WorkBudget.cpp): a disk's mass and which cloth nodes are
// pinned. validateScene() is in SceneValidation.cpp.
#include "physics/scene/SceneDesc.h"

#include <algorithm>
#include <numbers>

namespace phasebox {

double DiskDesc::resolvedMass() const {
    return mass ? *mass : density * std::numbers::pi * radius * radius;
}

bool clothNodePinned(const ClothDesc& cloth, int i, int j) {
    if (const auto* mode = std::get_if<std::string>(&cloth.pinned)) {
        if (*mode == "top") return j == 0;
        if (*mode == "top_corners") return j == 0 && (i == 0 || i == cloth.resolution[0] - 1);
        if (*mode == "left") return i == 0;
        return false;
    }
    const auto& nodes = std::get<std::vector<std::array<int, 2>>>(cloth.pinned);
    return std::find(nodes.begin(), nodes.end(), std::array<int, 2>{i, j}) != nodes.end();
}

}  // namespace phasebox
