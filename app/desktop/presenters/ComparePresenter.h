#pragma once
// Compare from here (Simulation menu and the timeline's button): from the timeline's moment the
// run goes on with another integrator, dt or contact model (CompareDialog) while the recorded
// run is drawn beside it, on the canvas as a ghost and in the energy and phase plots as dashed
// lines named after the recorded method (CompareRun holds it). Leave Compare, Reset, New, Open,
// an edit of the scene, undoing the comparison, or going on from before its start drop the
// ghost, so no view keeps a run that is not the scene's.

#include "app/desktop/presenters/Presenter.h"
#include "app/sim/CompareRun.h"

#include <QPointer>
#include <QString>

QT_BEGIN_NAMESPACE
class QAction;
QT_END_NAMESPACE

namespace phasebox {

class Document;
class PlotsPresenter;
class Recorder;
class SimulationController;
struct SimulationDesc;
namespace ui {
class PlotsPanel;
class SceneView;
class TimelineBar;
}  // namespace ui

class ComparePresenter : public Presenter {
    Q_OBJECT

public:
    ComparePresenter(ui::SceneView& canvas, ui::TimelineBar& timeline, ui::PlotsPanel& plots,
                     PlotsPresenter& plotsPresenter, Document& document,
                     SimulationController& controller, Recorder& recorder,
                     QObject* parent = nullptr);

    // The ghost at the live run's time, the plots' ghost lines, the actions' states.
    void refresh() override;
    // "Compare from Here…" and "Leave Compare" (Simulation menu; the timeline shows the one
    // that applies).
    void createActions(QWidget& window);

    // Starts comparing from the timeline's shown frame with these settings; false (and a
    // message) when refused.
    bool start(const SimulationDesc& settings);
    // Asks for the settings (CompareDialog), then starts.
    void startInteractively();
    void leave();
    const CompareRun& run() const { return run_; }

private:
    bool canStart() const;
    // "Explicit Euler", with its dt and contact model where they differ from the live run's.
    QString recordedRun() const;
    QString legendName() const;
    void updatePlots(bool force);

    ui::SceneView& canvas_;
    ui::TimelineBar& timeline_;
    ui::PlotsPanel& plots_;
    PlotsPresenter& plotsPresenter_;
    Document& document_;
    SimulationController& controller_;
    Recorder& recorder_;
    CompareRun run_;
    QAction* start_ = nullptr;
    QAction* leave_ = nullptr;
    QString plotsKey_;  // the phase target the plots' ghost lines were made for
};

}  // namespace phasebox
