#pragma once
// Shortest text that reads back as the same double (std::to_chars), for CSV and summaries,
// and CSV fields quoted as RFC 4180 asks.

#include <QString>

#include <charconv>
#include <cmath>

namespace phasebox {

inline QString formatNumber(double value) {
    if (std::isnan(value)) return QStringLiteral("nan");
    if (std::isinf(value)) return value > 0 ? QStringLiteral("inf") : QStringLiteral("-inf");
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return QString::fromLatin1(buffer, static_cast<qsizetype>(result.ptr - buffer));
}

// A CSV field: as it is, or quoted when it holds a comma, a quote or a line break (a cloth
// node's column "flag[1,0].x" would otherwise split in two).
inline QString csvField(const QString& text) {
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) &&
        !text.contains(QLatin1Char('\n')))
        return text;
    QString quoted = text;
    quoted.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

}  // namespace phasebox
