#pragma once
// Compare from here: the settings the run goes on with from the timeline's moment (integrator,
// dt, contact model), while the recorded run is drawn beside it as a ghost.

#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"

#include <QDialog>

QT_BEGIN_NAMESPACE
class QComboBox;
class QDoubleSpinBox;
QT_END_NAMESPACE

namespace phasebox {

class CompareDialog : public QDialog {
    Q_OBJECT

public:
    // current: the scene's settings (what is not chosen here is kept); recorded: what the
    // recorded run had at time t. The next integrator after the recorded one is proposed.
    CompareDialog(const SimulationDesc& current, const SimulationSettings& recorded, double t,
                  QWidget* parent = nullptr);

    // The scene's settings with the choices made here.
    SimulationDesc settings() const;

    // "Explicit Euler" in the app's language.
    static QString integratorLabel(const std::string& name);

private:
    SimulationDesc current_;
    double recordedDt_, shownDt_;  // the field rounds dt: left as shown, the recorded dt is kept
    QComboBox* integrator_;
    QDoubleSpinBox* dt_;
    QComboBox* contactModel_;
};

}  // namespace phasebox
