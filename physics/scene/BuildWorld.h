#pragma once
// SceneDesc → World. Constructs exactly the effects the scene lists plus what its objects
// imply (springs → the spring effect); nothing else exists, so nothing else costs.

#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace phasebox {

// Thrown by buildWorld for a scene that does not validate; carries every issue.
class SceneError : public std::runtime_error {
public:
    explicit SceneError(std::vector<SceneIssue> issues);
    const std::vector<SceneIssue>& issues() const { return issues_; }

private:
    std::vector<SceneIssue> issues_;
};

struct BuildResult {
    std::unique_ptr<World> world;
    // Things the scene asks for that this engine does not simulate yet, by effect name.
    std::vector<std::string> unsupported;
};

// The contact solver's settings from the scene's simulation.solver (keys as documented in
// docs/scene-format.md; absent keys keep their defaults).
ContactSettings contactSettings(const std::map<std::string, double>& solver);
// The world's settings from the scene's simulation section.
SimulationSettings simulationSettings(const SimulationDesc& sim);

// Throws SceneError when validateScene() finds issues.
BuildResult buildWorld(const SceneDesc& scene);

// The node index (into World::particles()) of cloth node (i, j).
inline int clothNode(const Cloth& cloth, int i, int j) {
    return cloth.firstParticle + j * cloth.nx + i;
}

}  // namespace phasebox
