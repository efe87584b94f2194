#include "ui/panels/AccessibleNames.h"

#include <QAbstractButton>
#include <QAccessible>
#include <QDockWidget>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QTabWidget>
#include <QWidget>

namespace phasebox::ui {

namespace {
// A label's text as a name: no mnemonic ampersands, no trailing colon, no markup.
QString plain(QString text) {
    static const QRegularExpression tags(QStringLiteral("<[^>]*>"));
    static const QRegularExpression mnemonic(QStringLiteral("&(?!&)"));
    text.remove(tags).remove(mnemonic).replace(QLatin1String("&&"), QLatin1String("&"));
    text = text.section(QLatin1Char('\n'), 0, 0).trimmed();
    while (text.endsWith(QLatin1Char(':'))) text.chop(1);
    return text.trimmed();
}

// The label a QFormLayout shows beside w, if w is one of its fields.
QString formLabel(QWidget* w) {
    for (QWidget* p = w->parentWidget(); p; p = p->parentWidget()) {
        auto* form = qobject_cast<QFormLayout*>(p->layout());
        if (!form) continue;
        for (int row = 0; row < form->rowCount(); ++row) {
            QLayoutItem* field = form->itemAt(row, QFormLayout::FieldRole);
            if (!field) continue;
            QWidget* fw = field->widget();
            if (!fw && field->layout())
                for (int i = 0; i < field->layout()->count() && !fw; ++i)
                    if (field->layout()->itemAt(i)->widget() == w) fw = w;
            if (fw != w && !(fw && fw->isAncestorOf(w))) continue;
            if (QLayoutItem* label = form->itemAt(row, QFormLayout::LabelRole))
                if (auto* l = qobject_cast<QLabel*>(label->widget())) return plain(l->text());
        }
        break;
    }
    return {};
}

QString containerTitle(QWidget* w) {
    for (QWidget* p = w->parentWidget(); p; p = p->parentWidget()) {
        if (auto* group = qobject_cast<QGroupBox*>(p); group && !group->title().isEmpty())
            return plain(group->title());
        if (auto* dock = qobject_cast<QDockWidget*>(p)) return plain(dock->windowTitle());
    }
    return {};
}

QString fallbackName(QWidget* w) {
    if (QString name = formLabel(w); !name.isEmpty()) return name;
    if (QString name = plain(w->toolTip()); !name.isEmpty()) return name;
    if (auto* edit = qobject_cast<QLineEdit*>(w); edit && !edit->placeholderText().isEmpty())
        return plain(edit->placeholderText());
    if (auto* button = qobject_cast<QAbstractButton*>(w); button && !button->text().isEmpty())
        return plain(button->text());
    if (QString name = plain(w->whatsThis()); !name.isEmpty()) return name;
    return containerTitle(w);
}
}  // namespace

QString accessibleNameOf(QWidget* w) {
    if (!w) return {};
    if (!w->accessibleName().isEmpty()) return w->accessibleName();
    QAccessibleInterface* iface = QAccessible::queryAccessibleInterface(w);
    return iface ? iface->text(QAccessible::Name).trimmed() : QString();
}

void nameControls(QWidget* root) {
    if (!root) return;
    QList<QWidget*> widgets = root->findChildren<QWidget*>();
    widgets.prepend(root);
    for (QWidget* w : std::as_const(widgets)) {
        if (!(w->focusPolicy() & Qt::TabFocus) || w->focusProxy()) continue;
        if (accessibleNameOf(w).isEmpty()) {
            const QString name = fallbackName(w);
            if (!name.isEmpty()) w->setAccessibleName(name);
        }
        if (w->accessibleDescription().isEmpty() && !w->toolTip().isEmpty())
            w->setAccessibleDescription(w->toolTip().section(QLatin1Char('\n'), 0, 2));
    }
}

}  // namespace phasebox::ui
