#pragma once
// The recording of a run behind the timeline (CONTRACT §8): a light frame after every step (the
// state, clock and ledger: what drawing and the readouts need) and, every so many steps, a
// keyframe of the world's whole state (WorldSnapshot), and one wherever the settings changed. Any
// recorded frame can be shown at once; stepping on from one restores the keyframe at or before it
// and re-simulates the steps between, which the world's determinism makes the very steps the run
// took.
//
// Memory stays within a budget: when the frames outgrow it, every other frame of the older half
// is dropped (never a keyframe's own frame, never the first), so recent history stays complete
// and old history grows coarser but keeps its whole span; keyframes thin the same way within a
// quarter of the budget. A dropped frame is still reachable exactly by re-simulation from the
// keyframe before it (restore()).

#include "physics/world/WorldSnapshot.h"

#include <cstddef>
#include <deque>
#include <vector>

namespace phasebox {

class World;

class RunRecording {
public:
    explicit RunRecording(std::size_t budgetBytes = kDefaultBudgetBytes);

    // Appends the world's current frame (call after each step, and once before the first). A
    // clock that did not move on (a reset, an edit that rebuilt the world, objects added or
    // removed) starts the recording over from this frame.
    void record(const World& world);
    void clear();

    void setBudgetBytes(std::size_t bytes);
    std::size_t budgetBytes() const { return budget_; }
    std::size_t bytesUsed() const { return frameBytes_ + keyframeBytes_; }
    // Steps between keyframes (at least 1).
    void setKeyframeInterval(long long steps);
    long long keyframeInterval() const { return keyframeEvery_; }

    int frameCount() const { return static_cast<int>(frames_.size()); }
    int keyframeCount() const { return static_cast<int>(keyframes_.size()); }
    const FrameState& frame(int index) const { return frames_[static_cast<std::size_t>(index)]; }
    // The last frame whose time is at or before t (0 when t is before the first), -1 when empty.
    int frameAtOrBefore(double t) const;

    // Draws the recorded frame in the world (WorldSnapshot::show). False when out of range or of
    // other objects.
    bool show(World& world, int index) const;
    // Puts the world into the whole state it had at step stepCount (a recorded frame or one
    // thinned out, within the recording): the keyframe before it, restored, and the steps
    // between taken again. False when no keyframe precedes it or the re-simulation diverged.
    bool restore(World& world, long long stepCount) const;

    // The settings the run had at step stepCount: those of the keyframe at or before it (a
    // recording keeps one wherever they changed); nullptr when no keyframe precedes it.
    const SimulationSettings* settingsAt(long long stepCount) const;

    // Drops every frame and keyframe after the given step and hands them back, so that an
    // undoable command can put them back with append().
    struct Tail {
        std::vector<FrameState> frames;
        std::vector<std::pair<long long, WorldSnapshot>> keyframes;
    };
    Tail truncateAfter(long long stepCount);
    void append(Tail&& tail);

    static constexpr std::size_t kDefaultBudgetBytes = std::size_t{400} << 20;
    static constexpr long long kDefaultKeyframeInterval = 120;

private:
    void thinFrames();
    void thinKeyframes();

    std::size_t budget_;
    long long keyframeEvery_ = kDefaultKeyframeInterval;
    std::deque<FrameState> frames_;
    // (step, whole state), in step order; the first is at the first frame.
    std::deque<std::pair<long long, WorldSnapshot>> keyframes_;
    std::size_t frameBytes_ = 0, keyframeBytes_ = 0;
    long long lastKeyframeStep_ = -1;
};

}  // namespace phasebox
