// SceneView's keyboard editing: Tab walks the objects, the arrow keys move the selection (with
// the Select tool) or the keyboard cursor, Enter opens the selection's properties or places the
// current tool's object at the cursor. The view only reports these; CanvasPresenter makes
// them edits, so that the keyboard and the mouse edit through the same commands.

#include "ui/canvas/SceneView.h"

#include <QKeyEvent>
#include <QPainter>

namespace phasebox::ui {

void SceneView::setKeyboardTargets(const QStringList& ids) {
    keyboardTargets_ = ids;
}

void SceneView::setKeyboardCursor(QPointF world) {
    keyboardCursor_ = world;
    update();
    if (surface_) surface_->update();
}

bool SceneView::focusNextPrevChild(bool next) {
    // Tab moves through the objects first; past the last one (or before the first with
    // Shift+Tab) the focus goes on to the next control, so the window stays walkable by Tab.
    if (!hasFocus() || keyboardTargets_.isEmpty()) return QWidget::focusNextPrevChild(next);
    qsizetype at = -1;
    for (const std::string& id : options_.selectedIds) {
        at = keyboardTargets_.indexOf(QString::fromStdString(id));
        if (at >= 0) break;
    }
    const qsizetype to = at < 0 ? (next ? 0 : keyboardTargets_.size() - 1) : at + (next ? 1 : -1);
    if (to < 0 || to >= keyboardTargets_.size()) return QWidget::focusNextPrevChild(next);
    emit keyboardSelected(keyboardTargets_.at(to));
    return true;
}

bool SceneView::handleKeyboardEditing(QKeyEvent* event) {
    const bool fine = event->modifiers() & Qt::ShiftModifier;
    const double step = fine ? kKeyboardFineStep : kKeyboardStep;
    QPointF delta;
    switch (event->key()) {
        case Qt::Key_Left:
            delta = {-step, 0.0};
            break;
        case Qt::Key_Right:
            delta = {step, 0.0};
            break;
        case Qt::Key_Up:
            delta = {0.0, step};
            break;
        case Qt::Key_Down:
            delta = {0.0, -step};
            break;
        case Qt::Key_Return:
        case Qt::Key_Enter:
            emit keyboardActivated(keyboardCursor_);
            event->accept();
            return true;
        default:
            return false;
    }
    if (arrowsMoveSelection_ && !options_.selectedIds.empty())
        emit keyboardNudged(delta);
    else
        setKeyboardCursor(keyboardCursor_ + delta);
    event->accept();
    return true;
}

void SceneView::focusInEvent(QFocusEvent* event) {
    // The cursor starts where the user looks: the middle of the view, unless it is in view.
    const QPointF at = toWidget(keyboardCursor_);
    if (!rect().contains(at.toPoint())) keyboardCursor_ = toWorld(QPointF(rect().center()));
    update();
    if (surface_) surface_->update();
    QWidget::focusInEvent(event);
}

void SceneView::drawKeyboardCursor(QPainter& painter) const {
    if (!hasFocus() || (arrowsMoveSelection_ && !options_.selectedIds.empty())) return;
    const QPointF c = view_.toScreen(keyboardCursor_);
    const double r = 9.0 * options_.lineWidthScale;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    for (const auto& [colour, width] :
         {std::pair{options_.background, 4.0}, {options_.colors.selection, 2.0}}) {
        painter.setPen(QPen(colour, width * options_.lineWidthScale));
        painter.drawLine(c - QPointF(r, 0), c + QPointF(r, 0));
        painter.drawLine(c - QPointF(0, r), c + QPointF(0, r));
    }
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(c, r * 0.5, r * 0.5);
    painter.restore();
}

}  // namespace phasebox::ui
