#include "ui/canvas/MeasureOverlay.h"
#include "ui/panels/ShownNumber.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace phasebox::ui {

namespace {
// The overlay's words in the app's language (pictures the command line draws stay English).
QString overlayText(const char* english) {
    return QCoreApplication::translate("MeasureOverlay", english);
}

const QColor kRulerColor{0x00, 0x6d, 0x77};
const QColor kMomentumColor{0xcc, 0x79, 0xa7};  // Okabe–Ito reddish purple, dashed

struct Painter {
    QPainter& p;
    const ViewTransform& view;
    const RenderOptions& o;
    double lw;
    // The labels drawn so far: a label that would cover one moves down past it.
    mutable QVector<QRectF> placed;

    QPen pen(const QColor& c, double width, Qt::PenStyle style = Qt::SolidLine) const {
        QPen pen(c, width * lw, style);
        pen.setCapStyle(Qt::RoundCap);
        pen.setJoinStyle(Qt::RoundJoin);
        return pen;
    }
    QFont font(double pixels) const {
        QFont f = p.font();
        f.setPixelSize(std::max(6, static_cast<int>(std::lround(pixels * o.fontScale))));
        return f;
    }
    // Text on a white backdrop; `at` is its centre, or its left end when leftAligned.
    void label(QPointF at, const QString& text, const QColor& colour, bool leftAligned = false,
               bool bold = false) const {
        QFont f = font(12.0);
        f.setBold(bold);
        p.setFont(f);
        const QSizeF size =
            QFontMetricsF(f).boundingRect(QRectF(0, 0, 4000, 4000), 0, text).size() +
            QSizeF(8.0, 4.0);
        const QPointF topLeft = leftAligned ? QPointF(at.x(), at.y() - 0.5 * size.height())
                                            : at - QPointF(0.5 * size.width(), 0.5 * size.height());
        QRectF box(topLeft, size);
        for (int tries = 0; tries < 8; ++tries) {
            const auto covered = std::find_if(placed.begin(), placed.end(),
                                              [&](const QRectF& r) { return r.intersects(box); });
            if (covered == placed.end()) break;
            box.moveTop(covered->bottom() + 1.0);
        }
        placed.push_back(box);
        p.setPen(Qt::NoPen);
        p.setBrush(o.colors.backdrop);
        p.drawRoundedRect(box, 3.0, 3.0);
        p.setPen(colour);
        p.drawText(box, Qt::AlignCenter, text);
    }
    void ring(QPointF at, const QColor& colour) const {
        p.setBrush(Qt::NoBrush);
        p.setPen(pen(colour, 1.5));
        const double r = MeasureRenderer::kEndRingPixels * lw;
        p.drawEllipse(at, r, r);
    }
    // A filled arrow head at `to`, pointing along from → to.
    void arrow(QPointF from, QPointF to, const QColor& colour, double width,
               Qt::PenStyle style = Qt::SolidLine) const {
        const QPointF d = to - from;
        const double length = std::hypot(d.x(), d.y());
        if (length < 1.0) return;
        const QPointF u = d / length, n(-u.y(), u.x());
        const double h = std::min(11.0 * lw, 0.45 * length);
        p.setPen(pen(colour, width, style));
        p.drawLine(from, to - u * (0.6 * h));
        QPolygonF head;
        head << to << to - u * h + n * (0.4 * h) << to - u * h - n * (0.4 * h);
        p.setPen(Qt::NoPen);
        p.setBrush(colour);
        p.drawPolygon(head);
    }
};

QPointF unitNormal(QPointF d) {
    const double length = std::hypot(d.x(), d.y());
    return length > 0.0 ? QPointF(-d.y(), d.x()) / length : QPointF(0.0, -1.0);
}

void drawRuler(const Painter& g, const MeasureOverlay::Ruler& r) {
    const QPointF a = g.view.toScreen(r.a), b = g.view.toScreen(r.b);
    const QPointF d = b - a;
    const double length = std::hypot(d.x(), d.y());
    const QPointF n = unitNormal(d);
    if (r.selected) {
        g.p.setPen(g.pen(g.o.colors.selection, 6.0));
        g.p.drawLine(a, b);
    }
    g.p.setPen(g.pen(kRulerColor, 2.0, r.pending ? Qt::DashLine : Qt::SolidLine));
    g.p.drawLine(a, b);
    // End marks, and a tick every {1, 2, 5}·10^k metres at least 24 px apart, like a ruler.
    g.p.setPen(g.pen(kRulerColor, 2.0));
    for (const QPointF& end : {a, b}) g.p.drawLine(end - 8.0 * g.lw * n, end + 8.0 * g.lw * n);
    if (length > 0.0) {
        const double spacing = g.view.niceLength(24.0 * g.lw);
        const double metres = g.view.toMetres(length);
        g.p.setPen(g.pen(kRulerColor, 1.0));
        for (int k = 1; k * spacing < metres && k < 500; ++k) {
            const QPointF t = a + d * (k * spacing / metres);
            g.p.drawLine(t, t + 4.0 * g.lw * n);
        }
    }
    if (r.attachedA) g.ring(a, kRulerColor);
    if (r.attachedB) g.ring(b, kRulerColor);
    if (!r.label.isEmpty()) {
        // Beside the middle, on the side away from the ticks.
        g.label(0.5 * (a + b) - 18.0 * g.lw * n, r.label, g.o.colors.text, false, true);
    }
}

void drawProtractor(const Painter& g, const MeasureOverlay::Protractor& r) {
    const QPointF v = g.view.toScreen(r.vertex), a = g.view.toScreen(r.armA);
    const Qt::PenStyle style = r.pending ? Qt::DashLine : Qt::SolidLine;
    QVector<QPointF> arms{a};
    if (r.armB) arms.push_back(g.view.toScreen(*r.armB));
    for (const QPointF& arm : arms) {
        if (r.selected) {
            g.p.setPen(g.pen(g.o.colors.selection, 6.0));
            g.p.drawLine(v, arm);
        }
        g.p.setPen(g.pen(kRulerColor, 2.0, style));
        g.p.drawLine(v, arm);
    }
    // attached[] is in ∠ABC's order: the first arm, the vertex, the second arm.
    if (r.attached[0]) g.ring(a, kRulerColor);
    if (r.attached[1]) g.ring(v, kRulerColor);
    if (r.armB && r.attached[2]) g.ring(arms[1], kRulerColor);
    if (!r.armB) return;
    // The arc from the first arm to the second the shorter way (the sign of angle(A,B,C)), in
    // world angles: Qt's arc angles are counter-clockwise on screen, as world angles are.
    const QPointF wa = r.armA - r.vertex;
    const double start = std::atan2(wa.y(), wa.x());
    const double span = signedAngle({r.armA.x(), r.armA.y()}, {r.vertex.x(), r.vertex.y()},
                                    {r.armB->x(), r.armB->y()});
    const double shortest = std::min(std::hypot(a.x() - v.x(), a.y() - v.y()),
                                     std::hypot(arms[1].x() - v.x(), arms[1].y() - v.y()));
    const double radius = std::clamp(0.4 * shortest, 12.0 * g.lw, 40.0 * g.lw);
    const QRectF circle(v - QPointF(radius, radius), QSizeF(2.0 * radius, 2.0 * radius));
    const double toQt = 16.0 * 180.0 / std::numbers::pi;
    g.p.setBrush(QColor(kRulerColor.red(), kRulerColor.green(), kRulerColor.blue(), 40));
    g.p.setPen(g.pen(kRulerColor, 1.5));
    g.p.drawPie(circle, static_cast<int>(std::lround(start * toQt)),
                static_cast<int>(std::lround(span * toQt)));
    if (!r.label.isEmpty()) {
        const double middle = start + 0.5 * span;
        const double out = radius + 26.0 * g.lw;
        g.label(v + QPointF(std::cos(middle), -std::sin(middle)) * out, r.label, g.o.colors.text,
                false, true);
    }
}

QString forceName(const BodyForce& f) {
    switch (f.source) {
        case BodyForce::Source::Effect: {
            // The effects' names as lupdate sees them; another name is shown as it is.
            [[maybe_unused]] static const char* const kEffectNames[] = {
                QT_TRANSLATE_NOOP("MeasureOverlay", "gravity"),
                QT_TRANSLATE_NOOP("MeasureOverlay", "drag"),
                QT_TRANSLATE_NOOP("MeasureOverlay", "newtonian gravity"),
                QT_TRANSLATE_NOOP("MeasureOverlay", "buoyancy"),
                QT_TRANSLATE_NOOP("MeasureOverlay", "wind"),
                QT_TRANSLATE_NOOP("MeasureOverlay", "flocking"),
                QT_TRANSLATE_NOOP("MeasureOverlay", "coulomb"),
                QT_TRANSLATE_NOOP("MeasureOverlay", "penalty contacts")};
            const QByteArray name =
                QString::fromStdString(f.name).replace(QLatin1Char('_'), QLatin1Char(' ')).toUtf8();
            return overlayText(name.constData());
        }
        case BodyForce::Source::Spring:
            return overlayText(QT_TRANSLATE_NOOP("MeasureOverlay", "spring %1"))
                .arg(QString::fromStdString(f.name));
        case BodyForce::Source::Contact:
            return overlayText(QT_TRANSLATE_NOOP("MeasureOverlay", "contact"));
        case BodyForce::Source::Joint:
            return overlayText(QT_TRANSLATE_NOOP("MeasureOverlay", "joint %1"))
                .arg(QString::fromStdString(f.name));
    }
    return {};
}

void drawCentreOfMass(const Painter& g, QPointF world) {
    const QPointF c = g.view.toScreen(world);
    const double r = 7.0 * g.lw;
    const QRectF box(c - QPointF(r, r), QSizeF(2.0 * r, 2.0 * r));
    g.p.setPen(g.pen(g.o.colors.text, 1.5));
    g.p.setBrush(Qt::white);
    g.p.drawEllipse(box);
    g.p.setPen(Qt::NoPen);
    g.p.setBrush(g.o.colors.text);
    g.p.drawPie(box, 0, 90 * 16);
    g.p.drawPie(box, 180 * 16, 90 * 16);
    g.label(c + QPointF(r + 4.0 * g.lw, 0.0), QStringLiteral("CM"), g.o.colors.text, true);
}

void drawFreeBody(const Painter& g, const MeasureOverlay& o, QSize viewport) {
    QStringList legend;
    if (o.freeBody) {
        const FreeBody& body = *o.freeBody;
        double largest = 0.0;
        for (const BodyForce& f : body.forces) largest = std::max(largest, f.force.norm());
        const double newtonsPerPixel =
            MeasureRenderer::arrowScale(largest, MeasureRenderer::kLongestForcePixels);
        // Below a nanometre per second the momentum is rounding, not motion: no arrow.
        const Vec2 momentum =
            body.momentum.norm() > 1e-9 * body.mass ? body.momentum : Vec2(Vec2::Zero());
        const double momentumPerPixel =
            MeasureRenderer::arrowScale(momentum.norm(), MeasureRenderer::kLongestMomentumPixels);
        const QPointF c = g.view.toScreen(body.position.x(), body.position.y());
        const auto tip = [&](const Vec2& v, double perPixel) {
            return c + QPointF(v.x(), -v.y()) / perPixel;
        };
        for (const BodyForce& f : body.forces)
            g.arrow(c, tip(f.force, newtonsPerPixel), MeasureRenderer::forceColor(f.source), 2.5);
        g.arrow(c, tip(momentum, momentumPerPixel), kMomentumColor, 2.0, Qt::DashLine);
        // Labels after the arrows, so no arrow crosses a label.
        const auto place = [&](const Vec2& v, double perPixel, const QString& text,
                               const QColor& colour) {
            const double length = v.norm() / perPixel;
            if (length < 1.0) return;
            const QPointF u = QPointF(v.x(), -v.y()) / v.norm();
            g.label(tip(v, perPixel) + u * (10.0 * g.lw), text, colour, u.x() > 0.3);
        };
        for (const BodyForce& f : body.forces)
            place(f.force, newtonsPerPixel,
                  QStringLiteral("%1 %2 N").arg(forceName(f),
                                                MeasureRenderer::number(f.force.norm())),
                  MeasureRenderer::forceColor(f.source));
        place(momentum, momentumPerPixel,
              QStringLiteral("p %1 kg·m/s").arg(MeasureRenderer::number(momentum.norm())),
              kMomentumColor);
        legend << overlayText(QT_TRANSLATE_NOOP("MeasureOverlay", "Free body: %1, m = %2 kg"))
                      .arg(o.freeBodyName, MeasureRenderer::number(body.mass))
               << overlayText(QT_TRANSLATE_NOOP("MeasureOverlay", "forces: 1 px = %1 N, net %2 N"))
                      .arg(shownNumber(newtonsPerPixel, 'g', 3))
                      .arg(MeasureRenderer::number(body.net().norm()))
               << (momentum == Vec2::Zero()
                       ? overlayText(QT_TRANSLATE_NOOP("MeasureOverlay", "momentum 0"))
                       : overlayText(
                             QT_TRANSLATE_NOOP("MeasureOverlay", "momentum: 1 px = %1 kg·m/s"))
                             .arg(shownNumber(momentumPerPixel, 'g', 3)));
    } else {
        legend << overlayText(
            QT_TRANSLATE_NOOP("MeasureOverlay", "Free body: select a moving body"));
    }
    if (o.centreOfMass) {
        drawCentreOfMass(g, *o.centreOfMass);
        legend << overlayText(
                      QT_TRANSLATE_NOOP("MeasureOverlay", "system: p = (%1, %2) kg·m/s, CM ◑"))
                      .arg(MeasureRenderer::number(o.systemMomentum.x()),
                           MeasureRenderer::number(o.systemMomentum.y()));
    }
    // The legend in the bottom right corner: the time is top left, the scale bar bottom left.
    const QString text = legend.join(QLatin1Char('\n'));
    const QFont f = g.font(12.0);
    g.p.setFont(f);
    const QSizeF size =
        QFontMetricsF(f).boundingRect(QRectF(0, 0, 4000, 4000), 0, text).size() + QSizeF(12, 8);
    const QRectF box(QPointF(std::max(8.0, viewport.width() - size.width() - 8.0),
                             viewport.height() - size.height() - 8.0),
                     size);
    g.p.setPen(Qt::NoPen);
    g.p.setBrush(g.o.colors.backdrop);
    g.p.drawRoundedRect(box, 4.0, 4.0);
    g.p.setPen(g.o.colors.text);
    g.p.drawText(box.adjusted(6, 4, -6, -4), Qt::AlignLeft | Qt::AlignVCenter, text);
}

}  // namespace

