#include "ui/canvas/SceneView.h"

#include "ui/canvas/GhostOverlay.h"

#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QOpenGLWidget>
#include <QPainter>
#include <QPolygonF>
#include <QSurfaceFormat>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <cmath>
#include <functional>
#include <limits>
#include <utility>

namespace phasebox::ui {

namespace {

// The world a scene of planes alone opens on: 10 m along the ground, 6 m above it.
constexpr double kEmptyGroundWidth = 10.0;
constexpr double kEmptyGroundHeight = 6.0;

using PaintFunction = std::function<void(QPainter&, QSize)>;

// Both surfaces only paint: input goes through them to the SceneView, which navigates and
// reports, so the two backends cannot behave differently. Neither may be marked opaque: the
// app repaints with update() on the SceneView, and Qt does not repaint an opaque child that
// covers a parent it was asked to update (a test pins this).
void makePassive(QWidget* surface) {
    surface->setAttribute(Qt::WA_TransparentForMouseEvents);
    surface->setAttribute(Qt::WA_OpaquePaintEvent, false);
    surface->setFocusPolicy(Qt::NoFocus);
}

class RasterSurface final : public QWidget {
public:
    RasterSurface(PaintFunction paint, QWidget* parent)
        : QWidget(parent), paint_(std::move(paint)) {
        makePassive(this);
    }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter painter(this);
        paint_(painter, size());
    }

private:
    PaintFunction paint_;
};

class GlSurface final : public QOpenGLWidget {
public:
    GlSurface(PaintFunction paint, QWidget* parent)
        : QOpenGLWidget(parent), paint_(std::move(paint)) {
        QSurfaceFormat format = QSurfaceFormat::defaultFormat();
        format.setSamples(4);
        setFormat(format);
        makePassive(this);
    }

protected:
    void paintGL() override {
        QPainter painter(this);
        paint_(painter, size());
    }

private:
    PaintFunction paint_;
};

bool headlessPlatform() {
    const QString platform = QGuiApplication::platformName();
    return platform == QLatin1String("offscreen") || platform == QLatin1String("minimal");
}

// The GL renderer's name, or empty when no GL context can be made. Probed once: creating a
// context costs milliseconds and the answer does not change while the program runs.
QString glRenderer() {
    static const QString renderer = [] {
        QOpenGLContext context;
        if (!context.create()) return QString();
        QOffscreenSurface surface;
        surface.setFormat(context.format());
        surface.create();
        if (!surface.isValid() || !context.makeCurrent(&surface)) return QString();
        const auto* name = context.functions()->glGetString(GL_RENDERER);
        QString result =
            name ? QString::fromLatin1(reinterpret_cast<const char*>(name)) : QString();
        context.doneCurrent();
        return result;
    }();
    return renderer;
}

void drawOverlay(QPainter& p, const ViewTransform& view, const ToolOverlay& overlay,
                 const RenderOptions& options) {
    if (overlay.shape == ToolOverlay::None && overlay.text.isEmpty()) return;
    const double lw = options.lineWidthScale;
    const QPointF a = view.toScreen(overlay.a), b = view.toScreen(overlay.b);
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setBrush(Qt::NoBrush);
    QPen pen(options.colors.text, 1.5 * lw, Qt::DashLine);
    p.setPen(pen);
    switch (overlay.shape) {
        case ToolOverlay::Line:
            p.drawLine(a, b);
            break;
        case ToolOverlay::Rect:
            p.drawRect(QRectF(a, b).normalized());
            break;
        case ToolOverlay::Circle: {
            const double r = QLineF(a, b).length();
            p.drawEllipse(a, r, r);
            p.drawLine(a, b);
            break;
        }
        case ToolOverlay::Arrow: {
            p.drawLine(a, b);
            const QLineF line(b, a);
            if (line.length() > 1.0) {
                pen.setStyle(Qt::SolidLine);
                p.setPen(pen);
                const QPointF u = (a - b) / line.length(), n(-u.y(), u.x());
                const double h = std::min(12.0 * lw, 0.5 * line.length());
                p.drawLine(b, b + u * h + n * (0.45 * h));
                p.drawLine(b, b + u * h - n * (0.45 * h));
            }
            break;
        }
        case ToolOverlay::Polyline: {
            if (overlay.points.isEmpty()) break;
            QPolygonF line;
            for (const QPointF& q : overlay.points) line << view.toScreen(q);
            line << b;
            p.drawPolyline(line);
            pen.setStyle(Qt::SolidLine);
            p.setPen(pen);
            for (const QPointF& q : std::as_const(line).first(line.size() - 1))
                p.drawEllipse(q, 2.5 * lw, 2.5 * lw);
            p.drawEllipse(line.front(), 6.0 * lw, 6.0 * lw);  // click here to close
            break;
        }
        case ToolOverlay::None:
            break;
    }
    if (!overlay.text.isEmpty()) {
        QFont font = p.font();
        font.setPixelSize(std::max(6, static_cast<int>(std::lround(12.0 * options.fontScale))));
        p.setFont(font);
        const QRectF bounds = p.fontMetrics().boundingRect(overlay.text).toRectF();
        QRectF box(b + QPointF(10.0 * lw, -10.0 * lw - bounds.height()),
                   bounds.size() + QSizeF(8.0, 4.0));
        p.setPen(Qt::NoPen);
        p.setBrush(options.colors.backdrop);
        p.drawRoundedRect(box, 3.0, 3.0);
        p.setPen(options.colors.text);
        p.drawText(box, Qt::AlignCenter, overlay.text);
    }
    p.restore();
}

void drawHud(QPainter& p, const QString& text, const RenderOptions& options) {
    if (text.isEmpty()) return;
    p.save();
    QFont font = p.font();
    font.setPixelSize(std::max(6, static_cast<int>(std::lround(13.0 * options.fontScale))));
    p.setFont(font);
    const QRectF bounds =
        p.fontMetrics().boundingRect(QRect(0, 0, 10000, 10000), 0, text).toRectF();
    const QRectF box(QPointF(8.0, 8.0), bounds.size() + QSizeF(12.0, 6.0));
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setPen(Qt::NoPen);
    p.setBrush(options.colors.backdrop);
    p.drawRoundedRect(box, 4.0, 4.0);
    p.setPen(options.colors.text);
    p.drawText(box, Qt::AlignCenter, text);
    p.restore();
}

}  // namespace

