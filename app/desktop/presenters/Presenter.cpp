#include "app/desktop/presenters/Presenter.h"

#include <QAction>
#include <QWidget>

namespace phasebox {

QAction* addWindowAction(QWidget& window, const QString& name, const QString& text,
                         const QKeySequence& shortcut) {
    auto* action = new QAction(text, &window);
    action->setObjectName(name);
    if (!shortcut.isEmpty()) action->setShortcut(shortcut);
    window.addAction(action);  // the shortcut works even with the menu bar hidden
    return action;
}

}  // namespace phasebox