double MeasureRenderer::arrowScale(double largest, double longestPixels) {
    if (!(largest > 0.0) || !std::isfinite(largest) || !(longestPixels > 0.0)) return 1.0;
    const double raw = largest / longestPixels;
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double m : {1.0, 2.0, 5.0, 10.0})
        if (m * decade >= raw * (1.0 - 1e-12)) return m * decade;
    return 10.0 * decade;
}

QString MeasureRenderer::number(double value) {
    const double a = std::abs(value);
    if (a == 0.0) return QStringLiteral("0");
    if (a >= 1000.0 || a < 0.01) return shownNumber(value, 'g', 3);
    return shownNumber(value, 'f', a >= 100.0 ? 0 : a >= 10.0 ? 1 : 2);
}

QColor MeasureRenderer::forceColor(BodyForce::Source source) {
    switch (source) {
        case BodyForce::Source::Effect:
            return {0x7b, 0x3f, 0xb5};
        case BodyForce::Source::Spring:
            return {0xd5, 0x5e, 0x00};  // Okabe–Ito vermillion
        case BodyForce::Source::Contact:
            return {0x00, 0x72, 0xb2};  // blue
        case BodyForce::Source::Joint:
            return {0x00, 0x9e, 0x73};  // bluish green
    }
    return Qt::black;
}

void MeasureRenderer::paint(QPainter& painter, const ViewTransform& view, QSize viewportPixels,
                            const MeasureOverlay& overlay, const RenderOptions& options) {
    if (overlay.isEmpty()) return;
    ViewTransform v = view;
    v.setWidgetSize(viewportPixels);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    const Painter g{painter, v, options, std::max(0.1, options.lineWidthScale), {}};
    if (overlay.freeBodyShown) drawFreeBody(g, overlay, viewportPixels);
    for (const MeasureOverlay::Ruler& r : overlay.rulers) drawRuler(g, r);
    for (const MeasureOverlay::Protractor& r : overlay.protractors) drawProtractor(g, r);
    painter.restore();
}

}  // namespace phasebox::ui
