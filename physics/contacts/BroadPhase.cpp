#include "physics/contacts/BroadPhase.h"

#include "physics/core/WorkerPool.h"

#include <algorithm>
#include <cmath>
#include <limits>
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
// Fewer boxes are swept on the calling thread: their sweep costs about what handing it out does
// (waking a helper that slept through the solve; the 40-row pyramid's 820 boxes were no faster
// on two workers).
constexpr int kSharedSweepBoxes = 2048;

// Bands of the cross axis (buildBands()): used from this many boxes and bands on, at most this
// many bands, and a box across more of them than kMaxBandsPerBox sweeps the whole order.
constexpr int kMinBandedBoxes = 256;
constexpr int kMinBands = 4;
constexpr int kMaxBands = 4096;
constexpr int kBandSample = 64;  // boxes whose median extent sets the bands' height

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

void BroadPhase::arrange(const std::vector<Aabb>& boxes) {
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
    buildBands(count);
}

void BroadPhase::findPairs(const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>& pairs,
                           const PairCap& cap, WorkerPool* pool) {
    pairs.clear();
    candidatesVisited_ = 0;
    capBound_ = false;
    const int count = static_cast<int>(boxes.size());

    arrange(boxes);

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
    // Whether both caps of box i are full, and whether then every further pair of a limited box
    // i is turned away: no box is free and none is less than half its size.
    const auto full = [&](int i) {
        return pairCount_[i] >= cap.perBox && nearCount_[i] >= cap.nearPerBox;
    };
    int freeBoxes = 0;
    double smallest = std::numeric_limits<double>::infinity();
    if (capped)
        for (int i = 0; i < count; ++i) {
            freeBoxes += (*cap.limited)[i] == PairCap::kFree;
            smallest = std::min(smallest, (*cap.size)[i]);
        }
    const auto closed = [&](int i) {
        return freeBoxes == 0 && smallest >= 0.5 * (*cap.size)[i] && full(i);
    };
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
        const bool countsForI = sizeJ >= 0.5 * sizeI;
        const bool countsForJ = sizeI >= 0.5 * sizeJ;
        // A side whose caps are both full turns the pair away whichever cap it falls under.
        if ((countsForI && full(i)) || (countsForJ && full(j))) {
            capBound_ = true;
            return false;
        }
        const Vec2 twiceOffset = (o.lower + o.upper) - (box.lower + box.upper);
        const double twiceReach = 2.0 * (sizeI + sizeJ);
        const bool overlapping = twiceOffset.squaredNorm() < twiceReach * twiceReach;
        std::vector<int>& taken = overlapping ? pairCount_ : nearCount_;
        const int limit = overlapping ? cap.perBox : cap.nearPerBox;
        if ((countsForI && taken[i] >= limit) || (countsForJ && taken[j] >= limit)) {
            capBound_ = true;
            return false;
        }
        taken[i] += countsForI;
        taken[j] += countsForJ;
        return true;
    };

    // Takes the pair (i, j) if the caps admit it; false when box i can take no further pair.
    const auto keep = [&](int i, int j) {
        const unsigned char kindI = capped ? (*cap.limited)[i] : PairCap::kFree;
        if (kindI == PairCap::kFree) {
            pairs.emplace_back(std::min(i, j), std::max(i, j));
            return true;
        }
        if (admit(i, j, boxes[i], boxes[j])) pairs.emplace_back(std::min(i, j), std::max(i, j));
        if (!closed(i)) return true;
        capBound_ = true;
        return false;
    };
    const auto offerAll = [](int, int) { return false; };
    const auto firstOtherAfter = [&](int k) {
        return static_cast<std::size_t>(std::upper_bound(otherAt_.begin(), otherAt_.end(), k) -
                                        otherAt_.begin());
    };
    // The sweep in chunks of the order, each into its own buffer (shared among the pool's
    // workers); the caps then take the overlaps in the order of the sweep.
    const int chunkCount = WorkerPool::chunkCount(count, kSweepGrain);
    if (chunks_.size() < static_cast<std::size_t>(chunkCount)) chunks_.resize(chunkCount);
    const int workers = pool && count >= kSharedSweepBoxes ? pool->workers() : 1;
    if (scratch_.size() < static_cast<std::size_t>(workers)) scratch_.resize(workers);
    for (Scratch& scratch : scratch_) {
        scratch.found.reserve(boxes.size());
        scratch.merged.reserve(boxes.size());
    }
    const auto sweepChunks = [&](int beginChunk, int endChunk, int worker) {
        Scratch& scratch = scratch_[worker];
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
                chunk.visited += sweepBox(
                    cap, k, nextOther, scratch,
                    [&](int i, int j) {
                        if (chunk.found.size() >= most) chunk.overflowed = true;
                        if (!chunk.overflowed) chunk.found.emplace_back(i, j);
                        return !chunk.overflowed;
                    },
                    offerAll);
            }
        }
    };
    if (pool && count >= kSharedSweepBoxes)
        pool->parallelFor(chunkCount, 1, sweepChunks);
    else
        sweepChunks(0, chunkCount, 0);
    // Whether keep(i, box at position l) would turn the pair away and change no count: box i
    // is capped, and so is the other, and the cap the pair falls under is full for i (or both
    // are kApart). In a pile at one point nearly every candidate is such, thousands per box:
    // they are passed over reading capAt_ alone. Never while box i is closed, so that keep
    // still ends its sweep where it did.
    const int crossAxis = 1 - axis_;
    const auto turnedAway = [&](int i, int l) {
        const unsigned char kindI = (*cap.limited)[i];
        const CapView& o = capAt_[l];
        if (kindI == PairCap::kFree || o.kind == PairCap::kFree || closed(i)) return false;
        if (kindI == PairCap::kApart && o.kind == PairCap::kApart) return true;
        const double sizeI = (*cap.size)[i];
        if (!(o.size >= 0.5 * sizeI)) return false;  // not counted against i's caps
        // admit()'s test, term for term.
        const Aabb& box = boxes[i];
        const double along = o.twiceAxis - (box.lower[axis_] + box.upper[axis_]);
        const double across = o.twiceCross - (box.lower[crossAxis] + box.upper[crossAxis]);
        const double twiceReach = 2.0 * (sizeI + o.size);
        const bool overlapping = along * along + across * across < twiceReach * twiceReach;
        const bool away =
            overlapping ? pairCount_[i] >= cap.perBox : nearCount_[i] >= cap.nearPerBox;
        capBound_ = capBound_ || away;
        return away;
    };
    capAt_.clear();
    for (int c = 0; c < chunkCount; ++c) {
        Chunk& chunk = chunks_[c];
        if (!chunk.overflowed) {
            for (const auto& [i, j] : chunk.found) keep(i, j);
            candidatesVisited_ += chunk.visited;
            continue;
        }
        if (capAt_.empty() && capped) {
            capAt_.resize(boxes.size());
            for (int l = 0; l < count; ++l) {
                const int b = order_[l];
                const Aabb& box = boxes[b];
                capAt_[l] = {box.lower[axis_] + box.upper[axis_],
                             box.lower[crossAxis] + box.upper[crossAxis], (*cap.size)[b],
                             (*cap.limited)[b]};
            }
        }
        const int begin = c * kSweepGrain, end = std::min(count, begin + kSweepGrain);
        std::size_t nextOther = firstOtherAfter(begin);
        for (int k = begin; k < end; ++k) {
            while (nextOther < otherAt_.size() && otherAt_[nextOther] <= k) ++nextOther;
            candidatesVisited_ += capped
                                      ? sweepBox(cap, k, nextOther, scratch_[0], keep, turnedAway)
                                      : sweepBox(cap, k, nextOther, scratch_[0], keep, offerAll);
        }
    }
    sortPairs(pairs, count);
}

