#include "app/sim/CompareRun.h"

#include "app/document/Document.h"
#include "app/sim/RunRecording.h"
#include "app/sim/SimulationController.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"

#include <QCoreApplication>
#include <QUndoStack>

#include <algorithm>
#include <iterator>

namespace phasebox {

CompareRun::CompareRun() = default;
CompareRun::~CompareRun() = default;

bool CompareRun::start(SimulationController& controller, Document& document,
                       const SimulationDesc& settings, QString* why) {
    const auto refuse = [why](const QString& text) {
        if (why) *why = text;
        return false;
    };
    const RunRecording* recording = controller.runRecording();
    const int from = controller.shownFrame();
    if (!recording || from < 0 || from >= recording->frameCount() - 1)
        return refuse(QCoreApplication::translate(
            "CompareRun",
            "Drag the timeline to an earlier moment first: the run is compared "
            "from there."));
    const SimulationSettings* recorded = recording->settingsAt(recording->frame(from).stepCount);
    if (!recorded)
        return refuse(QCoreApplication::translate(
            "CompareRun", "The recording holds no state before this moment."));

    // The ghost: the recorded frames from here on, in a world of the same objects.
    std::vector<FrameState> frames;
    frames.reserve(static_cast<std::size_t>(recording->frameCount() - from));
    for (int i = from; i < recording->frameCount(); ++i) frames.push_back(recording->frame(i));
    std::unique_ptr<World> ghost;
    try {
        ghost = buildWorld(document.setup()).world;
    } catch (const std::exception&) {
        return refuse(
            QCoreApplication::translate("CompareRun", "The scene cannot be built for the ghost."));
    }
    ghost->commit();
    if (!WorldSnapshot::show(*ghost, frames.front()))
        return refuse(QCoreApplication::translate(
            "CompareRun", "The recorded frames are of other objects than the scene's."));

    QUndoStack* stack = document.undoStack();
    stack->beginMacro(QCoreApplication::translate("CompareRun", "Compare from here"));
    controller.resumeFromShownFrame();
    QString error;
    const bool switched = document.applySimulationSettings(settings, &error);
    stack->endMacro();
    if (!switched) {
        stack->undo();  // back to the recorded run, whole
        return refuse(error);
    }
    end();
    frames_ = std::move(frames);
    ghost_ = std::move(ghost);
    recorded_ = *recorded;
    shown_ = 0;
    undoIndex_ = stack->index();
    return true;
}

void CompareRun::end() {
    frames_.clear();
    ghost_.reset();
    shown_ = -1;
    undoIndex_ = -1;
    series_.clear();
    series_.setPhaseTarget({}, QStringLiteral("x"));
    seriesValid_ = false;
}

int CompareRun::frameAt(double t) const {
    if (frames_.empty() || t < frames_.front().time - kTimeSlack) return -1;
    const auto it =
        std::upper_bound(frames_.begin(), frames_.end(), t + kTimeSlack,
                         [](double time, const FrameState& f) { return time < f.time; });
    return static_cast<int>(std::distance(frames_.begin(), it)) - 1;
}

const World* CompareRun::ghostAt(double t) {
    const int index = frameAt(t);
    if (!ghost_ || index < 0) return nullptr;
    if (index != shown_) {
        if (!WorldSnapshot::show(*ghost_, frames_[static_cast<std::size_t>(index)])) return nullptr;
        shown_ = index;
    }
    return ghost_.get();
}

const Recorder& CompareRun::series(const QString& phaseObject, const QString& phaseCoordinate) {
    if (seriesValid_ && series_.phaseObject() == phaseObject &&
        series_.phaseCoordinate() == phaseCoordinate)
        return series_;
    series_.clear();
    series_.setPhaseTarget(phaseObject, phaseCoordinate);
    series_.setMaxSamples(frames_.size() + 1);  // every frame: the recording already thinned them
    if (ghost_) {
        for (const FrameState& frame : frames_)
            if (WorldSnapshot::show(*ghost_, frame)) series_.record(*ghost_);
        // The canvas's frame again.
        if (shown_ >= 0) WorldSnapshot::show(*ghost_, frames_[static_cast<std::size_t>(shown_)]);
    }
    seriesValid_ = true;
    return series_;
}

}  // namespace phasebox
