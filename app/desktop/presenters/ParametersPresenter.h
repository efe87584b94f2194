#pragma once
// The Parameters dock: the simulation settings (integrator, dt, sub-steps, tolerance, Newton
// iterations), the playback speed and the stability advisor's line. The panel's edits, the
// keyboard's (Simulation menu) and the accuracy lab's choice all reach the document through
// change(), one undoable command each.

#include "app/desktop/presenters/Presenter.h"
#include "physics/scene/SceneDesc.h"

#include <functional>

QT_BEGIN_NAMESPACE
class QSettings;
QT_END_NAMESPACE

namespace phasebox {

class Document;
class SimulationController;
namespace ui {
class ParametersPanel;
}

class ParametersPresenter : public Presenter {
    Q_OBJECT

public:
    ParametersPresenter(ui::ParametersPanel& panel, Document& document,
                        SimulationController& controller, QObject* parent = nullptr);

    void refresh() override;
    // The transport (play, step, reset), which the panel's buttons show too, and the keyboard's
    // steps (Simulation menu): next/previous integrator, double/halve dt, more or fewer
    // sub-steps, faster/slower.
    void createActions(QWidget& window);
    // The playback speed is the user's, not the scene's: it outlives the session.
    void readSettings(const QSettings& settings);
    void writeSettings(QSettings& settings) const;

    // The one way a settings change is applied: edit runs on a copy of the scene's settings,
    // which goes to Document::applySimulationSettings (one undo step; the live world keeps its
    // state). A refused change leaves the settings as they were and shows them again.
    bool change(const std::function<void(SimulationDesc&)>& edit);

    void cycleIntegrator(int direction);
    void scaleDt(double factor);
    void changeSubsteps(int delta);
    void changeSpeed(int direction);
    void setSpeed(double factor);
    // The accuracy lab's pick: an integrator with its dt and tolerance, as one undo step.
    void applyStudyChoice(const QString& integrator, double dt, double tolerance);

signals:
    void speedChanged(double factor);

private:
    void showSettings();
    void updateAdvice();

    ui::ParametersPanel& panel_;
    Document& document_;
    SimulationController& controller_;
};

}  // namespace phasebox
