#include "ui/canvas/ViewTransform.h"

#include <algorithm>
#include <cmath>

namespace phasebox::ui {

ViewTransform::ViewTransform(QPointF centreWorld, double pixelsPerMetre, QSizeF widgetSize)
    : centre_(centreWorld), size_(widgetSize) {
    setPixelsPerMetre(pixelsPerMetre);
}

void ViewTransform::setPixelsPerMetre(double pixelsPerMetre) {
    if (!std::isfinite(pixelsPerMetre)) return;
    scale_ = std::clamp(pixelsPerMetre, kMinPixelsPerMetre, kMaxPixelsPerMetre);
}

QTransform ViewTransform::worldToScreen() const {
    const QPointF origin = toScreen(0.0, 0.0);
    return QTransform(scale_, 0.0, 0.0, -scale_, origin.x(), origin.y());
}

QRectF ViewTransform::visibleWorldRect() const {
    const QPointF a = toWorld({0.0, size_.height()});  // bottom-left on screen
    const QPointF b = toWorld({size_.width(), 0.0});   // top-right on screen
    return QRectF(a, b).normalized();
}

void ViewTransform::zoomAround(QPointF screenPoint, double factor) {
    if (!(factor > 0.0) || !std::isfinite(factor)) return;
    const QPointF anchor = toWorld(screenPoint);
    setPixelsPerMetre(scale_ * factor);
    // Solve toScreen(anchor) == screenPoint for the centre with the new (possibly clamped)
    // scale, rather than scaling the old offset: clamping must not make the point drift.
    centre_ = {anchor.x() - (screenPoint.x() - 0.5 * size_.width()) / scale_,
               anchor.y() + (screenPoint.y() - 0.5 * size_.height()) / scale_};
}

void ViewTransform::panByPixels(QPointF delta) {
    centre_ -= QPointF(delta.x() / scale_, -delta.y() / scale_);
}

void ViewTransform::fit(const QRectF& worldRect, QSizeF widgetSize, double marginPixels) {
    size_ = widgetSize;
    QRectF r = worldRect.normalized();
    if (r.width() <= 0.0 && r.height() <= 0.0) r.adjust(-1.0, -1.0, 1.0, 1.0);
    const double freeW = std::max(1.0, widgetSize.width() - 2.0 * marginPixels);
    const double freeH = std::max(1.0, widgetSize.height() - 2.0 * marginPixels);
    // A zero extent in one direction (a row of boxes on the ground) constrains nothing.
    const double sx = r.width() > 0.0 ? freeW / r.width() : kMaxPixelsPerMetre;
    const double sy = r.height() > 0.0 ? freeH / r.height() : kMaxPixelsPerMetre;
    setPixelsPerMetre(std::min(sx, sy));
    centre_ = r.center();
}

bool ViewTransform::keepInView(const QRectF& worldRect, double marginPixels) {
    const QRectF r = worldRect.normalized();
    const double freeW = std::max(1.0, size_.width() - 2.0 * marginPixels);
    const double freeH = std::max(1.0, size_.height() - 2.0 * marginPixels);
    bool changed = false;
    // Too big for the free area at this scale: zoom out about its centre until it fits.
    const double needed = std::min(r.width() > 0.0 ? freeW / r.width() : kMaxPixelsPerMetre,
                                   r.height() > 0.0 ? freeH / r.height() : kMaxPixelsPerMetre);
    if (needed < scale_) {
        setPixelsPerMetre(needed);
        changed = true;
    }
    // Then the least pan that brings it inside the free area, axis by axis.
    const double halfW = 0.5 * freeW / scale_, halfH = 0.5 * freeH / scale_;
    const auto shift = [](double lo, double hi, double centre, double half) {
        if (lo < centre - half) return lo - (centre - half);
        if (hi > centre + half) return hi - (centre + half);
        return 0.0;
    };
    const double dx = shift(r.left(), r.right(), centre_.x(), halfW);
    const double dy = shift(r.top(), r.bottom(), centre_.y(), halfH);
    if (dx != 0.0 || dy != 0.0) {
        centre_ += QPointF(dx, dy);
        changed = true;
    }
    return changed;
}

double ViewTransform::niceLength(double minPixels) const {
    const double minMetres = std::max(minPixels, 1e-9) / scale_;
    double decade = std::pow(10.0, std::floor(std::log10(minMetres)));
    for (int guard = 0; guard < 4; ++guard, decade *= 10.0)
        for (const double m : {1.0, 2.0, 5.0})
            // The relative slack absorbs log10's rounding when minMetres is itself nice.
            if (m * decade >= minMetres * (1.0 - 1e-12)) return m * decade;
    return 10.0 * decade;
}

}  // namespace phasebox::ui
