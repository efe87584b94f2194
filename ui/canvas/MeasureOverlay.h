#pragma once
// The canvas instruments drawn over the scene: rulers, protractors and the free-body view of
// one body. The app decides what they measure and attach to (MeasureTools); this only draws,
// with screen-constant line widths and type like the rest of the renderer, so a ruler reads
// the same at any zoom.
//
// Free-body arrows all start at the body's centre (the free-body convention), one per source,
// each labelled with its magnitude. Their scale is chosen from the largest force shown: the
// smallest {1, 2, 5}·10^k newtons per pixel at which it is at most kLongestForcePixels long,
// so lengths compare within one picture and change scale only in those steps; the legend says
// the scale. The momentum arrow has its own scale by the same rule (kLongestMomentumPixels;
// none below 1 nm/s, which is rounding, not motion).
// The system's centre of mass is a quartered disc.

#include "physics/world/FreeBody.h"
#include "ui/canvas/SceneRenderer.h"
#include "ui/canvas/ViewTransform.h"

#include <QPointF>
#include <QString>
#include <QVector>

#include <optional>

QT_BEGIN_NAMESPACE
class QPainter;
QT_END_NAMESPACE

namespace phasebox::ui {

struct MeasureOverlay {
    // World points; an attached end is drawn with a ring (it follows its object).
    struct Ruler {
        QPointF a, b;
        bool attachedA = false, attachedB = false;
        QString label;  // e.g. "5.000 m  (dx 3.000, dy 4.000)"
        bool selected = false;
        bool pending = false;  // being drawn: dashed
    };
    // The angle at vertex from armA to armB (∠ABC: A = armA, B = vertex, C = armB); without
    // armB (still being drawn) only the first arm and the vertex.
    struct Protractor {
        QPointF armA, vertex;
        std::optional<QPointF> armB;
        bool attached[3] = {false, false, false};  // armA, vertex, armB: ∠ABC's order
        QString label;
        bool selected = false;
        bool pending = false;
    };
    QVector<Ruler> rulers;
    QVector<Protractor> protractors;

    // The free-body view: the body (nullopt: nothing selected that moves), with its name, and
    // the system's centre of mass (nullopt: nothing dynamic).
    std::optional<FreeBody> freeBody;
    QString freeBodyName;
    std::optional<QPointF> centreOfMass;
    QPointF systemMomentum;  // Σ m·v of the dynamic objects (kg·m/s)
    bool freeBodyShown = false;

    bool isEmpty() const { return rulers.isEmpty() && protractors.isEmpty() && !freeBodyShown; }
};

class MeasureRenderer {
public:
    static constexpr double kLongestForcePixels = 120.0;
    static constexpr double kLongestMomentumPixels = 90.0;
    static constexpr double kEndRingPixels = 6.0;

    static void paint(QPainter& painter, const ViewTransform& view, QSize viewportPixels,
                      const MeasureOverlay& overlay, const RenderOptions& options);

    // Units per pixel for arrows whose largest is `largest` units long: the smallest {1, 2,
    // 5}·10^k with largest / scale ≤ longestPixels (1 for nothing to draw).
    static double arrowScale(double largest, double longestPixels);
    // A force, momentum or length with a few significant digits: "9.81", "0.0123", "1250".
    static QString number(double value);
    // The colour of a free-body arrow by source.
    static QColor forceColor(BodyForce::Source source);
};

}  // namespace phasebox::ui
