#include "app/io/JsonText.h"

#include <QJsonParseError>
#include <QRegularExpression>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace phasebox::jsontext {

std::pair<int, int> lineAndColumn(const QByteArray& text, qsizetype offset) {
    offset = std::clamp<qsizetype>(offset, 0, text.size());
    int line = 1;
    int column = 1;
    for (qsizetype i = 0; i < offset; ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte == '\n') {
            ++line;
            column = 1;
        } else if ((byte & 0xC0) != 0x80) {  // not a UTF-8 continuation byte
            ++column;
        }
    }
    return {line, column};
}

// The offset of the first byte that cannot be part of JSON text: a control character other
// than tab, newline and carriage return (JSON allows them nowhere, not even in strings), or a
// byte that is not valid UTF-8. A binary file chosen by mistake is then reported as such
// instead of as an "illegal value" somewhere in it.
std::optional<qsizetype> firstNonTextByte(const QByteArray& text) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(text.constData());
    const qsizetype n = text.size();
    auto continuation = [&](qsizetype i, unsigned char low = 0x80, unsigned char high = 0xBF) {
        return i < n && bytes[i] >= low && bytes[i] <= high;
    };
    for (qsizetype i = 0; i < n;) {
        const unsigned char b = bytes[i];
        qsizetype length = 0;
        if (b < 0x20)
            length = (b == '\t' || b == '\n' || b == '\r') ? 1 : 0;
        else if (b < 0x80)
            length = 1;
        else if (b >= 0xC2 && b <= 0xDF)
            length = continuation(i + 1) ? 2 : 0;
        else if (b >= 0xE0 && b <= 0xEF) {
            // No overlong forms (E0 80..9F) and no UTF-16 surrogates (ED A0..BF).
            const unsigned char low = b == 0xE0 ? 0xA0 : 0x80, high = b == 0xED ? 0x9F : 0xBF;
            length = continuation(i + 1, low, high) && continuation(i + 2) ? 3 : 0;
        } else if (b >= 0xF0 && b <= 0xF4) {
            const unsigned char low = b == 0xF0 ? 0x90 : 0x80, high = b == 0xF4 ? 0x8F : 0xBF;
            length = continuation(i + 1, low, high) && continuation(i + 2) && continuation(i + 3)
                         ? 4
                         : 0;
        }
        if (length == 0) return i;
        i += length;
    }
    return std::nullopt;
}

namespace {

// The word or number around a syntax error's offset (Qt puts it at the start of NaN but after
// the end of 1e400), and where it starts.
std::pair<QByteArray, qsizetype> tokenAt(const QByteArray& text, qsizetype offset) {
    auto inToken = [&](qsizetype i) {
        const char c = text[i];
        return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
    };
    offset = std::clamp<qsizetype>(offset, 0, text.size());
    qsizetype start = offset, end = offset;
    while (start > 0 && inToken(start - 1)) --start;
    while (end < text.size() && inToken(end)) ++end;
    return {text.mid(start, end - start), start};
}

// Qt's syntax messages, made specific where Qt's own says little: JSON has no NaN or Infinity
// (a program writing a scene may print them), a number beyond the double range reads as
// "illegal number", and a file cut short ends in whatever Qt was reading at that moment.
SyntaxProblem syntaxProblem(const QByteArray& json, const QJsonParseError& error) {
    const QString qtMessage = error.errorString();
    if (error.error == QJsonParseError::IllegalNumber ||
        error.error == QJsonParseError::IllegalValue) {
        // These point at the start of the offending token.
        const auto [token, start] = tokenAt(json, error.offset);
        QByteArray word = token.toLower();
        if (word.startsWith('-') || word.startsWith('+')) word = word.mid(1);
        if (word == "nan" || word == "inf" || word == "infinity")
            return {start,
                    QStringLiteral("%1: %2 is not a number JSON allows; write a finite number")
                        .arg(qtMessage, shortened(QString::fromLatin1(token)))};
        static const QRegularExpression number(
            QStringLiteral("^-?(0|[1-9][0-9]*)(\\.[0-9]+)?([eE][+-]?[0-9]+)?$"));
        // A well-formed number that Qt still refuses is out of the double's range.
        if (error.error == QJsonParseError::IllegalNumber &&
            number.match(QString::fromLatin1(token)).hasMatch()) {
            const bool huge = std::isinf(std::strtod(token.constData(), nullptr));
            return {
                start,
                QStringLiteral("%1: %2 is %3")
                    .arg(qtMessage, shortened(QString::fromLatin1(token)),
                         huge ? QStringLiteral("beyond the range of numbers (about ±1.8e308)")
                              : QStringLiteral("too close to zero to be represented; write 0"))};
        }
    }
    // Qt 6 refuses a lone value (42, "text", true) at the top level as an "illegal value".
    qsizetype first = 0;
    while (first < json.size() && std::isspace(static_cast<unsigned char>(json[first]))) ++first;
    if (error.error == QJsonParseError::IllegalValue && first < json.size() &&
        std::strchr("-0123456789\"tfn", json[first]) != nullptr)
        return {first,
                QStringLiteral("the top level must be a JSON object {...}, not a single value")};
    if (error.error == QJsonParseError::DeepNesting)
        return {error.offset,
                qtMessage + QStringLiteral(" (more than 1024 levels of arrays and objects)")};
    // At the end of the text (trailing spaces aside) the file stopped mid-value: a truncated
    // download or an interrupted copy. An unterminated string already says so in its words.
    qsizetype end = json.size();
    while (end > 0 && std::isspace(static_cast<unsigned char>(json[end - 1]))) --end;
    if (end > 0 && error.offset >= end && error.error != QJsonParseError::UnterminatedString)
        return {error.offset,
                QStringLiteral("the file ends before the JSON is complete (is it truncated?)")};
    return {error.offset, qtMessage};
}

}  // namespace

std::optional<SyntaxProblem> parse(const QByteArray& text, QJsonDocument& document,
                                   ScanResult* scanned) {
    if (const auto bad = firstNonTextByte(text))
        return SyntaxProblem{
            *bad, QStringLiteral("binary data (byte 0x%1), not UTF-8 JSON text: "
                                 "is this a scene file?")
                      .arg(static_cast<unsigned char>(text[*bad]), 2, 16, QLatin1Char('0'))};
    ScanResult found = scan(text);
    if (found.problem) return found.problem;
    if (scanned) *scanned = std::move(found);
    QJsonParseError error;
    QJsonDocument parsed = QJsonDocument::fromJson(text, &error);
    if (error.error != QJsonParseError::NoError) return syntaxProblem(text, error);
    document = std::move(parsed);
    return std::nullopt;
}

}  // namespace phasebox::jsontext
