#pragma once
// The instruments' graphs: one probe against time or against another probe, as a Qt Chart with
// readable ticks. The same chart serves the Instruments dock and the graphs' PNG and SVG export
// (ui::renderChart, written by app/io/ChartFile), so a saved graph is the graph on screen.
//
// Ticks fall on whole multiples of a step of 1, 2 or 5 × 10^k (QValueAxis::TicksDynamic), with
// as many decimals as the step needs: "0, 0.5, 1, 1.5" rather than Qt's default division of the
// range into equal parts ("0, 0.37, 0.74, …").

#include <QPointF>
#include <QString>
#include <QVector>

#include <utility>

QT_BEGIN_NAMESPACE
class QChart;
class QValueAxis;
QT_END_NAMESPACE

namespace phasebox::ui {

// A tick spacing of 1, 2 or 5 × 10^k that divides [lo, hi] into at most maxTicks intervals (and
// at least maxTicks/2.5), the first tick at or above lo, and the printf format of its labels.
struct NiceTicks {
    double step = 1.0;
    double first = 0.0;
    QString labelFormat = QStringLiteral("%.0f");
};
NiceTicks niceTicks(double lo, double hi, int maxTicks = 6);

// Sets the axis to [lo, hi] with nice ticks.
void applyNiceTicks(QValueAxis* axis, double lo, double hi, int maxTicks = 6);

// The range a value axis shows for samples in [lo, hi]: 5% of room on either side; a constant
// (a conserved momentum, to rounding) gets ±10% of its size (±1 about zero) so that it reads as
// a flat line at its value, not as noise magnified to fill the plot.
std::pair<double, double> paddedRange(double lo, double hi);

// A probe's samples as a line: y against time (timeAxis: the axis runs exactly over the samples)
// or against another probe (a curve: both axes padded). Non-finite points are left out, and a
// long series is thinned to kMaxPlotPoints (Charts.h). An empty title leaves the room to the plot;
// maxXTicks is as many x labels as the view's width holds whole, maxYTicks as many y labels as
// its height does (Qt Charts elides a label taller than its room to "…").
QChart* createProbeChart(const QVector<QPointF>& points, const QString& xTitle,
                         const QString& yTitle, const QString& title, bool timeAxis,
                         int maxXTicks = 6, int maxYTicks = 6);

}  // namespace phasebox::ui
