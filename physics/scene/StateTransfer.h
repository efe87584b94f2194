#pragma once
// Carrying a running simulation across a rebuilt world, and freezing it into a scene.
//
// The app edits a scene by changing its setup (a SceneDesc) and rebuilding the World from it;
// these two functions keep a run going across such an edit. Objects are matched by id, so an
// object that exists in both worlds continues where it was, and a new one starts from its
// setup values.

#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"

#include <string>
#include <unordered_set>

namespace phasebox {

// Copies the live position and velocity (and a box's angle and angular velocity) of every
// object that is dynamic in both worlds and has the same id and kind in both (cloth nodes by
// their ids ID[i,j]), and the clock: to.time() becomes from.time(). Objects named in
// keepSetup keep the values `to` was built with (an object the user just moved). Afterwards
// the energy baseline of `to` is its new state: work_nc and drift start again from 0, because
// the edit itself changes the energy and is not integration error.
void transferState(const World& from, World& to,
                   const std::unordered_set<std::string>& keepSetup = {});

// The setup with every particle's and box's position and velocity (box angle and angular
// velocity too) replaced by its live value in `world`, matched by id; pinned particles and
// static boxes keep theirs. Cloths cannot be snapshotted: a cloth is described by its origin,
// size and resolution, not node by node, so its nodes' live positions have no place in the
// scene format and the cloth comes back in its setup shape.
SceneDesc snapshotScene(const World& world, const SceneDesc& setup);

}  // namespace phasebox
