#pragma once
// The scene canvas. It shows a World through a ViewTransform and navigates (the wheel zooms
// around the cursor; a middle- or right-button drag, or Space with a left drag, pans; + and −
// zoom). Everything else the mouse does is reported in world coordinates for the app's tools:
// the canvas edits nothing.
//
// Two surfaces draw the same picture through SceneRenderer: a plain raster widget, the default
// and the one that runs under the offscreen and minimal platforms and on software GL
// (llvmpipe), and a multisampled QOpenGLWidget used only where a hardware GL is present.

#include "ui/canvas/MeasureOverlay.h"
#include "ui/canvas/ReferenceOverlay.h"
#include "ui/canvas/SceneRenderer.h"
#include "ui/canvas/ViewTransform.h"

#include <QCursor>
#include <QImage>
#include <QList>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <QWidget>

namespace phasebox::ui {

enum class CanvasBackend { Auto, Raster, OpenGL };

// A tool's preview drawn dashed over the scene, in world coordinates: a line, a rubber band
// (Rect with corners a and b), an arrow from a to b, a circle with centre a through b, an
// outline in progress (Polyline: points joined in order, then on to b, with a ring round the
// first point where a click closes it). The text is written next to b (e.g. "1.20 m").
struct ToolOverlay {
    enum Shape { None, Line, Rect, Arrow, Circle, Polyline };
    Shape shape = None;
    QPointF a, b;
    QString text;
    QList<QPointF> points;
};

class SceneView : public QWidget {
    Q_OBJECT

public:
    explicit SceneView(QWidget* parent = nullptr);
    ~SceneView() override;

    // The world shown (not owned; nullptr shows the empty grid). Repaint with update() after
    // the world changes; the view itself is not moved.
    void setWorld(const World* world);
    const World* world() const { return world_; }

    // Asks for a backend; what is used is resolveBackend(backend). Switches at once.
    void setBackend(CanvasBackend backend);
    CanvasBackend backend() const { return requested_; }
    bool usingOpenGL() const { return usingOpenGL_; }
    // Raster or OpenGL for a request. PHASEBOX_CANVAS=raster|opengl overrides the request (a
    // way out when a driver misbehaves); under the offscreen and minimal platforms it is
    // always Raster, because a QOpenGLWidget crashes there. Auto means OpenGL only on a
    // hardware GL; an explicit OpenGL needs a GL context of any kind.
    static CanvasBackend resolveBackend(CanvasBackend requested);
    // A GL context can be made and its renderer is not a software one (llvmpipe, softpipe,
    // Software Rasterizer, SwiftShader). Probed once with an offscreen surface.
    static bool hardwareGlAvailable();

    ViewTransform view() const;
    void setView(const ViewTransform& view);
    // Frames every object with marginPixels around (at least 2 m of world, so a lone small
    // particle is seen in context); with nothing to frame, 10 m across around the origin.
    // Until the user navigates, a resize frames the world again.
    // alsoInclude (left = min x, top = min y; null = nothing): a world area to frame as well,
    // such as where the scene's motion will go (kept while the view follows the widget's size).
    void fitToWorld(double marginPixels = 32.0, const QRectF& alsoInclude = {});
    // Shows widthMetres of the world across, centred on centre (a lesson's saved view); until
    // the user navigates, a resize keeps that width across.
    void showWidth(QPointF centre, double widthMetres);
    // The world width the view shows across now.
    double shownWidth() const;
    // The user navigated (or showWidth set the view): the view is not the automatic framing.
    bool isChosenView() const { return framing_ == Framing::Width || framing_ == Framing::Manual; }
    void zoomBy(double factor);  // around the widget's centre
    QPointF toWorld(QPointF widgetPoint) const { return view().toWorld(widgetPoint); }
    QPointF toWidget(QPointF worldPoint) const { return view().toScreen(worldPoint); }

    void setRenderOptions(const RenderOptions& options);
    const RenderOptions& renderOptions() const { return options_; }
    // Recorded on every repaint while options.trails is on (a repaint without a step adds
    // nothing); clear it on reset.
    TrailHistory& trails() { return trails_; }

    void setOverlay(const ToolOverlay& overlay);

