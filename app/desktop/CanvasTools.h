#pragma once
// What the mouse does on the canvas, tool by tool. The canvas (ui::SceneView) only reports
// presses, moves and releases in world coordinates; this turns them into Document edits, one
// undoable command per gesture (a drag merges into one), with a dashed preview while dragging.
//
//   Select   click picks (Shift adds), drag moves the object; while the simulation has run,
//            dragging a dynamic object pulls it with a mouse spring instead
//   Particle click drops a particle; a drag sets its launch velocity (1 m/s per metre dragged)
//   Spring   drag from an object to another object, or to empty space for an anchor
//   Cloth    drag a rectangle: a cloth pinned along its top edge
//   Box      drag a rectangle: a box of that size
//   Disk     drag from the centre to the rim; a click drops one of 0.5 m
//   Polygon  drag from the centre to a corner: a regular n-gon, flat side down; or click the
//            corners one by one and close on the first (Enter closes, Backspace takes the
//            last corner back, Esc drops the outline). A corner that would make the outline
//            non-convex, put three corners in a line or repeat one is refused with the reason.
//   Plane    drag a line along the surface; the solid side is to the right of the drag
//   Pin      click a particle to pin or unpin it, a rigid body to make it static or dynamic
//   Joint    drag from a body to another, or to empty space for the world: a hinge (its pivot
//            where the drag starts), rod, rope (between the points pressed and released),
//            weld, pulley (wheels a metre above) or track (a hoop centred where the drag
//            ends), as jointType() says
//   Ruler, Protractor   measuring instruments: MeasureTools handles them (nothing is edited)

#include <QObject>
#include <QPointF>
#include <QString>

#include "app/document/PropertyTable.h"
#include "physics/scene/SceneDesc.h"

#include <QList>

#include <optional>

namespace phasebox {

class Document;
namespace ui {
class SceneView;
}

class CanvasTools : public QObject {
    Q_OBJECT

public:
    enum class Tool {
        Select,
        Particle,
        Spring,
        Cloth,
        Box,
        Disk,
        Polygon,
        Plane,
        Pin,
        Joint,
        Ruler,
        Protractor
    };

    CanvasTools(Document& document, ui::SceneView& view, QObject* parent = nullptr);

    Tool tool() const { return tool_; }
    void setTool(Tool tool);
    static QString toolName(Tool tool);
    static QString toolHelp(Tool tool);
    // While an object is pulled, the rubber band follows the object as it moves: call after
    // every step.
    void refreshGrabOverlay();

    // Launch speed per metre dragged with the particle tool.
    static constexpr double kVelocityPerMetre = 1.0;
    // A drag shorter than this many pixels is a click.
    static constexpr double kClickPixels = 4.0;
    // The radius of a disk added with a click rather than a drag (m).
    static constexpr double kClickDiskRadius = 0.5;
    // The cloth the tool draws (N/m per spring; damping N·s/m along each spring).
    static constexpr ClothStiffnessDesc kDrawnClothStiffness{200.0, 2.0, 0.0};
    static constexpr double kDrawnClothDamping = 0.05;
    // The polygon tool's regular polygon: this many sides unless set (3 to 16).
    static constexpr int kPolygonSides = 6;
    int polygonSides() const { return polygonSides_; }
    // The joint tool's kind.
    JointType jointType() const { return jointType_; }
    void setJointType(JointType type) { jointType_ = type; }
    void setPolygonSides(int sides);
    // The keyboard's way to draw: the current tool's gesture with its default size at the
    // keyboard cursor (a particle, disk or pin there; a box, cloth or polygon centred on it; a
    // plane along it; a spring, joint or ruler from the first selected object to it).
    void placeAt(QPointF cursor);
    // Moves every selected object that can move by delta metres (one undo step per object).
    void nudgeSelection(QPointF delta);
    // The corners clicked so far with the polygon tool (world coordinates).
    const QList<QPointF>& outline() const { return outline_; }
    // Closes the clicked outline into a polygon (Enter); false, with a message, when refused.
    bool closeOutline();
    // The joint tool's pulley wheels: this far above the higher of its two points (m).
    static constexpr double kPulleyHeight = 1.0;
    // A click within this many pixels of the first corner closes the outline.
    static constexpr double kCloseOutlinePixels = 8.0;

signals:
    void toolChanged(phasebox::CanvasTools::Tool tool);
    // A line for the status bar: what the tool does, or why an edit was refused.
    void message(const QString& text);

private:
    void pressed(QPointF world, Qt::MouseButton button, Qt::KeyboardModifiers modifiers);
    void moved(QPointF world, Qt::MouseButtons buttons, Qt::KeyboardModifiers modifiers);
    void released(QPointF world, Qt::MouseButton button, Qt::KeyboardModifiers modifiers);
    void finish(QPointF world);
    bool eventFilter(QObject* watched, QEvent* event) override;
    void addOutlineCorner(QPointF world);
    void showOutline(QPointF cursor);
    Point2 localPoint(const QString& id, QPointF p) const;
    // Adds a joint of jointType() from a (pressed at start_) to b (empty: the world), the
    // drag ending at end; false with a message when refused.
    bool addJoint(const QString& a, const QString& b, QPointF end, QString* newId);
    void cancel();
    bool isClick(QPointF world) const;
    void report(bool ok, const QString& error);
    // Adds what the user drew (Document::addDrawnObject) and says so when the integrator had to
    // change for it to stay stable.
    bool addDrawn(const ObjectDesc& object, QString* error, QString* id);
    void showPreview(QPointF world);
    // The id of the object under a world point, or empty.
    QString objectAt(QPointF world) const;

    Document& document_;
    ui::SceneView& view_;
    Tool tool_ = Tool::Select;

    // The gesture in progress.
    bool dragging_ = false;
    QPointF start_;
    QString startObject_;
    QPointF grabOffset_;  // the moved object's position minus the press point
    bool grabbing_ = false;
    bool moved_ = false;

    int polygonSides_ = kPolygonSides;
    JointType jointType_ = JointType::Hinge;
    QList<QPointF> outline_;  // the polygon tool's clicked corners
};

}  // namespace phasebox
