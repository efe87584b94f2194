#pragma once
// The map between the world (metres, y up) and a widget (pixels, y down): a world point at
// the widget's centre and a scale. A value type, so a view can be saved, compared, animated
// or handed to the renderer for an export without touching the widget it came from.

#include <QPointF>
#include <QRectF>
#include <QSizeF>
#include <QTransform>

namespace phasebox::ui {

class ViewTransform {
public:
    // Far beyond any useful zoom, but keeps 1/scale and the grid's logarithm finite.
    static constexpr double kMinPixelsPerMetre = 1e-4;
    static constexpr double kMaxPixelsPerMetre = 1e7;

    ViewTransform() = default;
    ViewTransform(QPointF centreWorld, double pixelsPerMetre, QSizeF widgetSize);

    QPointF centre() const { return centre_; }
    void setCentre(QPointF world) { centre_ = world; }
    double pixelsPerMetre() const { return scale_; }
    void setPixelsPerMetre(double pixelsPerMetre);
    QSizeF widgetSize() const { return size_; }
    // The centre stays at the widget's centre: resizing shows more or less around it.
    void setWidgetSize(QSizeF size) { size_ = size; }

    QPointF toScreen(double x, double y) const {
        return {0.5 * size_.width() + (x - centre_.x()) * scale_,
                0.5 * size_.height() - (y - centre_.y()) * scale_};
    }
    QPointF toScreen(QPointF world) const { return toScreen(world.x(), world.y()); }
    QPointF toWorld(QPointF screen) const {
        return {centre_.x() + (screen.x() - 0.5 * size_.width()) / scale_,
                centre_.y() - (screen.y() - 0.5 * size_.height()) / scale_};
    }
    double toPixels(double metres) const { return metres * scale_; }
    double toMetres(double pixels) const { return pixels / scale_; }
    // The same map as a QTransform (y flipped), for drawing in world units.
    QTransform worldToScreen() const;

    // The world area the widget shows: left = min x, top = min y (QRectF's "top" is the
    // smaller y, which is the bottom of the screen here).
    QRectF visibleWorldRect() const;

    // Multiplies the scale by factor while the world point under screenPoint stays there.
    void zoomAround(QPointF screenPoint, double factor);
    // Moves the picture by a screen delta (a drag to the right moves the world right).
    void panByPixels(QPointF delta);
    // Frames worldRect (left = min x, top = min y) in a widget of this size with at least
    // marginPixels free on every side. An empty rect is framed as a point with 1 m around it.
    void fit(const QRectF& worldRect, QSizeF widgetSize, double marginPixels = 24.0);
    // Follow mode: keeps worldRect (left = min x, top = min y) inside the widget with
    // marginPixels free on every side, moving as little as it can: nothing while it is inside,
    // a pan while it fits at this scale, a zoom out (never in) when it does not. Returns
    // whether the view changed.
    bool keepInView(const QRectF& worldRect, double marginPixels);

    // The smallest length of the form {1, 2, 5}·10^k metres that is at least minPixels long
    // on screen: the grid's spacing (so lines never crowd) and the scale bar's length.
    double niceLength(double minPixels) const;

    bool operator==(const ViewTransform&) const = default;

private:
    QPointF centre_{0.0, 0.0};
    double scale_ = 50.0;  // pixels per metre
    QSizeF size_{640.0, 480.0};
};

}  // namespace phasebox::ui
