#pragma once
// A presenter connects one ui/ widget to the Document (what is edited) and the
// SimulationController (what runs), so that the widget only shows data and emits signals and
// MainWindow only composes. Each presenter follows the document's and the controller's signals
// itself and reaches them through their public interface only.

#include <QKeySequence>
#include <QObject>
#include <QString>

#include <initializer_list>

QT_BEGIN_NAMESPACE
class QAction;
class QWidget;
QT_END_NAMESPACE

namespace phasebox {

// A named action of the main window (MainWindow::action(name) finds it); its shortcut works
// even with the menu bar hidden (presentation mode). Presenters add the actions of their views.
QAction* addWindowAction(QWidget& window, const QString& name, const QString& text,
                         const QKeySequence& shortcut = {});
// Adds the window's named actions, in order, to a menu or tool bar; "" is a separator.
void addWindowActions(QWidget& to, const QWidget& window, std::initializer_list<const char*> names);

class Presenter : public QObject {
    Q_OBJECT

public:
    using QObject::QObject;

    // Brings the widget up to date at once, for pictures and tests (MainWindow::refreshNow).
    virtual void refresh() = 0;

signals:
    // A line for the status bar: what an edit did, or why it was refused.
    void message(const QString& text);
};

}  // namespace phasebox
