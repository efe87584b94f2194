#pragma once
// Shortest text that reads back as the same double (std::to_chars), for CSV and summaries.

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

}  // namespace phasebox
