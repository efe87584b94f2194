#pragma once
// The parameters panel: integrator, dt, sub-steps, tolerance, Newton iterations, speed, the
// transport buttons and the stability advisor's line. It shows settings and reports the
// user's changes as signals; the app applies them (to the document and the live world) and
// the setters here never emit.

#include "physics/scene/SceneDesc.h"

#include <QString>
#include <QWidget>

#include <vector>

QT_BEGIN_NAMESPACE
class QAction;
class QCheckBox;
class QComboBox;
class QLabel;
class QSpinBox;
class QToolButton;
QT_END_NAMESPACE

namespace phasebox::ui {

class ScientificSpinBox;

class ParametersPanel : public QWidget {
    Q_OBJECT
public:
    explicit ParametersPanel(QWidget* parent = nullptr);

    // Shows a scene's simulation settings without emitting any signal.
    void setSimulation(const SimulationDesc& simulation);
    // Shows the playback speed (the nearest of ¼×…4×) without emitting speedChanged.
    void setSpeed(double factor);

    // The app's actions drive the transport buttons (text, icon, checked state, enabled,
    // shortcut), so the buttons, menus and shortcuts can never disagree. Tooltips gain the
    // actions' shortcuts. Any may be nullptr.
    void setActions(QAction* play, QAction* step, QAction* reset);

    // The stability advisor's verdict; warning = the current settings will blow up. An empty
    // text hides the line.
    // details: the largest stable step of each method, shown as the line's tooltip.
    void setAdvice(const QString& text, bool warning, const QString& details = {});
    // The penalty stiffness in use (the scene's or the automatic choice), without emitting.
    void setContactStiffness(double stiffness, bool automatic);

    QString integrator() const;
    double dt() const;
    int substeps() const;
    double tolerance() const;
    int newtonIterations() const;
    double speed() const;
    ContactModel contactModel() const;
    QString adviceText() const;

    // The quick dt presets, in seconds (1/30 … 1/1000).
    static const std::vector<double>& dtPresets();
    // The playback speeds offered (¼× … 4×).
    static const std::vector<double>& speeds();

signals:
    void integratorChanged(const QString& name);
    void dtChanged(double seconds);
    void substepsChanged(int substeps);
    void toleranceChanged(double tolerance);
    void newtonIterationsChanged(int iterations);
    void speedChanged(double factor);
    void contactModelChanged(phasebox::ContactModel model);
    void contactStiffnessChanged(double stiffness);  // 0: automatic
    void contactDampingChanged(double damping);
    void sleepChanged(bool sleep);  // simulation.sleep

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void updateEnabledFields();
    void setButtonAction(QToolButton* button, QAction* action);

    QToolButton* playButton_ = nullptr;
    QToolButton* stepButton_ = nullptr;
    QToolButton* resetButton_ = nullptr;
    QComboBox* integratorBox_ = nullptr;
    ScientificSpinBox* dtBox_ = nullptr;
    QToolButton* dtPresetButton_ = nullptr;
    QSpinBox* substepsBox_ = nullptr;
    ScientificSpinBox* toleranceBox_ = nullptr;
    QLabel* toleranceLabel_ = nullptr;
    QSpinBox* newtonBox_ = nullptr;
    QLabel* newtonLabel_ = nullptr;
    QComboBox* speedBox_ = nullptr;
    QComboBox* contactModelBox_ = nullptr;
    QCheckBox* sleepBox_ = nullptr;
    ScientificSpinBox* stiffnessBox_ = nullptr;
    QToolButton* automaticStiffnessButton_ = nullptr;
    QLabel* stiffnessLabel_ = nullptr;
    ScientificSpinBox* contactDampingBox_ = nullptr;
    QLabel* contactDampingLabel_ = nullptr;
    QLabel* advice_ = nullptr;
};

}  // namespace phasebox::ui
