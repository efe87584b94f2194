#pragma once
// How the instruments write a probe's value: its unit (SI, from CONTRACT §7) and a reading of
// five significant digits that does not jump about as the value changes.

#include "physics/world/Probes.h"

#include <QString>

namespace phasebox::ui {

// "m", "m/s", "rad", "rad/s", "J", "kg·m/s", "kg·m²/s" or "N".
QString probeUnit(ProbeKind kind);

// An axis or column title: "p0.x [m]".
QString probeTitle(const QString& text, ProbeKind kind);

// Five significant digits, fixed-point between 1e-3 and 1e6 (−0.012346, 123.46), scientific
// outside (1.2346e-05), "0" for what is zero to rounding (below 1e-12), a true minus sign.
QString formatReading(double value);

}  // namespace phasebox::ui
