#pragma once
// The exact solution beside the simulation (View > Exact Solution): when the scene's motion has
// a closed form (app/accuracy/ExactReference: oscillators, free fall, Kepler orbits, simple
// pendulums), the canvas draws where each body would be now and the path it would take, dashed,
// and the phase plot draws the exact curve over the same times. A lesson that says "next to its
// exact solution" then shows it; a scene without a closed form shows nothing extra.

#include "app/accuracy/ExactReference.h"
#include "app/desktop/presenters/Presenter.h"
#include "ui/canvas/ReferenceOverlay.h"
#include "ui/plots/Charts.h"

#include <QElapsedTimer>

#include <optional>
#include <vector>

namespace phasebox {

class Document;
class Recorder;
class SimulationController;
namespace ui {
class PlotsPanel;
class SceneView;
}  // namespace ui

class ExactPresenter : public Presenter {
    Q_OBJECT

public:
    ExactPresenter(ui::SceneView& view, ui::PlotsPanel& plots, Document& document,
                   SimulationController& controller, const Recorder& recorder,
                   QObject* parent = nullptr);

    void refresh() override;
    // View > Exact Solution (checkable, on by default).
    void createActions(QWidget& window);
    void setShown(bool on);
    bool isShown() const { return shown_; }
    // What the closed form is ("harmonic oscillator", …), or empty when the scene has none.
    QString kind() const;
    // The exact state now, for tests and the overlay: nullopt without a closed form.
    const std::optional<ExactReference>& reference() const { return reference_; }

    // Scenes above this many objects are not searched for a closed form: building the world at
    // its start again would cost more than a frame, and big scenes are gases and cloths.
    static constexpr int kMaxObjects = 2000;
    static constexpr int kMaxPaths = 32;       // bodies whose exact path is drawn
    static constexpr int kPathSamples = 600;   // points per path
    static constexpr int kPhaseSamples = 800;  // points of the phase plot's exact curve
    static constexpr qint64 kPhaseIntervalMs = 200;

signals:
    // The phase plot's exact curve changed other than by time passing (a new scene, another
    // object, the overlay switched): the plot should be drawn again now.
    void phaseReferenceChanged();

private:
    void rebuild();
    void updatePhase();
    int phaseDof() const;

    ui::SceneView& view_;
    ui::PlotsPanel& plots_;
    Document& document_;
    const Recorder& recorder_;
    std::optional<ExactReference> reference_;
    int dimension_ = 0;
    QList<QPolygonF> paths_;
    bool shown_ = true;
    QAction* action_ = nullptr;
    QElapsedTimer sincePhase_;
};

}  // namespace phasebox
