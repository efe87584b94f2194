#pragma once
// Scenes shared by the GUI suites, built from the scene description as the app loads them.

#include "physics/scene/SceneDesc.h"
#include "tests/support/SceneBuilders.h"

#include <string>

namespace phasebox::testing {

// The GUI suites' particles are 10 cm in radius: big enough to be seen and picked.
inline ParticleDesc visibleParticle(const std::string& id, Point2 position, double mass = 1.0,
                                    Point2 velocity = {0.0, 0.0}) {
    return particle(id, position, mass, velocity, 0.1);
}

// Two masses on a spring and a spinning box, no external force: the total momentum
// (1·1 + 3·(−0.2), 1·0.5 + 3·0.1) = (0.4, 0.8) stays, and the centre of mass moves with it.
inline SceneDesc freeScene() {
    SceneDesc scene;
    scene.name = "Free system";
    scene.particles.push_back(visibleParticle("a", {-1.0, 0.0}, 1.0, {1.0, 0.5}));
    scene.particles.push_back(visibleParticle("b", {1.0, 0.0}, 3.0, {-0.2, 0.1}));
    BoxDesc box;
    box.id = "spinner";
    box.position = {0.0, 3.0};
    box.angularVelocity = 2.0;
    scene.boxes.push_back(box);
    scene.springs.push_back(bodySpring("a", "b", 20.0));
    return scene;
}

}  // namespace phasebox::testing
