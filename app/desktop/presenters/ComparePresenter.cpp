#include "app/desktop/presenters/ComparePresenter.h"

#include "app/desktop/CompareDialog.h"
#include "app/desktop/presenters/PlotsPresenter.h"
#include "app/document/Document.h"
#include "app/sim/Recorder.h"
#include "app/sim/RunRecording.h"
#include "app/sim/SimulationController.h"
#include "physics/contacts/ContactModel.h"
#include "ui/canvas/SceneView.h"
#include "ui/panels/ParametersPanel.h"
#include "ui/panels/TimelineBar.h"
#include "ui/plots/PlotsPanel.h"

#include <QAction>
#include <QUndoStack>

namespace phasebox {

ComparePresenter::ComparePresenter(ui::SceneView& canvas, ui::TimelineBar& timeline,
                                   ui::PlotsPanel& plots, PlotsPresenter& plotsPresenter,
                                   Document& document, SimulationController& controller,
                                   Recorder& recorder, QObject* parent)
    : Presenter(parent),
      canvas_(canvas),
      timeline_(timeline),
      plots_(plots),
      plotsPresenter_(plotsPresenter),
      document_(document),
      controller_(controller),
      recorder_(recorder) {
    // Another scene, or this one edited: the recorded run is no longer the scene's.
    connect(&document_, &Document::sceneReset, this, &ComparePresenter::leave);
    connect(&document_, &Document::sceneEdited, this, &ComparePresenter::leave);
    // Undoing the comparison. A stack cleared (a new scene, which sceneReset covers, or the
    // document going away) has dropped its commands and is left alone.
    connect(document_.undoStack(), &QUndoStack::indexChanged, this, [this](int index) {
        if (run_.isActive() && index < run_.undoIndex() &&
            document_.undoStack()->count() >= run_.undoIndex())
            leave();
    });
    connect(&controller_, &SimulationController::stepped, this, &ComparePresenter::refresh);
    connect(&controller_, &SimulationController::frameShown, this, &ComparePresenter::refresh);
    // The phase plot's object or coordinate changed: the ghost's trace follows.
    connect(&document_, &Document::selectionChanged, this, &ComparePresenter::refresh);
    connect(&plots_, &ui::PlotsPanel::phaseCoordinateRequested, this, &ComparePresenter::refresh);
}

void ComparePresenter::createActions(QWidget& window) {
    start_ = addWindowAction(window, QStringLiteral("compareFromHere"), tr("&Compare from Here…"));
    start_->setToolTip(
        tr("Run on from the timeline's moment with another integrator, dt or "
           "contact model, with the recorded run beside it as a ghost"));
    start_->setIconText(tr("Compare…"));  // the timeline's button: short, the slider keeps room
    connect(start_, &QAction::triggered, this, &ComparePresenter::startInteractively);
    leave_ = addWindowAction(window, QStringLiteral("leaveCompare"), tr("&Leave Compare"));
    leave_->setToolTip(tr("Remove the recorded run's ghost from the canvas and the plots"));
    leave_->setIconText(tr("Leave compare"));
    connect(leave_, &QAction::triggered, this, &ComparePresenter::leave);
    refresh();
}

bool ComparePresenter::canStart() const {
    const RunRecording* recording = controller_.runRecording();
    return recording && controller_.shownFrame() >= 0 &&
           controller_.shownFrame() < recording->frameCount() - 1;
}

bool ComparePresenter::start(const SimulationDesc& settings) {
    QString why;
    leave();
    if (!run_.start(controller_, document_, settings, &why)) {
        emit message(why);
        refresh();
        return false;
    }
    emit message(tr("Comparing from t = %L1 s: %2 against the recorded run (dashed).")
                     .arg(run_.startTime(), 0, 'f', 3)
                     .arg(CompareDialog::integratorLabel(settings.integrator)));
    plotsKey_.clear();
    refresh();
    return true;
}

void ComparePresenter::startInteractively() {
    if (!canStart()) {
        emit message(
            tr("Drag the timeline to an earlier moment first: the run is compared "
               "from there."));
        return;
    }
    const RunRecording& recording = *controller_.runRecording();
    const FrameState& frame = recording.frame(controller_.shownFrame());
    const SimulationSettings* recorded = recording.settingsAt(frame.stepCount);
    if (!recorded) return;
    auto* dialog =
        new CompareDialog(document_.setup().simulation, *recorded, frame.time, canvas_.window());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] { start(dialog->settings()); });
    dialog->open();
}

void ComparePresenter::leave() {
    const bool was = run_.isActive();
    run_.end();
    canvas_.setGhost(nullptr);
    plots_.setGhost({});
    plotsKey_.clear();
    if (was) {
        plotsPresenter_.refresh();
        emit message(tr("Left Compare: the recorded run's ghost is gone."));
    }
    refresh();
}

QString ComparePresenter::legendName() const {
    return tr("recorded: %1").arg(recordedRun());
}

QString ComparePresenter::recordedRun() const {
    const SimulationSettings& r = run_.recordedSettings();
    const SimulationDesc& now = document_.setup().simulation;
    QString what = CompareDialog::integratorLabel(r.integrator);
    if (r.dt != now.dt) what += tr(", dt %L1 s").arg(r.dt, 0, 'g', 4);
    if (r.contactModel != now.contactModel) {
        const QString models[] = {ui::ParametersPanel::tr("Impulse"),
                                  ui::ParametersPanel::tr("Penalty"),
                                  ui::ParametersPanel::tr("Kinematic")};
        what += QStringLiteral(", ") + models[static_cast<int>(r.contactModel) % 3];
    }
    return what;
}

void ComparePresenter::refresh() {
    if (run_.isActive() && controller_.shownFrame() < 0 &&
        document_.world().time() < run_.startTime() - CompareRun::kTimeSlack) {
        leave();  // the run went on from before the comparison's start: it is gone
        return;
    }
    if (start_) start_->setEnabled(canStart());
    if (leave_) leave_->setEnabled(run_.isActive());
    timeline_.setCompareAction(run_.isActive() ? leave_ : canStart() ? start_ : nullptr);
    if (!run_.isActive()) return;
    const double t = document_.world().time();
    const World* ghost = run_.ghostAt(t);
    const QString caption =
        run_.pastEnd(t)
            ? tr("Ghost: the recorded run ended at t = %L1 s").arg(run_.endTime(), 0, 'f', 3)
            : tr("Ghost: the recorded run, %1").arg(recordedRun());
    canvas_.setGhost(ghost, caption);
    updatePlots(false);
}

void ComparePresenter::updatePlots(bool force) {
    const QString object = recorder_.phaseObject();
    const QString coordinate = recorder_.phaseCoordinate();
    const QString key = legendName() + QLatin1Char('\n') + object + QLatin1Char('.') + coordinate;
    if (!force && key == plotsKey_) return;
    plotsKey_ = key;
    const Recorder& series = run_.series(object, coordinate);
    ui::GhostLines lines;
    lines.name = legendName();
    lines.energy.reserve(series.energySamples().size());
    for (const ui::EnergySample& e : series.energySamples())
        lines.energy.emplace_back(e.t, e.kinetic + e.potential);
    lines.phase = series.phaseSamples();
    lines.phaseTimes = series.phaseTimes();
    if (!object.isEmpty()) lines.phaseCoordinate = object + QLatin1Char('.') + coordinate;
    plots_.setGhost(std::move(lines));
    plotsPresenter_.refresh();
}

}  // namespace phasebox
