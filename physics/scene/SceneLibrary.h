#pragma once
// Named scenes, built in code so that the tests, the benchmarks, the command line and the app
// share them: the scene that is benchmarked is the scene that can be opened and looked at.

#include "physics/scene/SceneDesc.h"

#include <functional>
#include <string>
#include <vector>

namespace phasebox::scenes {

// A new document's scene: "Untitled", gravity, and the plane "ground" 2 m below the origin.
SceneDesc untitled();

// A pyramid of `rows` rows of 1 m boxes on a ground plane (friction 0.6), base centred at x = 0.
SceneDesc pyramid(int rows);
// The same pyramid of hexagons (1 m across the flats, pointy side up), stacked like a
// honeycomb, rows 0.866 m apart.
SceneDesc hexagonPyramid(int rows);
// A single column of `count` 1 m boxes on the ground.
SceneDesc tower(int count);
// Three boxes stacked bottom to top with these masses (e.g. 1, 20, 400 kg): heavy on light.
SceneDesc stack(const std::vector<double>& masses);
// A 2 m box `ratio` times heavier than the 0.5 m box it stands on.
SceneDesc bigOnSmall(double ratio);
// A ball (radius 0.1 m) whose bottom starts `height` above a floor, with this restitution.
SceneDesc ballDrop(double height, double restitution);
// A 1 m box resting on a plane inclined by `degrees`, friction μ on both (so the pair's μ).
SceneDesc incline(double degrees, double friction);
// `count` disks (radius 0.05 m, e = 1, μ = 0) with random velocities in a closed box: 4 m, or
// wider when that is needed to start the disks 3 radii apart (above ~625 disks).
SceneDesc elasticGas(int count, unsigned seed = 1);
// `count` touching balls in a row, the first moving into them at `speed`.
SceneDesc newtonsCradle(int count, double speed);
// A 0.05 m disk at `speed` toward a static wall 0.1 m thick.
SceneDesc bullet(double speed);
// A row of `count` dominoes (0.1 × 1 m, 0.5 m apart), the first one tipped over.
SceneDesc dominoes(int count);

// `links` hinged boxes of 1 m × 0.25 m (density 20, friction 0.2) laid end to end along y = 20 m,
// box i centred at x = 0.5 + i and hinged to the next at their shared end, the first to the world
// at the origin; released from rest under g = 10 m/s² it swings down and whips. No ground. The
// chain Box2D's benchmarks swing (its "chain" sample), so that the two can be timed side by side.
SceneDesc hingedChain(int links);

// `count` bodies of masses 0.5–2 kg under their mutual gravity (G = 1, no softening): three
// Gaussian clusters of different widths and a uniform background, so that a Barnes–Hut tree
// sees dense cores, sparse outskirts and empty cells (a uniform cloud alone is the easy case).
// Symplectic Euler at dt = 10⁻³; the same seed gives the same bodies.
SceneDesc clusteredBodies(int count, unsigned seed = 42);

// An n × n cloth of 1 m × 1 m, 1 kg in all, pinned along its top edge, structural stiffness
// k (shear k/10, bend k/100), under gravity, stepped by implicit Euler at dt = 1/60.
SceneDesc cloth(int n, double structuralStiffness);

struct NamedScene {
    std::string name;
    std::string summary;
    std::function<SceneDesc()> make;
};
// The library with default sizes, for `phasebox-cli scene` and the app.
const std::vector<NamedScene>& library();

}  // namespace phasebox::scenes
