#include "physics/contacts/BroadPhase.h"

#include <algorithm>
#include <numeric>

namespace phasebox {

void BroadPhase::findPairs(const std::vector<Aabb>& boxes,
                           std::vector<std::pair<int, int>>& pairs) {
    pairs.clear();
    const int count = static_cast<int>(boxes.size());
    const auto lowerX = [&boxes](int i) { return boxes[i].lower.x(); };

    if (order_.size() != boxes.size()) {
        // A changed count means the old order names other boxes (or missing ones): start over
        // with a full sort, since insertion sort on an unsorted list is quadratic.
        order_.resize(boxes.size());
        std::iota(order_.begin(), order_.end(), 0);
        std::sort(order_.begin(), order_.end(),
                  [&](int i, int j) { return lowerX(i) < lowerX(j); });
    } else {
        // Bodies move a little per step, so each box is at most a few places out of order.
        for (int k = 1; k < count; ++k) {
            const int box = order_[k];
            const double x = lowerX(box);
            int slot = k;
            while (slot > 0 && lowerX(order_[slot - 1]) > x) {
                order_[slot] = order_[slot - 1];
                --slot;
            }
            order_[slot] = box;
        }
    }

    // The boxes that overlap box i along x and start no earlier than it are those that follow
    // it in the order up to the first one starting beyond its upper x; the y test decides.
    for (int k = 0; k < count; ++k) {
        const int i = order_[k];
        const Aabb& box = boxes[i];
        const double upperX = box.upper.x();
        for (int l = k + 1; l < count; ++l) {
            const int j = order_[l];
            const Aabb& other = boxes[j];
            if (other.lower.x() > upperX) break;
            if (box.overlaps(other)) pairs.emplace_back(std::min(i, j), std::max(i, j));
        }
    }
    std::sort(pairs.begin(), pairs.end());
}

}  // namespace phasebox
