#pragma once
// The canvas in the middle: shows the document's live world with the selection highlighted and
// a line of what runs (time, integrator, dt). The mouse's tools are CanvasTools'.

#include "app/desktop/presenters/Presenter.h"
#include "ui/canvas/Appearance.h"
#include "ui/canvas/SceneRenderer.h"

#include <QList>
#include <QRectF>

#include <vector>

QT_BEGIN_NAMESPACE
class QSettings;
QT_END_NAMESPACE

namespace phasebox {

class CanvasTools;
class Document;
class SimulationController;
namespace ui {
class SceneView;
}

class CanvasPresenter : public Presenter {
    Q_OBJECT

public:
    CanvasPresenter(ui::SceneView& view, CanvasTools& tools, Document& document,
                    SimulationController& controller, QObject* parent = nullptr);

    void refresh() override;
    // The canvas's actions: the tools (keys 1 to 0, R and P), Fit Scene, the drawing options
    // (trails, velocity arrows, labels, grid) and the picture export.
    void createActions(QWidget& window);
    QList<QAction*> toolActions() const { return toolActions_; }
    // The polygon tool's number of sides, for the tool bar (made by createActions).
    QWidget* polygonSidesBox() const { return polygonSides_; }
    // The joint tool's kind, for the tool bar.
    QWidget* jointTypeBox() const { return jointType_; }
    // Thicker lines and larger labels for a projector.
    void setPresentation(bool on);
    // The theme's colours and the user's line and text scales (AppearancePresenter), which
    // multiply presentation mode's.
    void setAppearance(const ui::Appearance& appearance);
    // The drawing options are the user's, not the scene's: they outlive the session.
    void readSettings(const QSettings& settings);
    void writeSettings(QSettings& settings) const;
    // What the canvas's accessible description says of the selection, live.
    QString describeSelection() const;
    // A PNG of the scene, at least 800 × 600 pixels.
    bool exportPicture(const QString& path, QString* error) const;
    // Asks for a file name, then exports.
    void exportInteractively();

signals:
    // Enter on the canvas with the Select tool and a selection: its properties, please.
    void propertiesWanted();

private:
    struct ViewOption {
        QAction* action;
        bool ui::RenderOptions::*member;
        QString settingsKey;  // empty: not kept between sessions
    };

    void showSelection();
    void connectKeyboard();
    void applyLook();
    void setOption(bool ui::RenderOptions::*member, bool on);
    // Follow mode (View > Follow): the selection, or every moving object, stays in view.
    void followNow();
    QRectF motionExtent() const;
    static constexpr qint64 kPreviewMilliseconds = 150;  // motionExtent's wall-time budget
    static constexpr double kFollowMargin = 48.0;        // pixels kept free around what is followed
    bool following_ = false;

    ui::SceneView& view_;
    CanvasTools& tools_;
    Document& document_;
    QList<QAction*> toolActions_;
    QWidget* polygonSides_ = nullptr;
    QWidget* jointType_ = nullptr;
    std::vector<ViewOption> options_;
    bool presentation_ = false;
    ui::Appearance appearance_;
};

}  // namespace phasebox
