#pragma once
// The texts the app shows that are data, not code: the built-in scenes' and lessons' names and
// notes (resources/, compiled in as :/scenes and :/lessons), the schema's field labels and
// effect descriptions and the object kinds' names (physics/scene, which has no Qt), the
// integrators' names and summaries.
// lupdate cannot see them, so they are listed here, once, from their sources: the
// update_translations target writes them as a lupdate-readable file (phasebox-texts), and the
// translations test checks that each has a translation in every language.
//
// Each lives in a context of its own, translated by its English text at the place it is shown
// (ui/panels/BuiltinText.h).

#include <QString>

#include <vector>

namespace phasebox::i18n {

struct BuiltinText {
    const char* context;
    QString text;
    QString origin;  // where it comes from, for the translator and the test's messages
};

// Every such text, each (context, text) pair once, in a stable order.
std::vector<BuiltinText> builtinTexts();

// A C++ file of QT_TRANSLATE_NOOP entries that lupdate reads (it is never compiled).
QString lupdateSource(const std::vector<BuiltinText>& texts);

}  // namespace phasebox::i18n
