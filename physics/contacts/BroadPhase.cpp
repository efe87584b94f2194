#include "physics/contacts/BroadPhase.h"

#include "physics/core/WorkerPool.h"

#include <algorithm>
#include <numeric>

namespace phasebox {

namespace {

// The sweep switches axis only when the other one is clearly better: near-square scenes would
// otherwise flip back and forth, paying a full sort each time.
constexpr double kAxisSwitchRatio = 1.5;

// Insertion sort moves each box past the boxes it overtook since the last call. Beyond this
// many moves per box on average the order is scrambled and a full sort is cheaper.
constexpr long long kRepairMovesPerBox = 8;

// Positions of the order a chunk of the shared sweep takes (a box visits a few to a few hundred
// others along the axis), and the overlaps per box a chunk keeps before it is swept again with
// the caps applied as it goes (a box in a stack or a resting pile has at most a dozen).
constexpr int kSweepGrain = 512;
constexpr int kKeptPerBox = 24;
// Fewer boxes are swept on the calling thread: their sweep costs about what handing it out does.
constexpr int kSharedSweepBoxes = 512;

}  // namespace

void BroadPhase::sortOrder(const std::vector<Aabb>& boxes, bool fresh) {
    const int count = static_cast<int>(boxes.size());
    const int axis = axis_;
    const auto lower = [&boxes, axis](int i) { return boxes[i].lower[axis]; };
    const auto fullSort = [&] {
        std::sort(order_.begin(), order_.end(), [&](int i, int j) { return lower(i) < lower(j); });
    };
    if (fresh) {
        fullSort();
        return;
    }
    // Bodies move a little per step, so each box is at most a few places out of order.
    const long long budget = kRepairMovesPerBox * count + 64;
    long long moves = 0;
    for (int k = 1; k < count; ++k) {
        const int box = order_[k];
        const double x = lower(box);
        int slot = k;
        while (slot > 0 && lower(order_[slot - 1]) > x) {
            order_[slot] = order_[slot - 1];
            --slot;
        }
        order_[slot] = box;
        moves += k - slot;
        if (moves > budget) {
            fullSort();  // still a permutation: the repair only moved entries
            return;
        }
    }
}

void BroadPhase::findPairs(const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>& pairs,
                           const PairCap& cap, WorkerPool* pool) {
    pairs.clear();
    candidatesVisited_ = 0;
    const int count = static_cast<int>(boxes.size());

    // The axis of larger spread of the centres (variance, about the mean).
    Vec2 mean = Vec2::Zero();
    for (const Aabb& b : boxes) mean += 0.5 * (b.lower + b.upper);
    if (count > 0) mean /= count;
    Vec2 spread = Vec2::Zero();
    for (const Aabb& b : boxes) spread += (0.5 * (b.lower + b.upper) - mean).cwiseAbs2();
    const int other = 1 - axis_;
    const bool switchAxis = spread[other] > kAxisSwitchRatio * spread[axis_];
    if (switchAxis) axis_ = other;

    // A changed count means the old order names other boxes (or missing ones): start over with
    // a full sort, since insertion sort on an unsorted list is quadratic. So does a new axis.
    const bool fresh = order_.size() != boxes.size() || switchAxis;
    if (order_.size() != boxes.size()) {
        order_.resize(boxes.size());
        std::iota(order_.begin(), order_.end(), 0);
    }
    sortOrder(boxes, fresh);
    const int cross = 1 - axis_;
    sortedBoxes_.resize(boxes.size());
    upper_.resize(boxes.size());
    for (int k = 0; k < count; ++k) {
        const Aabb& b = boxes[order_[k]];
        sortedBoxes_[k] = {b.lower[axis_], b.lower[cross], b.upper[cross], order_[k]};
        upper_[k] = b.upper[axis_];
    }

    const bool capped = cap.limited != nullptr;
    if (capped) {
        pairCount_.assign(boxes.size(), 0);
        nearCount_.assign(boxes.size(), 0);
    }
    // The positions in the order of the boxes that are not kApart: a kApart box (a particle
    // when particles do not collide) looks only at those, so that many particles piled at one
    // point beside a single rigid body cost a linear sweep, not a visit of every pair.
    otherAt_.clear();
    if (capped)
        for (int k = 0; k < count; ++k)
            if ((*cap.limited)[order_[k]] != PairCap::kApart) otherAt_.push_back(k);
    // Whether a pair of limited box i and box j is kept (and counted against their caps).
    const auto admit = [&](int i, int j, const Aabb& box, const Aabb& o) {
        const unsigned char kindJ = (*cap.limited)[j];
        if (kindJ == PairCap::kFree) return true;
        if (kindJ == PairCap::kApart && (*cap.limited)[i] == PairCap::kApart) return false;
        // Overlapping shapes (centres closer than the sum of the sizes; the boxes are grown
        // symmetrically, so their centres are the shapes') and near ones have caps of their
        // own, so that the overlapping ones of a pile cannot use up the places of a contact
        // about to be made. Each side counts the other when the other is at least half its
        // size.
        const double sizeI = (*cap.size)[i], sizeJ = (*cap.size)[j];
        const Vec2 twiceOffset = (o.lower + o.upper) - (box.lower + box.upper);
        const double twiceReach = 2.0 * (sizeI + sizeJ);
        const bool overlapping = twiceOffset.squaredNorm() < twiceReach * twiceReach;
        std::vector<int>& taken = overlapping ? pairCount_ : nearCount_;
        const int limit = overlapping ? cap.perBox : cap.nearPerBox;
        const bool countsForI = sizeJ >= 0.5 * sizeI;
        const bool countsForJ = sizeI >= 0.5 * sizeJ;
        if ((countsForI && taken[i] >= limit) || (countsForJ && taken[j] >= limit)) return false;
        taken[i] += countsForI;
        taken[j] += countsForJ;
        return true;
    };

    const auto keep = [&](int i, int j) {
        const unsigned char kindI = capped ? (*cap.limited)[i] : PairCap::kFree;
        if (kindI != PairCap::kFree && !admit(i, j, boxes[i], boxes[j])) return;
        pairs.emplace_back(std::min(i, j), std::max(i, j));
    };
    const auto firstOtherAfter = [&](int k) {
        return static_cast<std::size_t>(std::upper_bound(otherAt_.begin(), otherAt_.end(), k) -
                                        otherAt_.begin());
    };
    // The sweep in chunks of the order, each into its own buffer (shared among the pool's
    // workers); the caps then take the overlaps in the order of the sweep.
    const int chunkCount = WorkerPool::chunkCount(count, kSweepGrain);
    if (chunks_.size() < static_cast<std::size_t>(chunkCount)) chunks_.resize(chunkCount);
    const auto sweepChunks = [&](int beginChunk, int endChunk, int) {
        for (int c = beginChunk; c < endChunk; ++c) {
            Chunk& chunk = chunks_[c];
            chunk.found.clear();
            chunk.visited = 0;
            chunk.overflowed = false;
            const int begin = c * kSweepGrain, end = std::min(count, begin + kSweepGrain);
            const std::size_t most = static_cast<std::size_t>(kKeptPerBox) * (end - begin);
            std::size_t nextOther = firstOtherAfter(begin);
            for (int k = begin; k < end && !chunk.overflowed; ++k) {
                while (nextOther < otherAt_.size() && otherAt_[nextOther] <= k) ++nextOther;
                chunk.visited += sweepFrom(cap, k, nextOther, [&](int i, int j) {
                    if (chunk.found.size() >= most) chunk.overflowed = true;
                    if (!chunk.overflowed) chunk.found.emplace_back(i, j);
                });
            }
        }
    };
    if (pool && count >= kSharedSweepBoxes)
        pool->parallelFor(chunkCount, 1, sweepChunks);
    else
        sweepChunks(0, chunkCount, 0);
    for (int c = 0; c < chunkCount; ++c) {
        Chunk& chunk = chunks_[c];
        if (!chunk.overflowed) {
            for (const auto& [i, j] : chunk.found) keep(i, j);
            candidatesVisited_ += chunk.visited;
            continue;
        }
        const int begin = c * kSweepGrain, end = std::min(count, begin + kSweepGrain);
        std::size_t nextOther = firstOtherAfter(begin);
        for (int k = begin; k < end; ++k) {
            while (nextOther < otherAt_.size() && otherAt_[nextOther] <= k) ++nextOther;
            candidatesVisited_ += sweepFrom(cap, k, nextOther, keep);
        }
    }
    sortPairs(pairs, count);
}

template <class Emit>
long long BroadPhase::sweepFrom(const PairCap& cap, int k, std::size_t nextOther,
                                Emit&& emit) const {
    // The boxes that overlap box i along the axis and start no earlier than it are those that
    // follow it in the order up to the first one starting beyond its upper bound; the other
    // axis decides. A kApart box looks only at the others (otherAt_).
    const int count = static_cast<int>(order_.size());
    const Sorted* sorted = sortedBoxes_.data();
    const int i = sorted[k].box;
    const double upper = upper_[k];
    const double crossLower = sorted[k].crossLower, crossUpper = sorted[k].crossUpper;
    const auto overlaps = [&](const Sorted& o) {
        return !(o.crossLower > crossUpper || crossLower > o.crossUpper);
    };
    if (cap.limited != nullptr && (*cap.limited)[i] == PairCap::kApart) {
        std::size_t m = nextOther;
        for (; m < otherAt_.size(); ++m) {
            const Sorted& o = sorted[otherAt_[m]];
            if (o.lower > upper) break;
            if (overlaps(o)) emit(i, o.box);
        }
        return static_cast<long long>(m - nextOther);
    }
    int l = k + 1;
    for (; l < count; ++l) {
        const Sorted& o = sorted[l];
        if (o.lower > upper) break;
        if (overlaps(o)) emit(i, o.box);
    }
    return l - (k + 1);
}

void BroadPhase::reserve(std::size_t boxes, std::size_t pairs) {
    order_.reserve(boxes);
    sortedBoxes_.reserve(boxes);
    upper_.reserve(boxes);
    pairCount_.reserve(boxes);
    nearCount_.reserve(boxes);
    otherAt_.reserve(boxes);
    firstOf_.reserve(boxes + 1);
    sorted_.reserve(pairs);
}

void BroadPhase::sortPairs(std::vector<std::pair<int, int>>& pairs, int count) {
    // By (i, j): a counting sort by i, then each box's few partners by j (a comparison sort
    // of the whole list was a fifth of the broad phase's time in a dense pile).
    firstOf_.assign(count + 1, 0);
    for (const auto& pair : pairs) ++firstOf_[pair.first + 1];
    std::partial_sum(firstOf_.begin(), firstOf_.end(), firstOf_.begin());
    sorted_.resize(pairs.size());
    for (const auto& pair : pairs) sorted_[firstOf_[pair.first]++] = pair;
    // firstOf_[i] is now where box i's pairs end, and firstOf_[i - 1] where they start.
    int start = 0;
    for (int i = 0; i < count; ++i) {
        const int end = firstOf_[i];
        if (end - start > 32) {  // a large body among many small ones
            std::sort(sorted_.begin() + start, sorted_.begin() + end);
            start = end;
            continue;
        }
        for (int k = start + 1; k < end; ++k) {
            const auto pair = sorted_[k];
            int slot = k;
            while (slot > start && sorted_[slot - 1].second > pair.second) {
                sorted_[slot] = sorted_[slot - 1];
                --slot;
            }
            sorted_[slot] = pair;
        }
        start = end;
    }
    pairs.swap(sorted_);
}

}  // namespace phasebox
