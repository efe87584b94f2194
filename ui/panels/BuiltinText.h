#pragma once
// Texts that are data, not code (the built-in scenes' names and notes, the schema's labels and
// effect descriptions, the integrators' names), shown in the app's language. Each is
// translated by its English text in a context of its own; the files keep English, and the
// list lupdate reads is made from the same sources (app/i18n/BuiltinTexts.h). Without a
// translation (the command line installs none) the English text is shown.

#include <QCoreApplication>
#include <QString>

#include <string>
#include <string_view>

namespace phasebox::ui {

inline constexpr const char* kSceneTextContext = "SceneTexts";
inline constexpr const char* kSchemaTextContext = "Schema";
inline constexpr const char* kIntegratorTextContext = "Integrators";

inline QString builtinText(const char* context, std::string_view english) {
    if (english.empty()) return {};
    const QByteArray source(english.data(), static_cast<qsizetype>(english.size()));
    return QCoreApplication::translate(context, source.constData());
}

// A scene's name or notes (a user's own text has no translation and stays as written).
inline QString sceneText(const std::string& english) {
    return builtinText(kSceneTextContext, english);
}
inline QString schemaText(std::string_view english) {
    return builtinText(kSchemaTextContext, english);
}
inline QString integratorText(std::string_view english) {
    return builtinText(kIntegratorTextContext, english);
}

}  // namespace phasebox::ui
