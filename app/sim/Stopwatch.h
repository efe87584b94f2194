#pragma once
// A stopwatch on simulated time, as a student would hold one beside the experiment: start,
// stop, lap, reset. It reads the world's clock, so it runs in slow motion with the simulation
// and stands still while it is paused; a lap is the split time since the start.

#include <vector>

namespace phasebox {

class Stopwatch {
public:
    bool isRunning() const { return running_; }
    // The time shown at simulated time now.
    double elapsed(double now) const { return running_ ? held_ + (now - startedAt_) : held_; }
    void start(double now) {
        if (running_) return;
        running_ = true;
        startedAt_ = now;
    }
    void stop(double now) {
        if (!running_) return;
        held_ = elapsed(now);
        running_ = false;
    }
    // Records the split time (only while running).
    void lap(double now) {
        if (running_) laps_.push_back(elapsed(now));
    }
    void reset() {
        running_ = false;
        held_ = 0.0;
        startedAt_ = 0.0;
        laps_.clear();
    }
    const std::vector<double>& laps() const { return laps_; }

private:
    bool running_ = false;
    double held_ = 0.0;       // elapsed time up to the last stop
    double startedAt_ = 0.0;  // the world's time at the last start
    std::vector<double> laps_;
};

}  // namespace phasebox
