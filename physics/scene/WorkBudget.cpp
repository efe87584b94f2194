// The work a step of a scene costs (stepWorkUnits) and the refusal of more sub-steps than
// SceneLimits::kMaxSubstepWork allows for it.
#include "physics/scene/SceneDesc.h"

#include <algorithm>
#include <string>

namespace phasebox {

long long stepWorkUnits(const SceneDesc& scene) {
    const auto count = [](const auto& objects) { return static_cast<long long>(objects.size()); };
    long long units = count(scene.particles) + count(scene.springs) +
                      SceneLimits::kCostlyWorkUnits * (count(scene.boxes) + count(scene.disks) +
                                                       count(scene.polygons) + count(scene.joints));
    for (const ClothDesc& cloth : scene.cloths) {
        const long long nx = std::max(0, cloth.resolution[0]),
                        ny = std::max(0, cloth.resolution[1]);
        // Its nodes and at most its structural, shear and bend springs.
        units += nx * ny + nx * std::max(0LL, ny - 1) + ny * std::max(0LL, nx - 1) +
                 2 * std::max(0LL, nx - 1) * std::max(0LL, ny - 1) + nx * std::max(0LL, ny - 2) +
                 ny * std::max(0LL, nx - 2);
    }
    return units;
}

std::string substepWorkProblem(const SceneDesc& scene, long long substeps) {
    const long long units = std::max(1LL, stepWorkUnits(scene));
    if (substeps <= SceneLimits::kMaxSubstepWork / units) return {};
    return std::to_string(substeps) + " sub-steps of a scene of " + std::to_string(units) +
           " work units (a particle, cloth node or spring 1, a rigid body or joint " +
           std::to_string(SceneLimits::kCostlyWorkUnits) + ") is " +
           "too much work a step: sub-steps times units may be at most " +
           std::to_string(SceneLimits::kMaxSubstepWork) + ", so at most " +
           std::to_string(SceneLimits::kMaxSubstepWork / units) + " sub-steps for this scene";
}

}  // namespace phasebox
