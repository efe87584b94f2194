#pragma once
// The plots Phasebox shows, as Qt Charts built from plain samples: energy against time and
// phase space. The same code serves the app's live plots, picture export and
// `phasebox-cli run --plot-energy/--plot-phase`, so a saved plot is what the app shows.

#include <QByteArray>
#include <QColor>
#include <QLocale>
#include <QPointF>
#include <QSize>
#include <QString>
#include <QVector>

#include <optional>
#include <span>

QT_BEGIN_NAMESPACE
class QCategoryAxis;
class QChart;
class QPainter;
class QRectF;
QT_END_NAMESPACE

namespace phasebox::ui {

struct EnergySample {
    double t = 0.0;
    double kinetic = 0.0;
    double potential = 0.0;
    double workNc = 0.0;
    double drift = 0.0;
    double correction = 0.0;  // position correction's energy, apart from work_nc (CONTRACT §6)
};

// A labelled vertical marker, e.g. where the integrator or dt changed.
struct PlotMarker {
    double t = 0.0;
    QString label;
};

struct PhaseSample {
    double coordinate = 0.0;
    double velocity = 0.0;
};

// At most this many points per series are drawn; longer series are decimated.
inline constexpr int kMaxPlotPoints = 4000;

// Keeps the shape of a long series: for each of maxPoints/2 buckets, its minimum and maximum
// in order, so spikes survive. Series shorter than maxPoints are returned as they are.
QVector<QPointF> decimate(const QVector<QPointF>& points, int maxPoints = kMaxPlotPoints);

// The energy plot: kinetic, potential, total, work_nc, drift and correction (dashed) against
// time, with markers.
QChart* createEnergyChart(std::span<const EnergySample> samples,
                          std::span<const PlotMarker> markers, const QString& title);

// Phase space of one coordinate against its velocity, with the exact solution's curve over the
// same times dashed beside it when there is one (exactName names it in the legend).
QChart* createPhaseChart(std::span<const PhaseSample> samples, const QString& coordinateName,
                         const QString& velocityName, const QString& title,
                         std::span<const PhaseSample> exact = {}, const QString& exactName = {});

// The live local error estimate against time, on a logarithmic error axis (non-positive and
// non-finite samples are left out: a log axis cannot show them).
QChart* createErrorChart(std::span<const QPointF> samples, const QString& title);

// A chart drawn as a PNG or SVG file's bytes (format "png" or "svg"); empty for another
// format or when drawing fails. Needs a QApplication (the offscreen platform is enough). The
// app writes them through its one file writer (app/io/OutputFile, app/io/ChartFile).
QByteArray renderChart(QChart* chart, const QString& format, QSize size);
// A chart drawn on a white background into target of painter (a clip's plots beside its
// canvas); the same layout as renderChart at target's size.
void paintChart(QChart* chart, QPainter& painter, const QRectF& target);
// The width a legend along the bottom takes in one row: its labels, their markers and the
// gaps, and the chart's and the legend's margins.
qreal legendRowWidth(const QChart* chart);

// Gives a finished chart the app's appearance (ui/canvas/Appearance.h: high contrast, line and
// text scales); nothing with the default appearance, which the command line keeps.
void applyChartAppearance(QChart* chart);

// The locale of the charts' tick labels from now on. None, the default and the command line's,
// writes them as C's printf does, with a decimal point; the app sets its language's, so that a
// German axis reads "1,5" like the rest of the window. A chart's CSV never uses it.
void setChartLocale(const std::optional<QLocale>& locale);
const std::optional<QLocale>& chartLocale();
// Gives a new chart that locale's tick labels (nothing while none is set).
void applyChartLocale(QChart* chart);

// 10ⁿ as a reader writes it ("10⁻⁶", "10³"), the 10 in the charts' locale's digits: the tick
// labels of the log axes in every language (Qt Charts' own log axis writes printf's "1e-06",
// or the locale's "1E-06").
QString powerOfTen(int exponent);
// An axis over log10 of the values, from lo to hi (log10 units), labelled powerOfTen at every
// step-th whole power of ten between them, with a grid line there.
QCategoryAxis* createDecadeAxis(double lo, double hi, int step = 1);

// The moment the timeline shows, marked in a chart (the plots and the instruments' graphs): a
// series named kCursorName on the chart's own axes that no legend names (its kNoLegend property
// set: a legend marker's own visibility cannot say it, a marker reads as hidden while its legend
// is, or before it is laid out). addTimeCursor draws a dashed vertical line at time t across the
// vertical axis's range, addPointCursor a dot at the state then (a phase or probe-against-probe
// curve); neither draws anything on a chart without axes.
inline constexpr char kCursorName[] = "cursor";
inline constexpr char kNoLegend[] = "phaseboxNoLegend";
void addTimeCursor(QChart* chart, double t, const QColor& colour);
void addPointCursor(QChart* chart, QPointF point, const QColor& colour);
// The cursor's points in a chart: empty when it has none.
QVector<QPointF> chartCursor(const QChart* chart);

// The series colours, shared with the app's legends.
// 0 kinetic, 1 potential, 2 total, 3 work_nc, 4 drift, 5 correction.
QColor energyColor(int series);

}  // namespace phasebox::ui
