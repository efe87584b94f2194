#pragma once
// Broad phase: which pairs of bounding boxes overlap. Sweep and prune along x: the order of
// the boxes by their lower x is kept from call to call and repaired by insertion sort, which is
// nearly linear when bodies move a little per step. Planes are not in it (they are infinite;
// the world tests them against every body).

#include "physics/contacts/Geometry.h"

#include <utility>
#include <vector>

namespace phasebox {

class BroadPhase {
public:
    // Fills pairs with every (i, j), i < j, whose boxes overlap, sorted by (i, j) so that the
    // result does not depend on the sweep's internal order. Allocation-free once the buffers
    // have grown to the scene's size.
    void findPairs(const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>& pairs);

private:
    std::vector<int> order_;  // indices sorted by lower x, kept between calls
};

}  // namespace phasebox
