#include "ui/canvas/ReferenceOverlay.h"

#include "ui/canvas/SceneRenderer.h"
#include "ui/canvas/ViewTransform.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <utility>

namespace phasebox::ui {

void drawReferenceOverlay(QPainter& p, const ViewTransform& view, const ReferenceOverlay& overlay,
                          const RenderOptions& options) {
    if (overlay.isEmpty()) return;
    const double lw = options.lineWidthScale;
    // A colour no object has: the reference must never be taken for a body.
    const QColor colour(0xd0, 0x60, 0x10);
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setBrush(Qt::NoBrush);
    QPen path(colour, 1.0 * lw, Qt::DashLine);
    path.setCosmetic(true);
    p.setPen(path);
    for (const QPolygonF& world : overlay.paths) {
        QPolygonF screen;
        screen.reserve(world.size());
        for (const QPointF& q : world) screen.append(view.toScreen(q));
        p.drawPolyline(screen);
    }
    QPen ghost(colour, 2.0 * lw, Qt::DashLine);
    p.setPen(ghost);
    for (const ReferenceOverlay::Ghost& g : overlay.ghosts) {
        if (!g.size.isEmpty()) {
            const double c = std::cos(g.angle), s = std::sin(g.angle);
            const double hw = 0.5 * g.size.width(), hh = 0.5 * g.size.height();
            QPolygonF outline;
            for (const auto& [x, y] : {std::pair{-hw, -hh}, {hw, -hh}, {hw, hh}, {-hw, hh}})
                outline.append(view.toScreen(g.centre + QPointF(c * x - s * y, s * x + c * y)));
            p.drawPolygon(outline);
            continue;
        }
        const double r =
            std::max(view.toPixels(g.radius), SceneRenderer::kMinParticlePixels + 3.0 * lw);
        p.drawEllipse(view.toScreen(g.centre), r, r);
    }
    if (!overlay.label.isEmpty()) {
        // Top right, clear of the HUD (top left) and the scale bar (bottom left); cut with "…"
        // rather than run off a narrow canvas.
        QFont font = p.font();
        font.setPixelSize(std::max(6, static_cast<int>(std::lround(12.0 * options.fontScale))));
        p.setFont(font);
        const QRectF viewport = p.viewport();
        const QFontMetricsF metrics(font);
        const QString text =
            metrics.elidedText(overlay.label, Qt::ElideRight, 0.9 * viewport.width());
        // Below the HUD's line, which a narrow canvas gives its whole width.
        const double top = 8.0 + 2.0 * metrics.height() + 4.0;
        const QRectF box(viewport.left(), viewport.top() + top, viewport.width() - 10.0,
                         viewport.height() - top);
        p.setPen(colour.darker(130));
        p.drawText(box, Qt::AlignRight | Qt::AlignTop, text);
    }
    p.restore();
}

}  // namespace phasebox::ui
