#pragma once
// The work-precision diagram of the accuracy study: log10 of the position error against log10
// of the CPU time, one line per integrator, each point labelled by its dt (or tolerance).
// Lower left is better: accurate and cheap. The same chart serves the app's Accuracy dialog and
// `phasebox-cli accuracy --plot`.

#include <QString>

#include <span>

QT_BEGIN_NAMESPACE
class QChart;
class QFont;
QT_END_NAMESPACE

namespace phasebox::ui {

// One run of the study, as the chart needs it (ui/ does not know the app's record type).
struct WorkPrecisionPoint {
    QString integrator;  // the registry name; points of one integrator form one line, in order
    double cpuSeconds = 0.0;
    // Points whose error is not finite and > 0 are left out (log axis); the legend counts
    // the diverged ones (error +∞).
    double error = 0.0;
    QString label;  // shown next to the point: "1/120", "tol 1e-4"
};

// The axis titles, spelled once: tests and the dialog's caption refer to them.
QString workPrecisionErrorTitle();  // "position error [m], lower is better"
QString workPrecisionTimeTitle();   // "CPU time [s], left is faster"

// Line styles follow the registry: solid explicit, dashed implicit, dotted adaptive; each
// integrator keeps its colour in every diagram. Text follows `font` (the widget's, larger in
// presentation mode): tick labels and legend at its size, titles bold, dt labels a little
// smaller. Tick labels read 10⁻⁶, not -6: the axes are log10 of the values.
QChart* createWorkPrecisionChart(std::span<const WorkPrecisionPoint> points, const QString& title,
                                 const QFont& font);
QChart* createWorkPrecisionChart(std::span<const WorkPrecisionPoint> points, const QString& title);
// The text sizes of a chart made above, again from `font` (the dialog makes the text larger as
// the diagram grows); the dt labels are placed anew.
void setWorkPrecisionFont(QChart* chart, const QFont& font);

}  // namespace phasebox::ui
