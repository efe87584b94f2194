#include "app/desktop/LanguageMenu.h"

#include "app/i18n/Language.h"

#include <QActionGroup>
#include <QGuiApplication>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStringList>

namespace phasebox {

LanguageMenu::LanguageMenu(QMenu& menu, const QString& stored, QWidget& window)
    : QObject(&menu), window_(window) {
    menu.setObjectName(QStringLiteral("languageMenu"));
    auto* group = new QActionGroup(&menu);
    QStringList codes{QString()};
    codes << i18n::languages();
    for (const QString& code : std::as_const(codes)) {
        QAction* a =
            menu.addAction(code.isEmpty() ? tr("&System Language") : i18n::nativeName(code));
        a->setCheckable(true);
        a->setChecked(code == stored);
        a->setData(code);
        a->setObjectName(QStringLiteral("language_") +
                         (code.isEmpty() ? QStringLiteral("system") : code));
        group->addAction(a);
        connect(a, &QAction::triggered, this, [this, code] { choose(code); });
    }
}

void LanguageMenu::choose(const QString& code) {
    QSettings settings;
    i18n::storeLanguage(settings, code);
    const QString next = i18n::resolve(code);
    if (next == i18n::installedLanguage()) return;
    const QString text =
        tr("Phasebox will speak %1 from its next start.").arg(i18n::nativeName(next));
    if (QGuiApplication::platformName() == QLatin1String("offscreen"))
        emit message(text);
    else
        QMessageBox::information(&window_, tr("Language"), text);
}

}  // namespace phasebox