template <class Emit, class Skip>
long long BroadPhase::sweepFrom(const PairCap& cap, int k, std::size_t nextOther, Emit&& emit,
                                Skip&& skip) const {
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
            if (overlaps(o) && !skip(i, otherAt_[m]) && !emit(i, o.box)) break;
        }
        return static_cast<long long>(m - nextOther);
    }
    int l = k + 1;
    for (; l < count; ++l) {
        const Sorted& o = sorted[l];
        if (o.lower > upper) break;
        if (overlaps(o) && !skip(i, l) && !emit(i, o.box)) break;
    }
    return l - (k + 1);
}

void BroadPhase::buildBands(int count) {
    // Bands of the cross axis twice as tall as the median box (a box lies in one or two of
    // them), at least kMinBands of them, or none: a pile at one point or a single row or column
    // has nothing to gain. Every bound must be finite (a diverged body's NaN would make the
    // sweep's order meaningless and its band undefined).
    bandCount_ = 0;
    if (count < kMinBandedBoxes) return;
    double low = std::numeric_limits<double>::infinity(), high = -low;
    // The median of a sample of the boxes spread over the order: the bands change only the
    // work, never the pairs.
    const int stride = std::max(1, count / kBandSample);
    extents_.clear();
    extents_.reserve(2 * kBandSample);  // count / stride < 2 · kBandSample
    for (int k = 0; k < count; ++k) {
        const Sorted& o = sortedBoxes_[k];
        if (!std::isfinite(o.lower) || !std::isfinite(upper_[k]) || !std::isfinite(o.crossLower) ||
            !std::isfinite(o.crossUpper))
            return;
        low = std::min(low, o.crossLower);
        high = std::max(high, o.crossUpper);
        if (k % stride == 0) extents_.push_back(o.crossUpper - o.crossLower);
    }
    const auto middle = extents_.begin() + extents_.size() / 2;
    std::nth_element(extents_.begin(), middle, extents_.end());
    const double height = std::max(2.0 * *middle, (high - low) / kMaxBands);
    if (!(height > 0.0) || !((high - low) / height >= kMinBands)) return;
    bandCount_ = std::min(kMaxBands, static_cast<int>((high - low) / height) + 1);
    bandLow_ = low;
    bandHeight_ = height;
    // The bands' boxes in the order's sequence (counted, then placed), and where each box
    // stands in each of its bands; a box across more than kMaxBandsPerBox bands is wide and
    // in none of them (it sweeps, and is found, as before).
    // Room for every box in kMaxBandsPerBox bands and for the most bands: nothing grows as
    // boxes cross bands or the bands' count changes.
    bandEntries_.reserve(static_cast<std::size_t>(kMaxBandsPerBox) * count);
    wide_.reserve(count);
    bandStart_.reserve(kMaxBands + 1);
    bandFill_.reserve(kMaxBands + 1);
    bandStart_.assign(bandCount_ + 1, 0);
    firstBand_.resize(count);
    lastBand_.resize(count);
    wide_.clear();
    for (int k = 0; k < count; ++k) {
        const int first = bandOf(sortedBoxes_[k].crossLower);
        const int last = bandOf(sortedBoxes_[k].crossUpper);
        const bool wide = last - first >= kMaxBandsPerBox;
        firstBand_[k] = wide ? -1 : first;
        lastBand_[k] = last;
        if (wide) {
            wide_.push_back(k);
            continue;
        }
        for (int b = first; b <= last; ++b) ++bandStart_[b + 1];
    }
    std::partial_sum(bandStart_.begin(), bandStart_.end(), bandStart_.begin());
    bandFill_.assign(bandStart_.begin(), bandStart_.end() - 1);
    bandEntries_.resize(bandStart_.back());
    slots_.resize(static_cast<std::size_t>(kMaxBandsPerBox) * count);
    for (int k = 0; k < count; ++k) {
        const int first = firstBand_[k];
        if (first < 0) continue;
        const Sorted& o = sortedBoxes_[k];
        for (int b = first; b <= lastBand_[k]; ++b) {
            const int slot = bandFill_[b]++;
            bandEntries_[slot] = {o.lower, o.crossLower, o.crossUpper, k, first};
            slots_[static_cast<std::size_t>(kMaxBandsPerBox) * k + (b - first)] = slot;
        }
    }
}

