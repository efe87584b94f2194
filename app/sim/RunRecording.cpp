#include "app/sim/RunRecording.h"

#include "physics/world/World.h"

#include <algorithm>
#include <cstring>
#include <iterator>

namespace phasebox {

RunRecording::RunRecording(std::size_t budgetBytes) : budget_(budgetBytes) {}

void RunRecording::clear() {
    frames_.clear();
    keyframes_.clear();
    frameBytes_ = keyframeBytes_ = 0;
    lastKeyframeStep_ = -1;
}

void RunRecording::setBudgetBytes(std::size_t bytes) {
    budget_ = bytes;
    thinKeyframes();
    thinFrames();
}

void RunRecording::setKeyframeInterval(long long steps) {
    keyframeEvery_ = std::max(1LL, steps);
}

void RunRecording::record(const World& world) {
    const long long step = world.stepCount();
    // Another layout of the state is another world (an edit), unless islands fell asleep or
    // woke: then the frames hold which bodies slept (FrameState::sleepers).
    const auto otherLayout = [&] {
        const FrameState& last = frames_.back();
        return world.positions().size() != last.q.size() && !world.sleepers() && !last.sleepers;
    };
    if (!frames_.empty() && (step <= frames_.back().stepCount || otherLayout())) clear();
    frames_.push_back(FrameState::of(world));
    frameBytes_ += frames_.back().bytes();
    // A keyframe where the settings changed too (a method switched live): re-simulation from a
    // keyframe runs with that keyframe's settings.
    const bool switched = !keyframes_.empty() && !keyframes_.back().second.hasSettingsOf(world);
    if (lastKeyframeStep_ < 0 || step - lastKeyframeStep_ >= keyframeEvery_ || switched) {
        keyframes_.emplace_back(step, WorldSnapshot::take(world));
        keyframeBytes_ += keyframes_.back().second.bytes();
        lastKeyframeStep_ = step;
        thinKeyframes();
    }
    thinFrames();
}

void RunRecording::thinFrames() {
    // Frames may use what the keyframes leave; at least two frames always stay.
    while (frames_.size() > 2 && keyframeBytes_ + frameBytes_ > budget_) {
        const std::size_t before = frames_.size();
        const std::size_t olderHalf = frames_.size() / 2;
        std::deque<FrameState> kept;
        std::size_t k = 0;  // keyframes_ index of the next keyframe at or after a frame
        for (std::size_t i = 0; i < frames_.size(); ++i) {
            const long long step = frames_[i].stepCount;
            while (k < keyframes_.size() && keyframes_[k].first < step) ++k;
            const bool atKeyframe = k < keyframes_.size() && keyframes_[k].first == step;
            const bool drop = i > 0 && i < olderHalf && i % 2 == 1 && !atKeyframe;
            if (drop)
                frameBytes_ -= frames_[i].bytes();
            else
                kept.push_back(std::move(frames_[i]));
        }
        frames_ = std::move(kept);
        if (frames_.size() == before) break;  // nothing left to thin: keyframes fill the budget
    }
}

void RunRecording::thinKeyframes() {
    while (keyframes_.size() > 2 && keyframeBytes_ > budget_ / 4) {
        const std::size_t before = keyframes_.size();
        const std::size_t olderHalf = (keyframes_.size() + 1) / 2;
        std::deque<std::pair<long long, WorldSnapshot>> kept;
        for (std::size_t i = 0; i < keyframes_.size(); ++i) {
            if (i > 0 && i < olderHalf && i % 2 == 1)
                keyframeBytes_ -= keyframes_[i].second.bytes();
            else
                kept.push_back(std::move(keyframes_[i]));
        }
        keyframes_ = std::move(kept);
        if (keyframes_.size() == before) break;  // the first and the last stay
    }
}

int RunRecording::frameAtOrBefore(double t) const {
    if (frames_.empty()) return -1;
    const auto it =
        std::upper_bound(frames_.begin(), frames_.end(), t,
                         [](double time, const FrameState& f) { return time < f.time; });
    return std::max(0, static_cast<int>(std::distance(frames_.begin(), it)) - 1);
}

bool RunRecording::show(World& world, int index) const {
    if (index < 0 || index >= frameCount()) return false;
    return WorldSnapshot::show(world, frames_[static_cast<std::size_t>(index)]);
}

bool RunRecording::restore(World& world, long long stepCount) const {
    const auto after =
        std::upper_bound(keyframes_.begin(), keyframes_.end(), stepCount,
                         [](long long step, const std::pair<long long, WorldSnapshot>& k) {
                             return step < k.first;
                         });
    if (after == keyframes_.begin() || frames_.empty() || stepCount > frames_.back().stepCount)
        return false;
    if (!std::prev(after)->second.restoreInto(world)) return false;
    while (world.stepCount() < stepCount)
        if (!world.step()) return false;
    if (world.stepCount() != stepCount) return false;
    // Where the step was kept, the re-simulation must have retraced it bit for bit; it does not
    // when the run was steered by hand (a drag) between the keyframe and the step.
    const int index = frameAtOrBefore(world.time());
    const FrameState& kept = frames_[static_cast<std::size_t>(index)];
    if (kept.stepCount != stepCount) return true;
    const auto same = [](const Vec& a, const Vec& b) {
        return a.size() == b.size() &&
               std::memcmp(a.data(), b.data(),
                           static_cast<std::size_t>(a.size()) * sizeof(double)) == 0;
    };
    return same(kept.q, world.positions()) && same(kept.u, world.velocities());
}

const SimulationSettings* RunRecording::settingsAt(long long stepCount) const {
    const auto after =
        std::upper_bound(keyframes_.begin(), keyframes_.end(), stepCount,
                         [](long long step, const std::pair<long long, WorldSnapshot>& k) {
                             return step < k.first;
                         });
    return after == keyframes_.begin() ? nullptr : &std::prev(after)->second.settings();
}

RunRecording::Tail RunRecording::truncateAfter(long long stepCount) {
    Tail tail;
    while (!frames_.empty() && frames_.back().stepCount > stepCount) {
        frameBytes_ -= frames_.back().bytes();
        tail.frames.insert(tail.frames.begin(), std::move(frames_.back()));
        frames_.pop_back();
    }
    while (!keyframes_.empty() && keyframes_.back().first > stepCount) {
        keyframeBytes_ -= keyframes_.back().second.bytes();
        tail.keyframes.insert(tail.keyframes.begin(), std::move(keyframes_.back()));
        keyframes_.pop_back();
    }
    lastKeyframeStep_ = keyframes_.empty() ? -1 : keyframes_.back().first;
    return tail;
}

void RunRecording::append(Tail&& tail) {
    for (FrameState& f : tail.frames) {
        frameBytes_ += f.bytes();
        frames_.push_back(std::move(f));
    }
    for (auto& k : tail.keyframes) {
        keyframeBytes_ += k.second.bytes();
        keyframes_.push_back(std::move(k));
    }
    lastKeyframeStep_ = keyframes_.empty() ? -1 : keyframes_.back().first;
    tail = {};
    thinKeyframes();
    thinFrames();
}

}  // namespace phasebox
