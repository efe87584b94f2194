#pragma once
// ContactSolver::forChunks and forColour, and a contact's tangent, for the solver's source files
// (private to physics/contacts).

#include "physics/contacts/ContactSolver.h"
#include "physics/core/WorkerPool.h"

namespace phasebox {

// A contact's tangent: its normal turned a quarter clockwise (friction's direction, t = (n_y,
// −n_x)).
inline Vec2 tangentOf(const Vec2& n) {
    return {n.y(), -n.x()};
}

template <class F>
void ContactSolver::forChunks(std::size_t count, std::size_t grain, const F& fn) {
    if (count == 0) return;
    if (!pool_ || count <= grain) {
        fn(std::size_t{0}, count);
        return;
    }
    pool_->parallelFor(kBlocks, 1, [&fn, count](int block, int, int) {
        fn(blockStart(count, block), blockStart(count, block + 1));
    });
}

template <class F>
void ContactSolver::forColour(int colour, const F& fn) {
    const auto first = static_cast<std::size_t>(colourWide_[colour]);
    const auto end = static_cast<std::size_t>(colourWide_[colour + 1]);
    if (first == end) return;
    if (!pool_ || !wideColour(colour)) {
        fn(first, end);
        return;
    }
    const int* starts = blockWide_.data() + colour * (kBlocks + 1);
    pool_->parallelFor(kBlocks, 1, [&fn, starts](int block, int, int) {
        if (starts[block] < starts[block + 1])
            fn(static_cast<std::size_t>(starts[block]),
               static_cast<std::size_t>(starts[block + 1]));
    });
}

template <class F>
void ContactSolver::forColours(const F& fn) {
    // The colours are one after the other in wide_: a pass whose rows are independent of one
    // another takes them at once, or block by block with each block's part of every colour, so
    // that a worker keeps its blocks' bodies and the workers meet once, not once a colour.
    // Shared as the sweeps are: only where some colour is (a helper woken for these passes
    // alone costs a middling scene more than it takes off).
    const auto total = static_cast<std::size_t>(colourWide_[kColours]);
    if (total == 0) return;
    bool wide = false;
    for (int colour = 0; colour < colours_ && !wide; ++colour) wide = wideColour(colour);
    if (!pool_ || !wide) {
        fn(std::size_t{0}, total);
        return;
    }
    const int* starts = blockWide_.data();
    const int colours = colours_;
    pool_->parallelFor(kBlocks, 1, [&fn, starts, colours](int block, int, int) {
        for (int colour = 0; colour < colours; ++colour) {
            const int* at = starts + colour * (kBlocks + 1);
            if (at[block] < at[block + 1])
                fn(static_cast<std::size_t>(at[block]), static_cast<std::size_t>(at[block + 1]));
        }
    });
}

}  // namespace phasebox
