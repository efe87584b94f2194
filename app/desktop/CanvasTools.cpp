#include "app/desktop/CanvasTools.h"

#include "app/document/Document.h"
#include "app/document/PropertyTable.h"
#include "physics/effects/MouseSpringEffect.h"
#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneView.h"
#include "ui/panels/ShownNumber.h"

#include <QKeyEvent>
#include <QLineF>

#include <cmath>
#include <numbers>

namespace phasebox {

namespace {
Point2 point(QPointF p) {
    return {p.x(), p.y()};
}

// The key pair that places an object of this kind (schema::KindInfo::placeKey); none for a
// kind that moves with its bodies or its anchor.
std::optional<std::pair<QString, QString>> positionKeys(ObjectKind kind) {
    const std::string_view key = schema::kindInfo(kind).placeKey;
    if (key.empty()) return std::nullopt;
    const QString name = QString::fromUtf8(key.data(), static_cast<qsizetype>(key.size()));
    return std::pair{name + QStringLiteral(".x"), name + QStringLiteral(".y")};
}

QString formatLength(double metres) {
    return ui::shownNumber(metres, 'f', 2) + QStringLiteral(" m");
}

// Why a corner cannot join the outline, in a user's words, from validatePolygonVertices().
QString outlineRefusal(const SceneIssue& issue) {
    const QString what = QString::fromStdString(issue.message);
    if (what.contains(QStringLiteral("convex")))
        return CanvasTools::tr(
            "That corner would make the polygon non-convex; polygons must be convex (build a "
            "concave shape from convex pieces).");
    if (what.contains(QStringLiteral("line")))
        return CanvasTools::tr("That corner is in a line with two others: move it off the line.");
    if (what.contains(QStringLiteral("repeats")))
        return CanvasTools::tr("That corner is on top of another one.");
    return CanvasTools::tr("That corner is refused: %1").arg(what);
}
}  // namespace

CanvasTools::CanvasTools(Document& document, ui::SceneView& view, QObject* parent)
    : QObject(parent), document_(document), view_(view) {
    connect(&view_, &ui::SceneView::worldMousePressed, this, &CanvasTools::pressed);
    connect(&view_, &ui::SceneView::worldMouseMoved, this, &CanvasTools::moved);
    connect(&view_, &ui::SceneView::worldMouseReleased, this, &CanvasTools::released);
    view_.installEventFilter(this);  // Enter, Backspace and Esc for an outline in progress
    // A double click on the last corner closes the outline.
    connect(&view_, &ui::SceneView::worldMouseDoubleClicked, this,
            [this](QPointF, Qt::MouseButton button) {
                if (button == Qt::LeftButton && tool_ == Tool::Polygon && outline_.size() >= 3)
                    closeOutline();
            });
}

QString CanvasTools::toolName(Tool tool) {
    switch (tool) {
        case Tool::Select:
            return tr("Select / move");
        case Tool::Particle:
            return tr("Add particle");
        case Tool::Spring:
            return tr("Add spring");
        case Tool::Cloth:
            return tr("Add cloth");
        case Tool::Box:
            return tr("Add box");
        case Tool::Disk:
            return tr("Add disk");
        case Tool::Polygon:
            return tr("Add polygon");
        case Tool::Plane:
            return tr("Add plane");
        case Tool::Pin:
            return tr("Pin / unpin");
        case Tool::Joint:
            return tr("Add joint");
        case Tool::Ruler:
            return tr("Ruler");
        case Tool::Protractor:
            return tr("Protractor");
    }
    return {};
}

QString CanvasTools::toolHelp(Tool tool) {
    switch (tool) {
        case Tool::Select:
            return tr(
                "Click to select (Shift adds), drag to move; while running, drag an object to "
                "pull it with a mouse spring.");
        case Tool::Particle:
            return tr("Click to drop a particle; drag to give it a velocity.");
        case Tool::Spring:
            return tr("Drag from an object to another, or to empty space for a fixed anchor.");
        case Tool::Cloth:
            return tr("Drag a rectangle: a cloth hung from its top corners.");
        case Tool::Box:
            return tr("Drag a rectangle: a box of that size.");
        case Tool::Disk:
            return tr(
                "Drag from the centre to the rim: a disk that rolls; click for one of 0.5 m.");
        case Tool::Polygon:
            return tr(
                "Drag from the centre to a corner: a regular polygon, flat side down; or click "
                "the corners and close on the first (double click or Enter closes, Backspace "
                "undoes a corner, "
                "Esc drops the outline).");
        case Tool::Plane:
            return tr("Drag a line along the surface; the solid side is to the right of the drag.");
        case Tool::Pin:
            return tr("Click a particle to pin or unpin it, a box or disk to make it static.");
        case Tool::Joint:
            return tr(
                "Drag from a body to another, or to empty space for the fixed world: a hinge "
                "pivots where the drag starts; a rod or rope joins the two points; a weld "
                "holds two bodies together; a pulley hangs two bodies over two wheels a metre "
                "above; a track puts a particle on a hoop centred where the drag ends.");
        case Tool::Ruler:
            return tr(
                "Drag from one point to another to measure the distance; an end dropped on an "
                "object follows it. Click a ruler to select it, Esc or Delete removes it.");
        case Tool::Protractor:
            return tr(
                "Drag from the vertex along the first arm, then click the second arm: the angle "
                "between them. Ends dropped on objects follow them; Esc or Delete removes the "
                "selected one.");
    }
    return {};
}

void CanvasTools::setPolygonSides(int sides) {
    polygonSides_ = std::clamp(sides, 3, SceneLimits::kMaxPolygonVertices);
}

void CanvasTools::setTool(Tool tool) {
    if (tool == tool_) return;
    cancel();
    tool_ = tool;
    view_.setCursor(tool == Tool::Select ? Qt::ArrowCursor : Qt::CrossCursor);
    emit toolChanged(tool);
    emit message(toolHelp(tool));
}

QString CanvasTools::objectAt(QPointF world) const {
    const ui::PickResult hit = view_.pick(view_.toWidget(world));
    if (!hit) return {};
    // A joint's pivot lies on its bodies: the tools that attach things attach them to its
    // body a there.
    if (hit.kind == ui::PickResult::Joint && tool_ != Tool::Select && tool_ != Tool::Pin) {
        const World& w = document_.world();
        const JointBody& a = w.joints()[hit.index].a;
        return QString::fromStdString(a.kind == JointBody::Kind::Rigid ? w.rigidBodies()[a.index].id
                                                                       : w.particles()[a.index].id);
    }
    return QString::fromStdString(hit.id);
}

bool CanvasTools::isClick(QPointF world) const {
    return QLineF(view_.toWidget(start_), view_.toWidget(world)).length() < kClickPixels;
}

void CanvasTools::report(bool ok, const QString& error) {
    if (!ok && !error.isEmpty()) emit message(error);
}

bool CanvasTools::addDrawn(const ObjectDesc& object, QString* error, QString* id) {
    QString notice;
    const bool ok = document_.addDrawnObject(object, error, id, &notice);
    if (ok && !notice.isEmpty()) emit message(notice);
    return ok;
}

void CanvasTools::pressed(QPointF world, Qt::MouseButton button, Qt::KeyboardModifiers modifiers) {
    if (button != Qt::LeftButton) return;
    dragging_ = true;
    moved_ = false;
    start_ = world;
    startObject_ = objectAt(world);
    grabbing_ = false;
    if (tool_ != Tool::Select) return;

    if (startObject_.isEmpty()) {
        if (!(modifiers & Qt::ShiftModifier)) document_.setSelection({});
        return;
    }
    // Select (Shift toggles the object in the selection).
    QStringList selection = document_.selection();
    if (modifiers & Qt::ShiftModifier) {
        if (selection.contains(startObject_))
            selection.removeAll(startObject_);
        else
            selection.append(startObject_);
    } else if (!selection.contains(startObject_)) {
        selection = {startObject_};
    }
    document_.setSelection(selection);

    // While the simulation runs (or has run), a drag pulls a dynamic object with a spring; at
    // the setup it moves the object.
    if (document_.hasRun()) {
        const World& w = document_.world();
        const ui::PickResult hit = view_.pick(view_.toWidget(world));
        Point2 local{0.0, 0.0};
        if (hit.kind == ui::PickResult::Box) {
            const Vec2 offset = Vec2(world.x(), world.y()) - w.bodyPosition(hit.index);
            const Vec2 inBox = rotation(-w.bodyAngle(hit.index)) * offset;
            local = {inBox.x(), inBox.y()};
        }
        if ((hit.kind == ui::PickResult::Particle || hit.kind == ui::PickResult::Box) &&
            document_.grab(startObject_, local, point(world))) {
            grabbing_ = true;
            emit message(tr("Pulling %1 with a mouse spring").arg(startObject_));
            return;
        }
    }
    const ObjectRef ref = findObject(document_.setup(), startObject_.toStdString());
    if (const auto keys = positionKeys(ref.kind)) {
        const QString id = QString::fromStdString(objectId(document_.setup(), ref));
        const auto x = propertyValue(document_.setup(), id, keys->first);
        const auto y = propertyValue(document_.setup(), id, keys->second);
        if (x && y) grabOffset_ = QPointF(*x, *y) - world;
        startObject_ = id;  // a cloth node moves its whole cloth
    } else {
        startObject_.clear();  // springs are not moved by dragging
    }
}

void CanvasTools::placeAt(QPointF cursor) {
    QPointF start = cursor, end = cursor;
    switch (tool_) {
        case Tool::Select:
            return;
        case Tool::Particle:
        case Tool::Disk:
        case Tool::Pin:
            break;  // a click
        case Tool::Polygon:
            end = cursor + QPointF(0.4, 0.0);  // from the centre to a corner
            break;
        case Tool::Box:
            start = cursor - QPointF(0.5, 0.3);
            end = cursor + QPointF(0.5, 0.3);
            break;
        case Tool::Cloth:
            start = cursor + QPointF(-0.6, 0.5);
            end = cursor + QPointF(0.6, -0.5);
            break;
        case Tool::Plane:  // solid below: the drag runs to the right
            start = cursor - QPointF(1.0, 0.0);
            end = cursor + QPointF(1.0, 0.0);
            break;
        case Tool::Spring:
        case Tool::Joint:
        case Tool::Ruler:
        case Tool::Protractor: {
            const QStringList selection = document_.selection();
            const ObjectRef ref = selection.isEmpty() ? ObjectRef{}
                                                      : findObject(document_.setup(),
                                                                   selection.first().toStdString());
            if (const auto keys = positionKeys(ref.kind)) {
                const QString id = QString::fromStdString(objectId(document_.setup(), ref));
                const auto x = propertyValue(document_.setup(), id, keys->first);
                const auto y = propertyValue(document_.setup(), id, keys->second);
                if (x && y) start = QPointF(*x, *y);
            }
            break;
        }
    }
    pressed(start, Qt::LeftButton, {});
    if (end != start) moved(end, Qt::LeftButton, {});
    released(end, Qt::LeftButton, {});
}

void CanvasTools::nudgeSelection(QPointF delta) {
    const SceneDesc& setup = document_.setup();
    for (const QString& selected : document_.selection()) {
        const ObjectRef ref = findObject(setup, selected.toStdString());
        const auto keys = positionKeys(ref.kind);
        if (!keys) continue;
        const QString id = QString::fromStdString(objectId(setup, ref));
        const auto x = propertyValue(setup, id, keys->first);
        const auto y = propertyValue(setup, id, keys->second);
        if (!x || !y) continue;
        QString error;
        report(document_.moveObject(id, {*x + delta.x(), *y + delta.y()}, &error), error);
    }
}

void CanvasTools::moved(QPointF world, Qt::MouseButtons buttons, Qt::KeyboardModifiers) {
    if (!outline_.isEmpty()) {
        showOutline(world);  // the outline follows the cursor; a drag adds no corner
        return;
    }
    if (!dragging_ || !(buttons & Qt::LeftButton)) return;
    if (!moved_ && isClick(world)) return;
    moved_ = true;
    if (tool_ == Tool::Select) {
        if (grabbing_) {
            document_.moveGrab(point(world));
            refreshGrabOverlay();
        } else if (!startObject_.isEmpty()) {
            QString error;
            report(document_.moveObject(startObject_, point(world + grabOffset_), &error), error);
        }
        return;
    }
    showPreview(world);
}

void CanvasTools::refreshGrabOverlay() {
    const MouseSpringEffect* spring = document_.mouseSpring();
    if (!grabbing_ || !spring || !spring->isAttached()) return;
    const Vec2 from = spring->grabbedPoint(document_.world().positions());
    const Vec2 to = spring->target();
    view_.setOverlay({ui::ToolOverlay::Line,
                      QPointF(from.x(), from.y()),
                      QPointF(to.x(), to.y()),
                      tr("pulling %1").arg(startObject_),
                      {}});
}

void CanvasTools::showPreview(QPointF world) {
    ui::ToolOverlay overlay;
    overlay.a = start_;
    overlay.b = world;
    const QPointF d = world - start_;
    switch (tool_) {
        case Tool::Particle:
            overlay.shape = ui::ToolOverlay::Arrow;
            overlay.text =
                tr("v = %1 m/s")
                    .arg(ui::shownNumber(std::hypot(d.x(), d.y()) * kVelocityPerMetre, 'f', 2));
            break;
        case Tool::Joint:
        case Tool::Spring: {
            overlay.shape = ui::ToolOverlay::Line;
            const QString target = objectAt(world);
            overlay.text = target.isEmpty()
                               ? tr("anchor, %1").arg(formatLength(std::hypot(d.x(), d.y())))
                               : target;
            break;
        }
        case Tool::Cloth:
        case Tool::Box:
            overlay.shape = ui::ToolOverlay::Rect;
            overlay.text = formatLength(std::abs(d.x())) + QStringLiteral(" × ") +
                           formatLength(std::abs(d.y()));
            break;
        case Tool::Polygon:
        case Tool::Disk:
            overlay.shape = ui::ToolOverlay::Circle;
            overlay.text = tr("r = %1").arg(formatLength(std::hypot(d.x(), d.y())));
            break;
        case Tool::Plane:
            overlay.shape = ui::ToolOverlay::Arrow;
            break;
        default:
            return;
    }
    view_.setOverlay(overlay);
}

void CanvasTools::released(QPointF world, Qt::MouseButton button, Qt::KeyboardModifiers) {
    if (button != Qt::LeftButton || !dragging_) return;
    view_.setOverlay({});
    finish(world);
    dragging_ = false;
    document_.finishInteraction();
}

void CanvasTools::finish(QPointF world) {
    const bool click = !moved_ && isClick(world);
    const QPointF d = world - start_;
    QString error, id;
    switch (tool_) {
        case Tool::Select:
            if (grabbing_) document_.releaseGrab();
            grabbing_ = false;
            return;
        case Tool::Particle: {
            ParticleDesc p;
            p.position = point(start_);
            if (!click) p.velocity = {d.x() * kVelocityPerMetre, d.y() * kVelocityPerMetre};
            report(addDrawn(p, &error, &id), error);
            break;
        }
        case Tool::Spring: {
            const QString target = objectAt(world);
            if (startObject_.isEmpty() || click || target == startObject_) {
                emit message(tr("A spring starts on an object: drag from a particle or box."));
                return;
            }
            SpringDesc s;
            s.a = startObject_.toStdString();
            if (target.isEmpty())
                s.anchor = point(world);
            else
                s.b = target.toStdString();
            // Stiff enough to hold a 1 kg ball against gravity with a visible stretch.
            s.stiffness = 50.0;
            s.damping = 0.1;
            report(addDrawn(s, &error, &id), error);
            break;
        }
        case Tool::Cloth: {
            if (click) return;
            ClothDesc c;
            c.origin = {std::min(start_.x(), world.x()), std::max(start_.y(), world.y())};
            c.size = {std::abs(d.x()), std::abs(d.y())};
            // About 20 cm between nodes, between 4 and 24 nodes a side.
            const auto nodes = [](double length) {
                return std::clamp(int(length / 0.2) + 1, 4, 24);
            };
            c.resolution = {nodes(c.size[0]), nodes(c.size[1])};
            // A cloth that drapes: hung from its top corners, stretchy along its threads and
            // hardly resisting shear, with no bending springs (in the plane they only resist
            // compression and would stiffen it into a board). The format's defaults, pinned
            // along the top, hang as a rigid net. Damping lets it settle.
            c.pinned = std::string("top_corners");
            c.stiffness = kDrawnClothStiffness;
            c.damping = kDrawnClothDamping;
            report(addDrawn(c, &error, &id), error);
            break;
        }
        case Tool::Box: {
            if (click) return;
            BoxDesc b;
            b.position = {0.5 * (start_.x() + world.x()), 0.5 * (start_.y() + world.y())};
            b.size = {std::abs(d.x()), std::abs(d.y())};
            report(addDrawn(b, &error, &id), error);
            break;
        }
        case Tool::Disk: {
            DiskDesc disk;
            disk.position = point(start_);
            disk.radius = click ? kClickDiskRadius : std::hypot(d.x(), d.y());
            report(addDrawn(disk, &error, &id), error);
            break;
        }
        case Tool::Polygon: {
            if (click || !outline_.isEmpty()) {
                addOutlineCorner(start_);
                return;
            }
            PolygonDesc polygon;
            polygon.position = point(start_);
            const double r = std::hypot(d.x(), d.y());
            // Flat side down: the lowest edge runs between -90° -/+ 180°/n.
            const int n = polygonSides_;
            for (int k = 0; k < n; ++k) {
                const double a = std::numbers::pi * (2.0 * k - 1.0) / n - 0.5 * std::numbers::pi;
                polygon.vertices.push_back({r * std::cos(a), r * std::sin(a)});
            }
            report(addDrawn(polygon, &error, &id), error);
            break;
        }
        case Tool::Plane: {
            if (click) return;
            PlaneDesc p;
            p.point = point(start_);
            // Solid to the right of the drag: the normal points to its left.
            p.normal = {-d.y(), d.x()};
            report(addDrawn(p, &error, &id), error);
            break;
        }
        case Tool::Joint: {
            if (startObject_.isEmpty()) {
                emit message(
                    tr("A joint starts on a body: drag from a particle, box, disk or "
                       "polygon."));
                return;
            }
            const QString target = objectAt(world);
            if (!addJoint(startObject_, target == startObject_ ? QString() : target, world, &id))
                return;
            break;
        }
        case Tool::Ruler:
        case Tool::Protractor:
            return;  // MeasureTools' gestures
        case Tool::Pin: {
            if (!click || startObject_.isEmpty()) return;
            const ObjectRef ref = findObject(document_.setup(), startObject_.toStdString());
            const QString key = pinPropertyKey(ref.kind);
            const auto current = propertyValue(document_.setup(), startObject_, key);
            if (!current) {
                emit message(tr("Only particles can be pinned and boxes and disks made static."));
                return;
            }
            report(document_.setPinned(startObject_, *current == 0.0, &error), error);
            return;
        }
    }
    if (!id.isEmpty()) document_.setSelection({id});
}

void CanvasTools::addOutlineCorner(QPointF world) {
    const bool nearFirst =
        !outline_.isEmpty() &&
        QLineF(view_.toWidget(outline_.front()), view_.toWidget(world)).length() <
            kCloseOutlinePixels;
    if (nearFirst) {
        if (outline_.size() >= 3) {
            closeOutline();
        } else {
            emit message(tr("A polygon needs at least three corners."));
        }
        return;
    }
    QList<QPointF> candidate = outline_;
    candidate.append(world);
    // Each corner is checked as it comes: the corners so far must already make a convex
    // polygon (a convex polygon's corners, any of them dropped, still do), so the first
    // corner that breaks the rule is the one refused.
    if (candidate.size() >= 3) {
        std::vector<Point2> vertices;
        for (const QPointF& q : candidate)
            vertices.push_back({q.x() - candidate.front().x(), q.y() - candidate.front().y()});
        if (const auto issues = validatePolygonVertices(vertices); !issues.empty()) {
            emit message(outlineRefusal(issues.front()));
            return;
        }
    }
    outline_ = candidate;
    if (outline_.size() == SceneLimits::kMaxPolygonVertices) {
        closeOutline();
        return;
    }
    showOutline(world);
    emit message(outline_.size() < 3
                     ? tr("Corner %1: click the next corner.").arg(outline_.size())
                     : tr("Corner %1: click the next, or the first corner (or Enter) to close.")
                           .arg(outline_.size()));
}

void CanvasTools::showOutline(QPointF cursor) {
    ui::ToolOverlay overlay;
    overlay.shape = ui::ToolOverlay::Polyline;
    overlay.points = outline_;
    overlay.a = outline_.front();
    overlay.b = cursor;
    overlay.text = tr("%n corner(s)", nullptr, static_cast<int>(outline_.size()));
    view_.setOverlay(overlay);
}

bool CanvasTools::closeOutline() {
    if (outline_.size() < 3) {
        emit message(tr("A polygon needs at least three corners."));
        return false;
    }
    PolygonDesc polygon;
    polygon.position = point(outline_.front());
    for (const QPointF& q : std::as_const(outline_))
        polygon.vertices.push_back({q.x() - outline_.front().x(), q.y() - outline_.front().y()});
    if (const auto issues = validatePolygonVertices(polygon.vertices); !issues.empty()) {
        emit message(outlineRefusal(issues.front()));
        return false;
    }
    // The body's frame at the centroid, as a loaded file has it.
    const Point2 c = polygon.centroid();
    for (Point2& v : polygon.vertices) v = {v[0] - c[0], v[1] - c[1]};
    polygon.position = {polygon.position[0] + c[0], polygon.position[1] + c[1]};
    outline_.clear();
    view_.setOverlay({});
    QString error, id;
    const bool ok = addDrawn(polygon, &error, &id);
    report(ok, error);
    if (ok) document_.setSelection({id});
    return ok;
}

bool CanvasTools::eventFilter(QObject* watched, QEvent* event) {
    if (watched != &view_ || event->type() != QEvent::KeyPress || outline_.isEmpty())
        return QObject::eventFilter(watched, event);
    switch (static_cast<QKeyEvent*>(event)->key()) {
        case Qt::Key_Return:
        case Qt::Key_Enter:
            closeOutline();
            return true;
        case Qt::Key_Backspace:
            outline_.removeLast();
            if (outline_.isEmpty())
                view_.setOverlay({});
            else
                showOutline(view_.overlay().b);
            return true;
        case Qt::Key_Escape:
            outline_.clear();
            view_.setOverlay({});
            emit message(tr("Outline dropped."));
            return true;
        default:
            return QObject::eventFilter(watched, event);
    }
}

// The point p (world) in the frame of the body with this id as the setup places it; a
// particle's point is unused (its centre).
Point2 CanvasTools::localPoint(const QString& id, QPointF p) const {
    const SceneDesc& setup = document_.setup();
    const auto x = propertyValue(setup, id, QStringLiteral("position.x"));
    const auto y = propertyValue(setup, id, QStringLiteral("position.y"));
    const auto angle = propertyValue(setup, id, QStringLiteral("angle"));
    if (!x || !y || !angle) return {0.0, 0.0};  // a particle or cloth node
    const double c = std::cos(*angle), s = std::sin(*angle);
    const double dx = p.x() - *x, dy = p.y() - *y;
    return {c * dx + s * dy, -s * dx + c * dy};
}

bool CanvasTools::addJoint(const QString& a, const QString& b, QPointF end, QString* newId) {
    JointDesc j;
    j.type = jointType_;
    j.a = a.toStdString();
    if (!b.isEmpty()) j.b = b.toStdString();
    switch (jointType_) {
        case JointType::Hinge:
            j.anchor = point(start_);  // the pivot: where the drag began, on a
            break;
        case JointType::Rod:
        case JointType::Rope:
            if (isClick(end)) {
                emit message(tr("Drag to where the %1 ends: another body or a fixed point.")
                                 .arg(jointType_ == JointType::Rod ? tr("rod") : tr("rope")));
                return false;
            }
            j.aPoint = localPoint(a, start_);
            if (b.isEmpty())
                j.anchor = point(end);
            else
                j.bPoint = localPoint(b, end);
            break;
        case JointType::Weld:
            if (b.isEmpty()) {
                emit message(tr("A weld holds two bodies: drag from one onto the other."));
                return false;
            }
            break;
        case JointType::Pulley:
            if (b.isEmpty()) {
                emit message(tr("A pulley hangs two bodies: drag from one to the other."));
                return false;
            }
            // The two wheels above the points pressed and released, a metre over the higher.
            j.aPoint = localPoint(a, start_);
            j.bPoint = localPoint(b, end);
            j.groundA = {start_.x(), std::max(start_.y(), end.y()) + kPulleyHeight};
            j.groundB = {end.x(), std::max(start_.y(), end.y()) + kPulleyHeight};
            j.b = b.toStdString();
            break;
        case JointType::Track:
            // A bead on a hoop: the circle about where the drag ends, through the particle.
            if (isClick(end)) {
                emit message(tr("Drag from a particle to the centre of its hoop."));
                return false;
            }
            j.b.reset();
            j.circle = TrackCircleDesc{point(end), QLineF(start_, end).length()};
            break;
    }
    QString error;
    const bool ok = addDrawn(j, &error, newId);
    report(ok, error);
    return ok;
}

void CanvasTools::cancel() {
    outline_.clear();
    if (grabbing_) document_.releaseGrab();
    grabbing_ = false;
    dragging_ = false;
    view_.setOverlay({});
}

}  // namespace phasebox
