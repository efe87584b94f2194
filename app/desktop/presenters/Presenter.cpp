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

void addWindowActions(QWidget& to, const QWidget& window,
                      std::initializer_list<const char*> names) {
    for (const char* name : names) {
        QAction* a =
            *name ? window.findChild<QAction*>(QLatin1String(name), Qt::FindDirectChildrenOnly)
                  : new QAction(&to);
        a->setSeparator(!*name);
        to.addAction(a);
    }
}

}  // namespace phasebox