SceneView::SceneView(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);  // hover: tools highlight what a click would pick
    // Right-drag pans; a right click without a drag is reported as worldContextMenuRequested.
    setContextMenuPolicy(Qt::PreventContextMenu);
    createSurface(resolveBackend(requested_));
}

SceneView::~SceneView() = default;

void SceneView::setWorld(const World* world) {
    if (world != world_) trails_.clear();
    world_ = world;
    surface_->update();
}

CanvasBackend SceneView::resolveBackend(CanvasBackend requested) {
    const QByteArray forced = qgetenv("PHASEBOX_CANVAS").trimmed().toLower();
    if (forced == "raster") requested = CanvasBackend::Raster;
    if (forced == "opengl") requested = CanvasBackend::OpenGL;
    if (requested == CanvasBackend::Raster || !qGuiApp || headlessPlatform())
        return CanvasBackend::Raster;
    if (requested == CanvasBackend::OpenGL)
        return glRenderer().isEmpty() ? CanvasBackend::Raster : CanvasBackend::OpenGL;
    return hardwareGlAvailable() ? CanvasBackend::OpenGL : CanvasBackend::Raster;
}

bool SceneView::hardwareGlAvailable() {
    // Checked before any probe: under these platforms even the probe is not worth the risk.
    if (!qGuiApp || headlessPlatform()) return false;
    const QString renderer = glRenderer().toLower();
    if (renderer.isEmpty()) return false;
    for (const char* software :
         {"llvmpipe", "softpipe", "software rasterizer", "swiftshader", "swrast", "basic render"})
        if (renderer.contains(QLatin1String(software))) return false;
    return true;
}

void SceneView::setBackend(CanvasBackend backend) {
    requested_ = backend;
    const CanvasBackend resolved = resolveBackend(backend);
    if (surface_ && usingOpenGL_ == (resolved == CanvasBackend::OpenGL)) return;
    createSurface(resolved);
}

void SceneView::createSurface(CanvasBackend resolved) {
    delete surface_;
    PaintFunction paint = [this](QPainter& painter, QSize size) { paintSurface(painter, size); };
    usingOpenGL_ = resolved == CanvasBackend::OpenGL;
    if (usingOpenGL_)
        surface_ = new GlSurface(std::move(paint), this);
    else
        surface_ = new RasterSurface(std::move(paint), this);
    layout()->addWidget(surface_);
}

