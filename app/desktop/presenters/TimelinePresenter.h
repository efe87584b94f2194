#pragma once
// The timeline under the canvas: it owns the run's recording (RunRecording), hands it to the
// controller, and moves the shown moment when the user drags the slider, steps a frame (, and .)
// or jumps to the start (Home). The controller puts the world in that moment's state, so the
// canvas, plots, readouts and instruments follow by their own signals. The controller is the
// window's member and goes before its child presenters, so this one never detaches from it.

#include "app/desktop/presenters/Presenter.h"
#include "app/sim/RunRecording.h"
#include "ui/panels/TimelineBar.h"

namespace phasebox {

class SimulationController;

class TimelinePresenter : public Presenter {
    Q_OBJECT

public:
    TimelinePresenter(ui::TimelineBar& bar, SimulationController& controller,
                      QObject* parent = nullptr);

    void refresh() override;
    // "One Frame Back" (,), "One Frame Forward" (.), "Jump to Start" (Home).
    void createActions(QWidget& window);
    // Moves the shown frame by delta (from the live end when none is shown), within the recording.
    void stepFrames(int delta);
    const RunRecording& recording() const { return recording_; }

private:
    ui::TimelineBar& bar_;
    SimulationController& controller_;
    RunRecording recording_;
};

}  // namespace phasebox