int BroadPhase::bandOf(double cross) const {
    // Monotone in cross: two boxes that overlap on the cross axis share a band.
    const double at = (cross - bandLow_) / bandHeight_;
    if (!(at > 0.0)) return 0;
    if (at >= bandCount_) return bandCount_ - 1;
    return static_cast<int>(at);
}

template <class Emit, class Skip>
long long BroadPhase::sweepBox(const PairCap& cap, int k, std::size_t nextOther, Scratch& buffers,
                               Emit&& emit, Skip&& skip) const {
    // A box in the bands looks at the boxes after it in its bands and at the wide ones, and
    // emits the same overlaps in the same order as the sweep along the whole order would (by
    // their positions in it): each pair is taken in the first band the two boxes share.
    if (bandCount_ == 0 || firstBand_[k] < 0) return sweepFrom(cap, k, nextOther, emit, skip);
    const Sorted& box = sortedBoxes_[k];
    const double upper = upper_[k];
    const bool apart = cap.limited != nullptr && (*cap.limited)[box.box] == PairCap::kApart;
    const auto wanted = [&](int l, double crossLower, double crossUpper) {
        return !(crossLower > box.crossUpper || box.crossLower > crossUpper) &&
               !(apart && (*cap.limited)[sortedBoxes_[l].box] == PairCap::kApart);
    };
    // Each band's overlaps and the wide ones come in the order's sequence: runs, merged.
    std::vector<int>& scratch = buffers.found;
    std::vector<int>& merged = buffers.merged;
    scratch.clear();
    int runEnds[kMaxBandsPerBox + 1];
    int runs = 0;
    long long visited = 0;
    const int first = firstBand_[k];
    for (int b = first; b <= lastBand_[k]; ++b) {
        const int end = bandStart_[b + 1];
        const int start = slots_[static_cast<std::size_t>(kMaxBandsPerBox) * k + (b - first)] + 1;
        int slot = start;
        for (; slot < end; ++slot) {
            const BandEntry& o = bandEntries_[slot];
            if (o.lower > upper) break;
            if (std::max(first, o.firstBand) == b && wanted(o.position, o.crossLower, o.crossUpper))
                scratch.push_back(o.position);
        }
        visited += slot - start;
        runEnds[runs++] = static_cast<int>(scratch.size());
    }
    for (auto w = std::upper_bound(wide_.begin(), wide_.end(), k); w != wide_.end(); ++w) {
        const Sorted& o = sortedBoxes_[*w];
        if (o.lower > upper) break;
        ++visited;
        if (wanted(*w, o.crossLower, o.crossUpper)) scratch.push_back(*w);
    }
    runEnds[runs++] = static_cast<int>(scratch.size());
    for (int r = 1; r < runs; ++r) {
        if (runEnds[r] == runEnds[r - 1] || runEnds[r - 1] == 0) continue;
        merged.resize(runEnds[r]);
        std::merge(scratch.begin(), scratch.begin() + runEnds[r - 1],
                   scratch.begin() + runEnds[r - 1], scratch.begin() + runEnds[r], merged.begin());
        std::copy(merged.begin(), merged.end(), scratch.begin());
    }
    for (const int l : scratch)
        if (!skip(box.box, l) && !emit(box.box, sortedBoxes_[l].box)) break;
    return visited;
}

void BroadPhase::reserve(std::size_t boxes, std::size_t pairs) {
    order_.reserve(boxes);
    sortedBoxes_.reserve(boxes);
    upper_.reserve(boxes);
    pairCount_.reserve(boxes);
    nearCount_.reserve(boxes);
    otherAt_.reserve(boxes);
    capAt_.reserve(boxes);
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
