#pragma once
// Numbers as the window shows them: in the default locale, which the chosen language sets
// (app/i18n/Language.cpp), so "1,5" in German, Spanish and French; without group separators,
// so that a number reads as one token. Files, CSV and the clipboard never go through this:
// they stay '.'-decimal (app/io/NumberFormat.h, QString::number).

#include <QLocale>
#include <QString>

namespace phasebox::ui {

inline QLocale shownLocale() {
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    return locale;
}

// value with format 'f', 'e' or 'g' and precision as QLocale::toString takes them.
// The exponent is written with a small e, as everywhere else in the app ("2.5e-3"), where the
// locale's own symbol would be a capital E.
inline QString shownNumber(double value, char format = 'g', int precision = 6) {
    const QLocale locale = shownLocale();
    return locale.toString(value, format, precision)
        .replace(locale.exponential(), QStringLiteral("e"));
}

}  // namespace phasebox::ui
