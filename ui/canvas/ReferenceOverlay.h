#pragma once
// The exact solution drawn beside the simulation: where each body would be now if the scene's
// closed form held (a dashed ghost), and the path the closed form takes (a thin dashed line),
// so that a lesson's "next to its exact solution" is something to see, not only to read.

#include <QList>
#include <QPointF>
#include <QPolygonF>
#include <QSizeF>
#include <QString>

QT_BEGIN_NAMESPACE
class QPainter;
QT_END_NAMESPACE

namespace phasebox::ui {

struct RenderOptions;
class ViewTransform;

struct ReferenceOverlay {
    struct Ghost {
        QPointF centre;       // world m
        double radius = 0.0;  // m; drawn at least a few pixels wide
        // A rectangle's width and height (m) and angle (rad), drawn as its outline; a circle's
        // ghost has none.
        QSizeF size;
        double angle = 0.0;
    };
    QList<QPolygonF> paths;  // world m
    QList<Ghost> ghosts;
    QString label;  // e.g. "dashed: exact solution (harmonic oscillator)"

    bool isEmpty() const { return paths.isEmpty() && ghosts.isEmpty(); }
};

void drawReferenceOverlay(QPainter& painter, const ViewTransform& view,
                          const ReferenceOverlay& overlay, const RenderOptions& options);

}  // namespace phasebox::ui