void SceneView::paintSurface(QPainter& painter, QSize size) {
    syncView();
    if (world_ && options_.trails) trails_.record(*world_);
    if (world_)
        SceneRenderer::paint(painter, view_, size, *world_, options_, &trails_);
    else
        SceneRenderer::paintEmpty(painter, view_, size, options_);
    if (world_ && ghost_) drawGhost(painter, view_, size, *ghost_, options_);
    if (world_) drawReferenceOverlay(painter, view_, reference_, options_);
    MeasureRenderer::paint(painter, view_, size, measurements_, options_);
    if (world_ && ghost_) drawGhostCaption(painter, size, ghostCaption_, options_);
    drawOverlay(painter, view_, overlay_, options_);
    drawHud(painter, hudText_, options_);
    drawKeyboardCursor(painter);
}

// ---- the view ---------------------------------------------------------------------------------

ViewTransform SceneView::view() const {
    syncView();
    return view_;
}

void SceneView::syncView() const {
    if (syncedSize_ == size()) return;
    syncedSize_ = size();
    if (framing_ == Framing::Manual)
        view_.setWidgetSize(size());
    else
        frameNow();
}

void SceneView::frameNow() const {
    const QSizeF widget(size());
    if (framing_ == Framing::Width) {
        view_ = ViewTransform(shownCentre_, std::max(1.0, widget.width()) / shownWidth_, widget);
        return;
    }
    // Corners by hand: QRectF::united() drops empty rects, and a plane's point is one.
    double lo[2] = {std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
    double hi[2] = {-lo[0], -lo[1]};
    const auto include = [&](const Vec2& p, double reach) {
        for (int k = 0; k < 2; ++k) {
            lo[k] = std::min(lo[k], p[k] - reach);
            hi[k] = std::max(hi[k], p[k] + reach);
        }
    };
    if (world_ && framing_ == Framing::World) {
        const World& w = *world_;
        for (int i = 0; i < static_cast<int>(w.particles().size()); ++i)
            include(w.particlePosition(i), w.particles()[i].radius);
        for (int i = 0; i < static_cast<int>(w.rigidBodies().size()); ++i)
            include(w.bodyPosition(i), 0.5 * w.rigidBodies()[i].size.norm());
        // A scene of planes alone (File > New: the ground) shows a classroom's worth of world
        // above them, kEmptyGroundWidth wide, instead of the few metres around a plane's point.
        const bool onlyPlanes = w.particles().empty() && w.rigidBodies().empty() &&
                                w.springs().empty() && w.joints().empty();
        for (const Plane& plane : w.planes()) {
            include(plane.point, 0.0);
            if (!onlyPlanes) continue;
            const Vec2 along(plane.normal.y(), -plane.normal.x());
            include(plane.point + 0.5 * kEmptyGroundWidth * along, 0.0);
            include(plane.point - 0.5 * kEmptyGroundWidth * along, 0.0);
            include(plane.point + kEmptyGroundHeight * plane.normal, 0.0);
            include(plane.point - 0.5 * plane.normal, 0.0);
        }
        for (const Spring& s : w.springs())
            for (const SpringEnd* end : {&s.a, &s.b})
                if (end->kind == SpringEnd::Kind::Anchor) include(end->point, 0.0);
        // What joints hold to the world: anchors, pulley wheels, a track's curve.
        for (const Joint& j : w.joints()) {
            if (j.b.kind == JointBody::Kind::World && j.type != Joint::Type::Track)
                include(j.b.point, 0.0);
            if (j.type == Joint::Type::Pulley) {
                include(j.groundA, 0.0);
                include(j.groundB, 0.0);
            }
            if (j.type == Joint::Type::Track && j.circle) include(j.center, j.radius);
        }
        // isNull, not isEmpty: a motion along one axis has no height and must still count.
        if (!alsoInclude_.isNull()) {
            include(Vec2(alsoInclude_.left(), alsoInclude_.top()), 0.0);
            include(Vec2(alsoInclude_.right(), alsoInclude_.bottom()), 0.0);
        }
    }
    if (!(lo[0] <= hi[0])) {  // nothing to frame
        view_ = ViewTransform({0.0, 0.0}, std::max(1.0, widget.width()) / 10.0, widget);
        return;
    }
    // At least 2 m of world each way, so a lone small particle is seen in context.
    constexpr double kMinExtent = 2.0;
    for (int k = 0; k < 2; ++k) {
        const double grow = 0.5 * std::max(0.0, kMinExtent - (hi[k] - lo[k]));
        lo[k] -= grow;
        hi[k] += grow;
    }
    const QRectF bounds(QPointF(lo[0], lo[1]), QPointF(hi[0], hi[1]));
    view_.fit(bounds, widget, fitMargin_);
}

void SceneView::setView(const ViewTransform& view) {
    framing_ = Framing::Manual;
    view_ = view;
    view_.setWidgetSize(size());
    syncedSize_ = size();
    surface_->update();
    emit viewChanged();
}

void SceneView::fitToWorld(double marginPixels, const QRectF& alsoInclude) {
    framing_ = Framing::World;
    alsoInclude_ = alsoInclude;
    fitMargin_ = marginPixels;
    frameNow();
    syncedSize_ = size();
    surface_->update();
    emit viewChanged();
}

void SceneView::showWidth(QPointF centre, double widthMetres) {
    framing_ = Framing::Width;
    shownCentre_ = centre;
    shownWidth_ = widthMetres;
    frameNow();
    syncedSize_ = size();
    surface_->update();
    emit viewChanged();
}

double SceneView::shownWidth() const {
    if (framing_ == Framing::Width) return shownWidth_;  // as asked, not as rounded by the scale
    const ViewTransform v = view();
    return std::max(1.0, v.widgetSize().width()) / v.pixelsPerMetre();
}

void SceneView::zoomBy(double factor) {
    ViewTransform v = view();
    v.zoomAround(QPointF(0.5 * width(), 0.5 * height()), factor);
    setView(v);
}

void SceneView::setRenderOptions(const RenderOptions& options) {
    if (!options.trails && options_.trails) trails_.clear();
    options_ = options;
    surface_->update();
}

void SceneView::setMeasurements(const MeasureOverlay& measurements) {
    measurements_ = measurements;
    surface_->update();
}

void SceneView::setOverlay(const ToolOverlay& overlay) {
    overlay_ = overlay;
    surface_->update();
}

void SceneView::setReferenceOverlay(const ReferenceOverlay& overlay) {
    reference_ = overlay;
    surface_->update();
}

void SceneView::setHudText(const QString& text) {
    if (text == hudText_) return;
    hudText_ = text;
    surface_->update();
}

void SceneView::setGhost(const World* ghost, const QString& caption) {
    ghost_ = ghost;
    ghostCaption_ = ghost ? caption : QString();
    surface_->update();
}

QImage SceneView::renderImage(QSize size, bool withHud) const {
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    if (image.isNull()) return image;
    ViewTransform v = view();
    const double scale = std::min(size.width() / std::max(1.0, v.widgetSize().width()),
                                  size.height() / std::max(1.0, v.widgetSize().height()));
    v.setPixelsPerMetre(v.pixelsPerMetre() * scale);
    v.setWidgetSize(size);
    RenderOptions options = options_;
    // Thicker in a larger picture so it looks like the screen; never thinner than on screen.
    options.lineWidthScale *= std::max(1.0, scale);
    options.fontScale *= std::max(1.0, scale);
    QPainter painter(&image);
    if (world_)
        SceneRenderer::paint(painter, v, size, *world_, options, &trails_);
    else
        SceneRenderer::paintEmpty(painter, v, size, options);
    if (world_ && ghost_) {
        drawGhost(painter, v, size, *ghost_, options);
        drawGhostCaption(painter, size, ghostCaption_, options);
    }
    MeasureRenderer::paint(painter, v, size, measurements_, options);
    if (withHud) drawHud(painter, hudText_, options);
    return image;
}

PickResult SceneView::pick(QPointF widgetPoint, double tolerancePixels) const {
    return world_ ? SceneRenderer::pick(*world_, view(), widgetPoint, tolerancePixels)
                  : PickResult{};
}

// ---- input ------------------------------------------------------------------------------------

void SceneView::startPan(Qt::MouseButton button, QPointF position) {
    panButton_ = button;
    lastPanPosition_ = position;
    panTravel_ = 0.0;
    updatePanCursor();
}

void SceneView::endPan() {
    panButton_ = Qt::NoButton;
    updatePanCursor();
}

// A closed hand while dragging, an open one while Space is held, and otherwise whatever cursor
// was set before (a tool's crosshair survives a pan).
void SceneView::updatePanCursor() {
    const bool panning = panButton_ != Qt::NoButton;
    if (panning || spaceHeld_) {
        if (!cursorSaved_) {
            hadCursor_ = testAttribute(Qt::WA_SetCursor);
            savedCursor_ = cursor();
            cursorSaved_ = true;
        }
        setCursor(panning ? Qt::ClosedHandCursor : Qt::OpenHandCursor);
    } else if (cursorSaved_) {
        if (hadCursor_)
            setCursor(savedCursor_);
        else
            unsetCursor();
        cursorSaved_ = false;
    }
}

void SceneView::mousePressEvent(QMouseEvent* event) {
    event->accept();
    if (panButton_ != Qt::NoButton) return;  // a second button during a pan does nothing
    const Qt::MouseButton button = event->button();
    if (button == Qt::MiddleButton || button == Qt::RightButton ||
        (button == Qt::LeftButton && spaceHeld_)) {
        startPan(button, event->position());
        return;
    }
    if (button == Qt::LeftButton)
        emit worldMousePressed(toWorld(event->position()), button, event->modifiers());
}

void SceneView::mouseMoveEvent(QMouseEvent* event) {
    event->accept();
    if (panButton_ != Qt::NoButton) {
        const QPointF delta = event->position() - lastPanPosition_;
        lastPanPosition_ = event->position();
        panTravel_ += std::hypot(delta.x(), delta.y());
        ViewTransform v = view();
        v.panByPixels(delta);
        setView(v);
        return;
    }
    emit worldMouseMoved(toWorld(event->position()), event->buttons(), event->modifiers());
}

void SceneView::mouseReleaseEvent(QMouseEvent* event) {
    event->accept();
    if (panButton_ != Qt::NoButton) {
        if (event->button() != panButton_) return;
        const bool click = panButton_ == Qt::RightButton && panTravel_ < 4.0;
        endPan();
        if (click)
            emit worldContextMenuRequested(toWorld(event->position()),
                                           event->globalPosition().toPoint());
        return;
    }
    if (event->button() == Qt::LeftButton)
        emit worldMouseReleased(toWorld(event->position()), event->button(), event->modifiers());
}

void SceneView::mouseDoubleClickEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton || spaceHeld_) {
        mousePressEvent(event);  // the second press of a pan button still pans
        return;
    }
    event->accept();
    emit worldMouseDoubleClicked(toWorld(event->position()), event->button(), event->modifiers());
}

