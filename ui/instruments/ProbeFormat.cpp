#include "ui/instruments/ProbeFormat.h"

#include <QLocale>

#include <cmath>

namespace phasebox::ui {

QString probeUnit(ProbeKind kind) {
    switch (kind) {
        case ProbeKind::X:
        case ProbeKind::Y:
        case ProbeKind::SystemComX:
        case ProbeKind::SystemComY:
        case ProbeKind::Distance:
            return QStringLiteral("m");
        case ProbeKind::Vx:
        case ProbeKind::Vy:
        case ProbeKind::Speed:
            return QStringLiteral("m/s");
        case ProbeKind::Angle:
        case ProbeKind::AngleAt:
        case ProbeKind::JointAngle:
            return QStringLiteral("rad");
        case ProbeKind::Omega:
            return QStringLiteral("rad/s");
        case ProbeKind::Kinetic:
        case ProbeKind::SystemKinetic:
        case ProbeKind::SystemPotential:
        case ProbeKind::SystemTotal:
        case ProbeKind::SystemWorkNc:
        case ProbeKind::SystemDrift:
        case ProbeKind::SystemCorrection:
            return QStringLiteral("J");
        case ProbeKind::Px:
        case ProbeKind::Py:
        case ProbeKind::SystemPx:
        case ProbeKind::SystemPy:
            return QStringLiteral("kg·m/s");
        case ProbeKind::AngularMomentum:
        case ProbeKind::SystemAngularMomentum:
            return QStringLiteral("kg·m²/s");
        case ProbeKind::JointForce:
        case ProbeKind::ContactForce:
            return QStringLiteral("N");
    }
    return {};
}

QString probeTitle(const QString& text, ProbeKind kind) {
    return QStringLiteral("%1 [%2]").arg(text, probeUnit(kind));
}

QString formatReading(double value) {
    if (std::isnan(value)) return QStringLiteral("—");
    if (std::isinf(value)) return value > 0 ? QStringLiteral("∞") : QStringLiteral("−∞");
    const double size = std::abs(value);
    // In the app's locale (a decimal comma in German and French); files never use this.
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    QString text;
    if (size < 1e-12) {
        text = QStringLiteral("0");
    } else if (size >= 1e-3 && size < 1e6) {
        const int decimals = std::max(0, 4 - static_cast<int>(std::floor(std::log10(size))));
        text = locale.toString(value, 'f', decimals);
    } else {
        text = locale.toString(value, 'e', 4);
    }
    text.replace(QLatin1Char('-'), QChar(0x2212));
    return text;
}

}  // namespace phasebox::ui
