#include "ui/canvas/GhostOverlay.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace phasebox::ui {

RenderOptions ghostOptions(const RenderOptions& live) {
    RenderOptions o;
    o.grid = o.scaleBar = o.trails = o.velocityArrows = o.forceArrows = o.labels = false;
    o.lineWidthScale = live.lineWidthScale;
    o.fontScale = live.fontScale;
    o.spriteThreshold = live.spriteThreshold;
    o.background = Qt::transparent;
    // Dark on a light canvas, light on a dark one (high contrast), always see-through.
    const bool dark = live.background.lightnessF() < 0.5;
    const QColor body = dark ? QColor(0xe0, 0xe0, 0xe0, 0x70) : QColor(0x30, 0x30, 0x40, 0x58);
    const QColor line = dark ? QColor(0xe0, 0xe0, 0xe0, 0xa0) : QColor(0x30, 0x30, 0x40, 0x90);
    // Bodies asleep half as opaque: dimmed, as the live canvas dims its sleepers.
    QColor asleep = body;
    asleep.setAlpha(body.alpha() / 2);
    SceneColors& c = o.colors;
    c.particle = c.dynamicBox = body;
    c.sleepingParticle = c.sleepingBox = asleep;
    c.springCompressed = c.springRest = c.springStretched = c.cloth = c.joint = c.rope = line;
    c.track = c.anchor = c.pinnedParticle = c.staticBox = c.plane = c.planeBorder = Qt::transparent;
    c.text = line;
    return o;
}

void drawGhost(QPainter& painter, const ViewTransform& view, QSize viewportPixels,
               const World& ghost, const RenderOptions& live) {
    SceneRenderer::paint(painter, view, viewportPixels, ghost, ghostOptions(live));
}

void drawGhostCaption(QPainter& painter, QSize viewportPixels, const QString& caption,
                      const RenderOptions& live) {
    if (caption.isEmpty()) return;
    painter.save();
    QFont font = painter.font();
    font.setPixelSize(std::max(6, static_cast<int>(std::lround(13.0 * live.fontScale))));
    painter.setFont(font);
    const QSizeF text =
        QFontMetricsF(font).boundingRect(QRectF(0, 0, 10000, 10000), 0, caption).size();
    const QSizeF size = text + QSizeF(12.0, 6.0);
    // The bottom right corner: the time line and the exact solution's label hold the top, the
    // scale bar the bottom left.
    const QRectF box(QPointF(viewportPixels.width() - size.width() - 8.0,
                             viewportPixels.height() - size.height() - 8.0),
                     size);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(live.colors.text, 1.0, Qt::DashLine));
    painter.setBrush(live.colors.backdrop);
    painter.drawRoundedRect(box, 4.0, 4.0);
    painter.setPen(live.colors.text);
    painter.drawText(box, Qt::AlignCenter, caption);
    painter.restore();
}

}  // namespace phasebox::ui
