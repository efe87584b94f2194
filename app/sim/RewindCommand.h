#pragma once
// Play from an earlier moment as one undoable step: the run goes on from a shown frame and the
// frames, plot samples and live end after it are kept here, so that Undo puts that branch back
// (and keeps the newer one for Redo).

#include "app/sim/Recorder.h"
#include "app/sim/RunRecording.h"
#include "app/sim/SimulationController.h"
#include "physics/world/WorldSnapshot.h"

#include <QUndoCommand>

#include <memory>

namespace phasebox {

struct SimulationController::Branch {
    long long generation = 0;  // the run it belongs to (SimulationController::runGeneration_)
    long long step = 0;        // the step it branches off after
    double time = 0.0;
    RunRecording::Tail frames;
    Recorder::Tail samples;
    std::shared_ptr<WorldSnapshot> end;  // the world's whole state at the branch's end
};

class RewindCommand final : public QUndoCommand {
public:
    RewindCommand(SimulationController& controller, SimulationController::Branch dropped);

    void undo() override { controller_.swapBranch(other_); }
    // The first redo is the push itself: the run has already gone back.
    void redo() override {
        if (!first_) controller_.swapBranch(other_);
        first_ = false;
    }

private:
    SimulationController& controller_;
    SimulationController::Branch other_;
    bool first_ = true;
};

}  // namespace phasebox
