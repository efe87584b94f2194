#pragma once
// Text from a scene file shown in the window (its name, object ids, its description) may be
// anything the format accepts, e.g. a name that is one word of a million characters: laid out
// whole in a title, a label or a tree, that froze the app for minutes. What is shown is
// bounded here; the scene keeps the full text, and a save writes it unchanged.

#include <QChar>
#include <QString>

namespace phasebox::ui {

// Names, ids and paths in titles, labels, menus and trees: longer than this they are cut.
inline constexpr qsizetype kMaxShownName = 200;
// Descriptions (the Notes, tooltips): longer than this they are cut, with a note.
inline constexpr qsizetype kMaxShownDescription = 20'000;

// text cut to at most maxChars characters, ending in "…" when cut (never in the middle of a
// surrogate pair).
inline QString shownText(const QString& text, qsizetype maxChars = kMaxShownName) {
    if (text.size() <= maxChars) return text;
    qsizetype keep = maxChars > 1 ? maxChars - 1 : 0;
    if (keep > 0 && text.at(keep - 1).isHighSurrogate()) --keep;
    return text.left(keep) + QChar(0x2026);
}

// A description cut to kMaxShownDescription characters, saying how much more the file holds.
inline QString shownDescription(const QString& text) {
    if (text.size() <= kMaxShownDescription) return text;
    return shownText(text, kMaxShownDescription) +
           QStringLiteral(" [%1 more characters in the file]")
               .arg(text.size() - kMaxShownDescription + 1);
}

}  // namespace phasebox::ui
