#pragma once
// Broad phase: which pairs of bounding boxes overlap. Sweep and prune along one axis, chosen
// per call as the axis along which the box centres spread more: a vertical column swept along
// x would have every box overlap every other along the sweep axis (quadratic), swept along y it
// costs what a row costs along x. The order of the boxes by their lower bound on that axis is
// kept from call to call and repaired by insertion sort, which is nearly linear when bodies
// move a little per step; a full sort takes over when the axis changes or the repair grows
// long (an exploding pile scrambles the order). In a broad heap the other axis is cut into bands
// (buildBands()) so that a box visits its neighbours, not the heap's whole width; the overlaps
// still come out in the sweep's order. Planes are not in it (they are infinite; the world tests
// them against every body).
//
// Rejected: a uniform grid (one cell size cannot serve a 100 m ground box and 5 cm disks) and
// a dynamic AABB tree (more code and state than the scenes here need). Known limit: boxes that
// spread along both axes in two thin lines (a cross, an L) still overlap along either axis in
// one of the lines.

#include "physics/contacts/Geometry.h"

#include <utility>
#include <vector>

namespace phasebox {

class WorkerPool;

// An optional bound on the pairs a box may take part in, for piles: a body in a pile needs a
// handful of neighbours, not the thousands whose boxes overlap when many bodies share one
// point. Only pairs of two limited boxes are capped. Pairs whose shapes overlap (centre
// distance below the sum of the sizes) count against perBox: a resting disk overlaps at most
// six equal ones, so it binds only in a pathological pile. Pairs that are only near (the
// speculative margin, a fast body's swept box) count against nearPerBox, so that a pile's
// overlaps cannot crowd out a contact about to be made. A partner counts against box i's caps
// when its size is at least half of i's, so a large disk among small ones keeps all of its
// (many, legitimate) small neighbours while each small one counts the large one.
// A box marked kApart is never paired with another kApart box (disks when particles do not
// collide); a kApart box counts as capped against the others.
struct PairCap {
    static constexpr unsigned char kFree = 0, kCapped = 1, kApart = 2;
    const std::vector<unsigned char>* limited = nullptr;  // per box; null: no cap at all
    // Per box: the radius of the shape it bounds, centred on the box (grown symmetrically).
    const std::vector<double>* size = nullptr;
    int perBox = 0;
    int nearPerBox = 0;
};

class BroadPhase {
public:
    // Room for boxes and pairs up front, so that a scene's first steps do not grow the buffers
    // one doubling at a time (ContactStage::bind).
    void reserve(std::size_t boxes, std::size_t pairs);
    // Fills pairs with every (i, j), i < j, whose boxes overlap, sorted by (i, j) so that the
    // result does not depend on the sweep's internal order. With a cap, a pair of two limited
    // boxes is left out when either box has already reached its cap in the sweep's order (which
    // is deterministic). Allocation-free once the buffers have grown to the scene's size.
    // With a pool the sweep is shared: each chunk of the order finds its boxes' overlaps into a
    // buffer of its own, and the caps are then applied to them in the order of the sweep, so the
    // pairs are those of one thread, bit for bit.
    void findPairs(const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>& pairs,
                   const PairCap& cap = {}, WorkerPool* pool = nullptr);

    // The sweep axis of the last call (0 = x, 1 = y) and how many candidate boxes it visited
    // along that axis (the sweep's work; equal to the pair count only when the other axis
    // rejects nothing).
    int axis() const { return axis_; }
    long long candidatesVisited() const { return candidatesVisited_; }
    // Whether the caps of the last call turned away a pair (or ended a box's sweep): then its
    // pairs depend on which candidates there were, and those of a subset of the boxes' extents
    // are not those pairs filtered. Pairs of two kApart boxes, left out whatever the
    // candidates, do not count.
    bool capBound() const { return capBound_; }

private:
    // The sweep axis, the order along it (sortOrder()), the bounds in its sequence and the
    // bands, for this call.
    void arrange(const std::vector<Aabb>& boxes);
    void sortOrder(const std::vector<Aabb>& boxes, bool fresh);
    void sortPairs(std::vector<std::pair<int, int>>& pairs, int count);
    // The overlaps of the box at position k of the order that follow it (the other axis
    // tested), as emit(i, j), until emit returns false (box i takes no further pair); returns
    // how many boxes it visited along the axis. nextOther: the first entry of otherAt_ after k.
    // skip(i, l): the candidate at position l is one emit would turn away with no effect (it
    // is not offered; emit still decides where the sweep of box i ends).
    template <class Emit, class Skip>
    long long sweepFrom(const PairCap& cap, int k, std::size_t nextOther, Emit&& emit,
                        Skip&& skip) const;