void SceneView::wheelEvent(QWheelEvent* event) {
    const int steps = event->angleDelta().y();
    if (steps == 0) {
        event->ignore();
        return;
    }
    event->accept();
    ViewTransform v = view();
    v.zoomAround(event->position(), std::pow(1.2, steps / 120.0));  // one notch: 20 %
    setView(v);
}

void SceneView::keyPressEvent(QKeyEvent* event) {
    if (handleKeyboardEditing(event)) return;
    switch (event->key()) {
        case Qt::Key_Plus:
        case Qt::Key_Equal:  // + without Shift on most layouts
            zoomBy(1.25);
            break;
        case Qt::Key_Minus:
            zoomBy(0.8);
            break;
        case Qt::Key_Space:
            if (!event->isAutoRepeat()) {
                spaceHeld_ = true;
                updatePanCursor();
            }
            break;
        default:
            QWidget::keyPressEvent(event);
            return;
    }
    event->accept();
}

void SceneView::keyReleaseEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Space && !event->isAutoRepeat()) {
        spaceHeld_ = false;
        updatePanCursor();
        event->accept();
        return;
    }
    QWidget::keyReleaseEvent(event);
}

void SceneView::focusOutEvent(QFocusEvent* event) {
    // The Space release may go to another widget: do not stay in pan mode.
    spaceHeld_ = false;
    updatePanCursor();
    QWidget::focusOutEvent(event);
}

void SceneView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    syncView();
    emit viewChanged();
}

}  // namespace phasebox::ui