    // ---- the keyboard (SceneViewKeyboard.cpp) ----
    // The objects Tab and Shift+Tab walk, in order; past either end the focus leaves the canvas.
    void setKeyboardTargets(const QStringList& ids);
    // Where the tools place an object from the keyboard (Enter); the arrow keys move it unless
    // they move the selection. Drawn as a cross while the canvas has the focus.
    QPointF keyboardCursor() const { return keyboardCursor_; }
    void setKeyboardCursor(QPointF world);
    // Whether the arrow keys move the selection (the Select tool) or the cursor (the others).
    void setArrowsMoveSelection(bool on) { arrowsMoveSelection_ = on; }
    // One arrow key's step in metres, and Shift's fine one.
    static constexpr double kKeyboardStep = 0.1;
    static constexpr double kKeyboardFineStep = 0.01;
    // The scene's exact solution beside the simulation (empty: none drawn).
    void setReferenceOverlay(const ReferenceOverlay& overlay);
    const ReferenceOverlay& referenceOverlay() const { return reference_; }
    const ToolOverlay& overlay() const { return overlay_; }
    // The rulers, protractors and free-body view (drawn over the scene, under the tool's
    // preview; in renderImage too: they are part of the picture).
    void setMeasurements(const MeasureOverlay& measurements);
    const MeasureOverlay& measurements() const { return measurements_; }
    // A recorded run's ghost drawn over the scene (GhostOverlay.h) and its caption; nullptr:
    // none. Not owned; repaint with update() after it changes.
    void setGhost(const World* ghost, const QString& caption = {});
    const World* ghost() const { return ghost_; }
    QString ghostCaption() const { return ghostCaption_; }
    void setHudText(const QString& text);
    QString hudText() const { return hudText_; }

    // The scene and its measurements (no tool preview; the HUD line only when asked, as a
    // clip's frames show it) framed as on screen, at another size: a larger picture is the same
    // view in more pixels, lines and text thickened to match.
    QImage renderImage(QSize size, bool withHud = false) const;
    PickResult pick(QPointF widgetPoint, double tolerancePixels = 6.0) const;

    QSize sizeHint() const override { return {800, 600}; }
    QSize minimumSizeHint() const override { return {160, 120}; }

signals:
    void worldMousePressed(QPointF world, Qt::MouseButton button, Qt::KeyboardModifiers modifiers);
    void worldMouseMoved(QPointF world, Qt::MouseButtons buttons, Qt::KeyboardModifiers modifiers);
    void worldMouseReleased(QPointF world, Qt::MouseButton button, Qt::KeyboardModifiers modifiers);
    // Replaces the second press of a double click (Qt's order: press, release, double click,
    // release).
    void worldMouseDoubleClicked(QPointF world, Qt::MouseButton button,
                                 Qt::KeyboardModifiers modifiers);
    // A right click that did not become a pan: the place for a context menu.
    void worldContextMenuRequested(QPointF world, QPoint globalPosition);
    void viewChanged();
    // The keyboard: Tab chose an object; an arrow key asks to move the selection by delta
    // (metres); Enter was pressed with the cursor at cursor (the selection's properties, or the
    // current tool's object placed there).
    void keyboardSelected(const QString& id);
    void keyboardNudged(QPointF delta);
    void keyboardActivated(QPointF cursor);

protected:
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;
    void focusInEvent(QFocusEvent* event) override;
    bool focusNextPrevChild(bool next) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    // How the view follows the widget's size until the user navigates.
    enum class Framing { Default, World, Width, Manual };

    void createSurface(CanvasBackend resolved);
    void paintSurface(QPainter& painter, QSize size);
    void syncView() const;
    void frameNow() const;
    void startPan(Qt::MouseButton button, QPointF position);
    void endPan();
    void updatePanCursor();
    bool handleKeyboardEditing(QKeyEvent* event);
    void drawKeyboardCursor(QPainter& painter) const;

    const World* world_ = nullptr;
    QWidget* surface_ = nullptr;
    CanvasBackend requested_ = CanvasBackend::Auto;
    bool usingOpenGL_ = false;

    // The centre and scale; its widget size follows size() lazily (see syncView), since a
    // hidden widget is resized without a resize event.
    mutable ViewTransform view_;
    mutable QSize syncedSize_;  // the size view_ was last fitted to; invalid at first
    Framing framing_ = Framing::Default;
    QRectF alsoInclude_;  // fitToWorld's extra area
    double fitMargin_ = 32.0;
    QPointF shownCentre_;  // showWidth's view
    double shownWidth_ = 10.0;

    RenderOptions options_;
    TrailHistory trails_;
    ToolOverlay overlay_;
    ReferenceOverlay reference_;
    MeasureOverlay measurements_;
    QString hudText_;
    const World* ghost_ = nullptr;
    QString ghostCaption_;
    QStringList keyboardTargets_;
    QPointF keyboardCursor_{0.0, 0.0};
    bool arrowsMoveSelection_ = true;

    Qt::MouseButton panButton_ = Qt::NoButton;
    QPointF lastPanPosition_;
    double panTravel_ = 0.0;  // pixels: a right click that moved less is a click
    bool spaceHeld_ = false;
    bool cursorSaved_ = false;
    bool hadCursor_ = false;
    QCursor savedCursor_;
};

}  // namespace phasebox::ui
