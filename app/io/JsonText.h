#pragma once
// The text layer under the scene loader: whether a file is JSON text at all, and where and
// what a syntax error is, in words a teacher can act on ("NaN is not a number JSON allows",
// "the file ends before the JSON is complete") rather than Qt's terse ones.

#include <QByteArray>
#include <QJsonDocument>
#include <QString>

#include <optional>
#include <utility>

namespace phasebox::jsontext {

// 1-based line and column of a byte offset into UTF-8 text. The column counts characters,
// not bytes, because that is what editors show.
std::pair<int, int> lineAndColumn(const QByteArray& text, qsizetype offset);

// The offset of the first byte that cannot be part of JSON text (a control character other
// than tab, newline and carriage return, or a byte that is not valid UTF-8), or nothing.
std::optional<qsizetype> firstNonTextByte(const QByteArray& text);

struct SyntaxProblem {
    qsizetype offset = 0;  // into the text, for lineAndColumn
    QString what;
};

// Parses text into *document; on failure returns where and what without touching *document.
std::optional<SyntaxProblem> parse(const QByteArray& text, QJsonDocument& document);

}  // namespace phasebox::jsontext