    // A chunk of the shared sweep: its overlaps in sweep order, unless there were more than
    // it keeps (a pile at one point, where nearly all are then capped away): the chunk is swept
    // again with the caps applied as it goes.
    struct Chunk {
        std::vector<std::pair<int, int>> found;
        long long visited = 0;
        bool overflowed = false;
    };
    std::vector<Chunk> chunks_;

    std::vector<int> order_;  // indices sorted by lower bound on axis_, kept between calls
    // The bounds the sweep reads, in the order's sequence (this call): one contiguous stream
    // instead of a jump through order_ into the boxes for every candidate visited.
    struct Sorted {
        double lower;                   // on axis_
        double crossLower, crossUpper;  // on the other axis
        int box;
    };
    std::vector<Sorted> sortedBoxes_;
    std::vector<double> upper_;  // per position of the order: the box's upper bound on axis_

    // Bands of the cross axis, so that a box in a broad heap (a pyramid) visits its neighbours
    // in its bands, not every box of the heap's width along the sweep axis: each band lists
    // the boxes that reach into it in the order's sequence. None when they do not pay.
    void buildBands(int count);
    int bandOf(double cross) const;
    struct Scratch;
    template <class Emit, class Skip>
    long long sweepBox(const PairCap& cap, int k, std::size_t nextOther, Scratch& buffers,
                       Emit&& emit, Skip&& skip) const;
    static constexpr int kMaxBandsPerBox = 4;
    struct BandEntry {
        double lower;
        double crossLower, crossUpper;
        int position;   // in the order
        int firstBand;  // the first band the box reaches into
    };
    int bandCount_ = 0;  // 0: no bands this call
    double bandLow_ = 0.0, bandHeight_ = 1.0;
    std::vector<int> bandStart_, bandFill_;  // per band + 1: where its entries start
    std::vector<BandEntry> bandEntries_;
    std::vector<int> firstBand_, lastBand_;  // per position (firstBand_ −1: wide)
    std::vector<int> slots_;                 // per position, kMaxBandsPerBox: its entry per band
    std::vector<int> wide_;                  // positions of the wide boxes
    // Per worker: one box's overlaps in the bands, put in the order's sequence (room for every
    // box, so that no call allocates once the count is reached).
    struct Scratch {
        std::vector<int> found, merged;
    };
    std::vector<Scratch> scratch_;
    std::vector<double> extents_;  // scratch: the boxes' cross extents
    std::vector<int> pairCount_;   // per box: overlapping capped partners taken in this call
    std::vector<int> nearCount_;   // per box: near capped partners taken in this call
    std::vector<int> otherAt_;     // positions in order_ of the boxes not kApart (this call)
    // Per position of the order, what the caps read of its box, side by side (filled where a
    // chunk is swept again with the caps: a pile at one point, where each box meets thousands).
    struct CapView {
        double twiceAxis, twiceCross;  // lower + upper on the sweep axis and the other one
        double size;
        unsigned char kind;
    };
    std::vector<CapView> capAt_;
    std::vector<int> firstOf_;                 // per box + 1: where its pairs start (sorting)
    std::vector<std::pair<int, int>> sorted_;  // the pairs by (i, j), before the swap
    int axis_ = 0;
    long long candidatesVisited_ = 0;
    bool capBound_ = false;
};

}  // namespace phasebox
