#pragma once
// Compare from here (CONTRACT §8): the run goes on from a recorded moment with other settings
// while the recorded run from that moment on stays beside it as a ghost. The ghost's frames are
// the recording's own (copied when the comparison starts, since the new run replaces them in the
// recording), shown in a world of its own built from the same scene: nothing is simulated twice.
//
// The two runs are matched by time, not by frame index, so a comparison with another dt pairs
// each of its moments with the last recorded frame at or before it. Past the recording's last
// frame the ghost stays at that frame (pastEnd() says so).

#include "app/sim/Recorder.h"
#include "physics/world/World.h"
#include "physics/world/WorldSnapshot.h"

#include <QString>

#include <memory>
#include <vector>

namespace phasebox {

class Document;
class RunRecording;
class SimulationController;
struct SceneDesc;
struct SimulationDesc;

class CompareRun {
public:
    CompareRun();
    ~CompareRun();

    // Starts a comparison from the timeline's shown frame: keeps the recorded frames from it on
    // as the ghost, puts the live world into the whole state the run had there
    // (SimulationController::resumeFromShownFrame) and switches it to `settings`, as one undo
    // step. False with *why (nothing changed) when no earlier frame is shown or the ghost
    // cannot be built. With sleeping on, the frame's islands asleep come back asleep, and the
    // switch of settings wakes them (CONTRACT §6).
    bool start(SimulationController& controller, Document& document, const SimulationDesc& settings,
               QString* why = nullptr);
    // Drops the ghost (the live run goes on).
    void end();
    bool isActive() const { return ghost_ != nullptr; }

    // The settings the recorded run had at the compare's start.
    const SimulationSettings& recordedSettings() const { return recorded_; }
    double startTime() const { return frames_.empty() ? 0.0 : frames_.front().time; }
    double endTime() const { return frames_.empty() ? 0.0 : frames_.back().time; }
    // The undo stack's index right after the start: undoing below it ends the comparison.
    int undoIndex() const { return undoIndex_; }
    const std::vector<FrameState>& frames() const { return frames_; }

    // The ghost's frame for time t: the last recorded frame at or before it (within rounding),
    // -1 before the start.
    int frameAt(double t) const;
    bool pastEnd(double t) const { return isActive() && t > endTime() + kTimeSlack; }
    // The ghost world showing the frame for time t; nullptr before the start or when inactive.
    const World* ghostAt(double t);

    // The recorded run's energy and the phase trace of one object's coordinate, from the ghost
    // frames, as the plots' Recorder would have recorded them.
    const Recorder& series(const QString& phaseObject, const QString& phaseCoordinate);

    // Clock readings this close count as the same moment (two runs with different dt sum
    // their steps with different rounding).
    static constexpr double kTimeSlack = 1e-9;

private:
    std::vector<FrameState> frames_;
    std::unique_ptr<World> ghost_;
    SimulationSettings recorded_;
    int shown_ = -1;
    int undoIndex_ = -1;
    Recorder series_;
    bool seriesValid_ = false;
};

}  // namespace phasebox
