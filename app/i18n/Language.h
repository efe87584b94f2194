#pragma once
// The language of the desktop app: which translations exist, which one a user chose, and
// installing it. The command line never calls these: its messages, keys and numbers are an
// interface for scripts (CONTRACT §1, §4) and stay English whatever the system's language.
//
// Texts that are data rather than code (the built-in scenes' names and notes, the schema's
// field labels, the integrators' names) are translated by their English text in a context of
// their own (BuiltinTexts.h), so the files on disk stay English and a user's own scene that
// happens to carry a built-in name is shown translated like the built-in one.

#include <QString>
#include <QStringList>

class QSettings;

namespace phasebox::i18n {

// The languages the app speaks, as ISO 639-1 codes; "en" (the source language) first.
const QStringList& languages();
// A language's name in that language ("Deutsch"), for the menu that chooses it.
QString nativeName(const QString& code);

// The stored choice: "" means "follow the system".
QString storedLanguage(const QSettings& settings);
void storeLanguage(QSettings& settings, const QString& code);

// The language to use for a choice: a known code as it is, otherwise ("" or unknown) the first
// of the system's preferred languages that the app speaks, else English.
QString resolve(const QString& choice);

// Replaces the translators this function installed before with the app's and Qt's own
// (standard buttons, dialogs) for the language, and makes its locale the default one, so that
// numbers shown follow it. Files never use the default locale: they are written with '.'
// decimals through QString::number and the JSON writer. Returns false when the app has no
// translation for the language (English needs none).
bool install(const QString& code);
// The language install() put in place last ("en" before any call).
QString installedLanguage();

}  // namespace phasebox::i18n
