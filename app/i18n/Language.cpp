#include "app/i18n/Language.h"

#include "ui/plots/Charts.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

#include <memory>
#include <vector>

namespace phasebox::i18n {

namespace {
const QString kSettingsKey = QStringLiteral("language");

// The translators install() owns; replaced as a whole on every call.
std::vector<std::unique_ptr<QTranslator>>& installedTranslators() {
    static std::vector<std::unique_ptr<QTranslator>> translators;
    return translators;
}

QString& current() {
    static QString code = QStringLiteral("en");
    return code;
}
}  // namespace

const QStringList& languages() {
    static const QStringList codes{QStringLiteral("en"), QStringLiteral("de"), QStringLiteral("es"),
                                   QStringLiteral("fr")};
    return codes;
}

QString nativeName(const QString& code) {
    // QLocale's native names are lower case for some languages ("español", "français"); a menu
    // entry starts with a capital.
    QString name = QLocale(code).nativeLanguageName();
    if (!name.isEmpty()) name[0] = name[0].toUpper();
    return name.isEmpty() ? code : name;
}

QString storedLanguage(const QSettings& settings) {
    const QString code = settings.value(kSettingsKey).toString();
    return languages().contains(code) ? code : QString();
}

void storeLanguage(QSettings& settings, const QString& code) {
    if (code.isEmpty() || !languages().contains(code))
        settings.remove(kSettingsKey);
    else
        settings.setValue(kSettingsKey, code);
}

QString resolve(const QString& choice) {
    if (languages().contains(choice)) return choice;
    for (const QString& preferred : QLocale::system().uiLanguages()) {
        const QString code = preferred.left(2).toLower();  // "de-AT" speaks "de"
        if (languages().contains(code)) return code;
    }
    return QStringLiteral("en");
}

namespace {
// The system's own locale when it speaks the language (a German user in Austria keeps
// Austrian formats), else the language's main one.
QLocale localeFor(const QString& code) {
    const QLocale language(code);
    return QLocale::system().language() == language.language() ? QLocale::system() : language;
}
}  // namespace

bool install(const QString& code) {
    auto& translators = installedTranslators();
    for (const auto& t : translators) QCoreApplication::removeTranslator(t.get());
    translators.clear();
    current() = QStringLiteral("en");
    QLocale::setDefault(localeFor(QStringLiteral("en")));
    // The charts' tick labels follow the window's numbers (the command line never comes here).
    ui::setChartLocale(QLocale());
    if (code == QLatin1String("en")) return true;
    auto own = std::make_unique<QTranslator>();
    if (!own->load(QStringLiteral(":/i18n/phasebox_%1.qm").arg(code))) return false;
    QLocale::setDefault(localeFor(code));
    ui::setChartLocale(QLocale());
    QCoreApplication::installTranslator(own.get());
    translators.push_back(std::move(own));
    // Qt's own strings (OK, Cancel, the file dialog) when the system has them installed.
    auto qt = std::make_unique<QTranslator>();
    if (qt->load(QLocale(code), QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(qt.get());
        translators.push_back(std::move(qt));
    }
    current() = code;
    return true;
}

QString installedLanguage() {
    return current();
}

}  // namespace phasebox::i18n
