#pragma once
// The text layer under the scene loader: whether a file is JSON text at all, and where and
// what a syntax error is, in words a teacher can act on ("NaN is not a number JSON allows",
// "the file ends before the JSON is complete") rather than Qt's terse ones.

#include <QByteArray>
#include <QJsonDocument>
#include <QString>

#include <optional>
#include <utility>
#include <vector>

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

// A key given twice in one object. Qt's reader keeps the last silently, which would drop the
// first value without a word (a teacher's spring losing its stiffness).
struct DuplicateKey {
    QString path;         // JSON path of the key, e.g. particles[0].mass
    qsizetype first = 0;  // offsets of the two occurrences, for lineAndColumn
    qsizetype second = 0;
};

// What a pass over the raw text finds that Qt's parser hides or misreports.
struct ScanResult {
    // What the JSON grammar forbids and Qt misreports or accepts: a number such as 0x10, 01,
    // +1, .5, 1. or 1e (Qt calls most of them an "unterminated object" somewhere else), a
    // comment or a single-quoted string (the same), and an invalid escape such as \l, which Qt
    // accepts and drops ("C:\lessons" read as "C:lessons"). The first one, where it starts.
    std::optional<SyntaxProblem> problem;
    // The first kMaxReportedDuplicates duplicate keys, and how many there are in all.
    std::vector<DuplicateKey> duplicates;
    long long duplicateCount = 0;
};
inline constexpr int kMaxReportedDuplicates = 10;

// Scans the text once. It stops quietly at any other syntax error (leaving it to Qt's parser
// and its messages), so it reports only what comes before the first such error.
ScanResult scan(const QByteArray& text);

// A token for a message: as it is up to about 40 characters, else its first 40 and its length,
// so that a 20 MB number or key is never echoed whole.
QString shortened(const QString& token);

// Parses text into *document; on failure returns where and what without touching *document.
// Duplicate keys do not stop the parse: they are added to *duplicates (when given) for the
// caller to report with their JSON paths.
std::optional<SyntaxProblem> parse(const QByteArray& text, QJsonDocument& document,
                                   ScanResult* scanned = nullptr);

}  // namespace phasebox::jsontext
