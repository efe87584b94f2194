#pragma once
// Where a step's time goes, stage by stage (CONTRACT.md §7): World::step() is a script of
// named stages and times each one into this profile, in the spirit of b2Profile. The app's
// effects panel and `phasebox-cli run --json` (`stages`) show it; the per-effect costs are a
// finer view of the first stage.

#include <array>
#include <chrono>
#include <string_view>

namespace phasebox {

enum class StepStage : unsigned char {
    Integrate,
    Collide,
    SolveContacts,
    SolveJoints,
    Ledger,
    Guard
};

using ProfileClock = std::chrono::steady_clock;

inline double secondsSince(ProfileClock::time_point start) {
    return std::chrono::duration<double>(ProfileClock::now() - start).count();
}

struct StepProfile {
    static constexpr int kStageCount = 6;
    // Names in the order the stages run; these are the `stages[].name` of --json.
    static constexpr std::array<std::string_view, kStageCount> kStageNames = {
        "integrate", "collide", "solve contacts", "solve joints", "ledger", "guard"};

    std::array<double, kStageCount> seconds{};  // summed since the last reset
    long long steps = 0;                        // steps timed since the last reset

    double& operator[](StepStage stage) { return seconds[static_cast<int>(stage)]; }
    double operator[](StepStage stage) const { return seconds[static_cast<int>(stage)]; }
    double total() const {
        double sum = 0.0;
        for (double s : seconds) sum += s;
        return sum;
    }
    // Mean milliseconds per step of stage i (0 before the first step).
    double msPerStep(int i) const { return steps > 0 ? 1e3 * seconds[i] / double(steps) : 0.0; }
    // Whether stage i ran at all since the reset (a scene with nothing to touch never collides).
    bool ran(int i) const { return seconds[i] > 0.0; }
    void reset() { *this = StepProfile{}; }
};

// Times consecutive stages into a profile: each call to start() ends the stage before it.
class StageTimer {
public:
    explicit StageTimer(StepProfile& profile) : profile_(profile) {}
    ~StageTimer() { stop(); }
    StageTimer(const StageTimer&) = delete;
    StageTimer& operator=(const StageTimer&) = delete;
    void start(StepStage stage) {
        const auto now = ProfileClock::now();
        if (running_) profile_[stage_] += std::chrono::duration<double>(now - since_).count();
        stage_ = stage;
        since_ = now;
        running_ = true;
    }
    void stop() {
        if (running_) profile_[stage_] += secondsSince(since_);
        running_ = false;
    }

private:
    StepProfile& profile_;
    StepStage stage_ = StepStage::Integrate;
    ProfileClock::time_point since_;
    bool running_ = false;
};

}  // namespace phasebox
