#include "ui/plots/Charts.h"

#include "ui/canvas/Appearance.h"
#include "ui/plots/ProbeChart.h"

#include <QAbstractAxis>
#include <QBuffer>
#include <QCategoryAxis>
#include <QChart>
#include <QCoreApplication>
#include <QGraphicsScene>
#include <QImage>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPainter>
#include <QPen>
#include <QScatterSeries>
#include <QSvgGenerator>
#include <QValueAxis>
#include <QXYSeries>

#include <algorithm>
#include <cmath>
#include <limits>

namespace phasebox::ui {

namespace {
// The charts' words in the app's language; the command line installs no translation, so the
// plots it writes stay English.
QString chartText(const char* english) {
    return QCoreApplication::translate("Charts", english);
}
// Time runs exactly over the samples: padding or rounding it out would show times that never were.
void fitTimeAxis(QValueAxis* axis, double lo, double hi) {
    if (!(hi > lo)) hi = lo + 1.0;
    axis->setRange(lo, hi);
    axis->setLabelFormat(QStringLiteral("%.3g"));
}

void fitAxis(QValueAxis* axis, double lo, double hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) lo = hi = 0.0;
    if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) {
        const double pad = std::max(1e-9, std::abs(hi) * 0.1 + 1e-3);
        lo -= pad;
        hi += pad;
    } else {
        const double pad = 0.05 * (hi - lo);
        lo -= pad;
        hi += pad;
    }
    axis->setRange(lo, hi);
    axis->applyNiceNumbers();
    axis->setLabelFormat(QStringLiteral("%.4g"));
}

QLineSeries* addSeries(QChart* chart, const QVector<QPointF>& points, const QString& name,
                       const QColor& color, qreal width = 2.0, Qt::PenStyle style = Qt::SolidLine) {
    auto* series = new QLineSeries(chart);
    series->setName(name);
    series->replace(decimate(points));
    QPen pen(color);
    pen.setWidthF(width);
    pen.setStyle(style);
    series->setPen(pen);
    chart->addSeries(series);
    return series;
}

void attach(QChart* chart, QValueAxis* x, QValueAxis* y) {
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    for (QAbstractSeries* s : chart->series()) {
        s->attachAxis(x);
        s->attachAxis(y);
    }
}

std::optional<QLocale>& storedChartLocale() {
    static std::optional<QLocale> locale;
    return locale;
}

QChart* newChart(const QString& title) {
    auto* chart = new QChart;
    applyChartLocale(chart);
    chart->setTitle(title);
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->legend()->setAlignment(Qt::AlignBottom);
    chart->setBackgroundRoundness(0);
    return chart;
}
}  // namespace

QString powerOfTen(int exponent) {
    static const char16_t digits[] = u"⁰¹²³⁴⁵⁶⁷⁸⁹";
    QString power;
    for (int n = std::abs(exponent); n > 0 || power.isEmpty(); n /= 10)
        power.prepend(QChar(digits[n % 10]));
    if (exponent < 0) power.prepend(QChar(u'⁻'));
    const QLocale locale = storedChartLocale().value_or(QLocale::c());
    return locale.toString(10) + power;
}

QCategoryAxis* createDecadeAxis(double lo, double hi, int step) {
    auto* axis = new QCategoryAxis;
    axis->setRange(lo, hi);
    step = std::max(step, 1);
    // The categories end at the labelled powers; the first starts below the range, so that a
    // power at lo is labelled too.
    axis->setStartValue(lo - step);
    axis->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
    axis->setMinorTickCount(0);
    // Whole powers that are multiples of step, as a value axis anchored at 0 would tick them.
    for (int n = static_cast<int>(std::ceil(lo / step)) * step; n <= hi; n += step)
        axis->append(powerOfTen(n), n);
    return axis;
}

void setChartLocale(const std::optional<QLocale>& locale) {
    auto& stored = storedChartLocale();
    stored = locale;
    if (stored) stored->setNumberOptions(stored->numberOptions() | QLocale::OmitGroupSeparator);
}

const std::optional<QLocale>& chartLocale() {
    return storedChartLocale();
}

void applyChartLocale(QChart* chart) {
    if (const std::optional<QLocale>& locale = storedChartLocale(); locale && chart) {
        chart->setLocale(*locale);
        chart->setLocalizeNumbers(true);
    }
}

namespace {
void addCursor(QChart* chart, QXYSeries* cursor, const QList<QPointF>& points) {
    const QList<QAbstractAxis*> x = chart->axes(Qt::Horizontal);
    const QList<QAbstractAxis*> y = chart->axes(Qt::Vertical);
    if (x.isEmpty() || y.isEmpty()) {
        delete cursor;
        return;
    }
    cursor->setName(QLatin1String(kCursorName));
    cursor->append(points);
    chart->addSeries(cursor);
    cursor->attachAxis(x.first());
    cursor->attachAxis(y.first());
    // The legend names what was computed, not where the timeline is.
    cursor->setProperty(kNoLegend, true);
    if (QLegend* legend = chart->legend())
        for (QLegendMarker* m : legend->markers(cursor)) m->setVisible(false);
}
}  // namespace

void addTimeCursor(QChart* chart, double t, const QColor& colour) {
    const auto* y = qobject_cast<QValueAxis*>(chart->axes(Qt::Vertical).value(0));
    if (!y || !std::isfinite(t)) return;
    auto* line = new QLineSeries;
    line->setPen(QPen(colour, 1.5, Qt::DashLine));
    addCursor(chart, line, {{t, y->min()}, {t, y->max()}});
}

void addPointCursor(QChart* chart, QPointF point, const QColor& colour) {
    if (!std::isfinite(point.x()) || !std::isfinite(point.y())) return;
    auto* dot = new QScatterSeries;
    dot->setMarkerSize(11.0);
    dot->setColor(colour);
    addCursor(chart, dot, {point});
}

QVector<QPointF> chartCursor(const QChart* chart) {
    if (!chart) return {};
    for (QAbstractSeries* s : chart->series())
        if (s->name() == QLatin1String(kCursorName))
            if (const auto* series = qobject_cast<const QXYSeries*>(s)) return series->points();
    return {};
}

QColor energyColor(int series) {
    // Okabe–Ito hues (ui/canvas/Appearance.h): kinetic blue against potential orange, drift
    // vermillion against correction's bluish green, which is dashed as well, and work_nc's
    // reddish purple dash-dotted: no two lines differ in red against green alone. On the
    // high-contrast theme's black the total is white and drift yellow.
    const bool dark = chartAppearance().highContrast;
    const QColor colors[] = {dark ? okabeIto::skyBlue : okabeIto::blue,
                             okabeIto::orange,
                             dark ? QColor(0xff, 0xff, 0xff) : QColor(0x20, 0x20, 0x20),
                             okabeIto::reddishPurple,
                             dark ? okabeIto::yellow : okabeIto::vermillion,
                             okabeIto::bluishGreen};
    return colors[std::clamp(series, 0, 5)];
}

void applyChartAppearance(QChart* chart) {
    const Appearance& a = chartAppearance();
    if (a == Appearance{} || !chart) return;
    const auto scaled = [&](QFont font) {
        font.setPointSizeF(font.pointSizeF() * a.textScale);
        return font;
    };
    const QColor ink = a.highContrast ? QColor(0xff, 0xff, 0xff) : QColor(0x20, 0x20, 0x20);
    if (a.highContrast) {
        chart->setBackgroundBrush(QColor(0x00, 0x00, 0x00));
        chart->setPlotAreaBackgroundVisible(false);
        chart->setTitleBrush(ink);
        chart->legend()->setLabelColor(ink);
    }
    chart->setTitleFont(scaled(chart->titleFont()));
    chart->legend()->setFont(scaled(chart->legend()->font()));
    for (QAbstractAxis* axis : chart->axes()) {
        axis->setLabelsFont(scaled(axis->labelsFont()));
        axis->setTitleFont(scaled(axis->titleFont()));
        if (a.highContrast) {
            axis->setLabelsColor(ink);
            axis->setTitleBrush(ink);
            axis->setLinePenColor(QColor(0xc0, 0xc0, 0xc0));
            axis->setGridLineColor(QColor(0x48, 0x48, 0x48));
            axis->setMinorGridLineColor(QColor(0x30, 0x30, 0x30));
        }
    }
    for (QAbstractSeries* s : chart->series()) {
        auto* line = qobject_cast<QXYSeries*>(s);
        if (!line) continue;
        QPen pen = line->pen();
        pen.setWidthF(pen.widthF() * a.lineScale);
        // Dark strokes (the total, markers) turn light on black.
        if (a.highContrast && pen.color().lightnessF() < 0.35)
            pen.setColor(QColor::fromHslF(pen.color().hslHueF(), pen.color().hslSaturationF(),
                                          1.0 - pen.color().lightnessF()));
        line->setPen(pen);
        line->setMarkerSize(line->markerSize() * a.lineScale);
    }
}

QVector<QPointF> decimate(const QVector<QPointF>& points, int maxPoints) {
    if (points.size() <= maxPoints || maxPoints < 4) return points;
    const int buckets = maxPoints / 2;
    QVector<QPointF> out;
    out.reserve(2 * buckets + 1);
    const qsizetype n = points.size();
    for (int b = 0; b < buckets; ++b) {
        const qsizetype begin = n * b / buckets, end = n * (b + 1) / buckets;
        if (begin >= end) continue;
        qsizetype lo = begin, hi = begin;
        for (qsizetype i = begin; i < end; ++i) {
            if (points[i].y() < points[lo].y()) lo = i;
            if (points[i].y() > points[hi].y()) hi = i;
        }
        out.push_back(points[std::min(lo, hi)]);
        if (lo != hi) out.push_back(points[std::max(lo, hi)]);
    }
    if (out.back() != points.back()) out.push_back(points.back());
    return out;
}

QChart* createEnergyChart(std::span<const EnergySample> samples,
                          std::span<const PlotMarker> markers, const QString& title) {
    // The ledger's lines in the order of CONTRACT §6 (correction after drift). Correction is
    // dashed: it is not energy the bodies hold but what the push-out put in or took out.
    struct Line {
        const char* name;
        double (*value)(const EnergySample&);
        qreal width;
        Qt::PenStyle style;
    };
    static constexpr Line lines[] = {
        {QT_TRANSLATE_NOOP("Charts", "kinetic"), [](const EnergySample& e) { return e.kinetic; },
         1.8, Qt::SolidLine},
        {QT_TRANSLATE_NOOP("Charts", "potential"),
         [](const EnergySample& e) { return e.potential; }, 1.8, Qt::SolidLine},
        {QT_TRANSLATE_NOOP("Charts", "total"),
         [](const EnergySample& e) { return e.kinetic + e.potential; }, 2.5, Qt::SolidLine},
        {QT_TRANSLATE_NOOP("Charts", "work_nc"), [](const EnergySample& e) { return e.workNc; },
         1.8, Qt::DashDotLine},
        {QT_TRANSLATE_NOOP("Charts", "drift"), [](const EnergySample& e) { return e.drift; }, 1.8,
         Qt::SolidLine},
        {QT_TRANSLATE_NOOP("Charts", "correction"),
         [](const EnergySample& e) { return e.correction; }, 2.0, Qt::DashLine},
    };
    constexpr int kLines = static_cast<int>(std::size(lines));
    QChart* chart = newChart(title);
    QVector<QPointF> series[kLines];
    for (auto& s : series) s.reserve(static_cast<qsizetype>(samples.size()));
    double tMin = 0.0, tMax = 0.0;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const EnergySample& e : samples) {
        for (int k = 0; k < kLines; ++k) {
            const double v = lines[k].value(e);
            series[k].push_back({e.t, v});
            if (std::isfinite(v)) {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
        }
    }
    if (!samples.empty()) {
        tMin = samples.front().t;
        tMax = samples.back().t;
    }
    for (int k = 0; k < kLines; ++k)
        addSeries(chart, series[k], chartText(lines[k].name), energyColor(k), lines[k].width,
                  lines[k].style);
    // The legend draws each line's own pen, so correction is dashed there too.
    chart->legend()->setMarkerShape(QLegend::MarkerShapeFromSeries);
    auto* x = new QValueAxis;
    x->setTitleText(chartText(QT_TRANSLATE_NOOP("Charts", "time [s]")));
    auto* y = new QValueAxis;
    y->setTitleText(chartText(QT_TRANSLATE_NOOP("Charts", "energy [J]")));
    fitTimeAxis(x, tMin, tMax);
    // Ticks on whole multiples of 1, 2 or 5 × 10^k, labelled with as many decimals as the step
    // needs: "14000, 16000" where printf's %g would write "1.4e+04" (ProbeChart.h).
    const auto [ylo, yhi] = paddedRange(lo, hi);
    applyNiceTicks(y, ylo, yhi, 5);
    for (const PlotMarker& m : markers)
        addSeries(chart, {{m.t, y->min()}, {m.t, y->max()}}, m.label, QColor(0x80, 0x80, 0x80), 1.2,
                  Qt::DashLine);
    attach(chart, x, y);
    applyChartAppearance(chart);
    return chart;
}

QChart* createErrorChart(std::span<const QPointF> samples, const QString& title) {
    QChart* chart = newChart(title);
    QVector<QPointF> points;
    points.reserve(static_cast<qsizetype>(samples.size()));
    double tlo = std::numeric_limits<double>::infinity(), thi = -tlo, elo = tlo, ehi = -tlo;
    for (const QPointF& p : samples) {
        if (!(p.y() > 0.0) || !std::isfinite(p.y())) continue;
        points.push_back({p.x(), std::log10(p.y())});  // the error axis holds log10 of the error
        tlo = std::min(tlo, p.x());
        thi = std::max(thi, p.x());
        elo = std::min(elo, p.y());
        ehi = std::max(ehi, p.y());
    }
    auto* series =
        addSeries(chart, points, chartText(QT_TRANSLATE_NOOP("Charts", "local error per step")),
                  energyColor(4), 1.6);
    chart->legend()->setVisible(false);
    auto* t = new QValueAxis;
    t->setTitleText(chartText(QT_TRANSLATE_NOOP("Charts", "time [s]")));
    fitTimeAxis(t, std::isfinite(tlo) ? tlo : 0.0, std::isfinite(thi) ? thi : 1.0);
    if (!std::isfinite(elo)) elo = ehi = 1e-6;
    // Whole decades around the samples, so the axis reads as orders of magnitude.
    auto* e = createDecadeAxis(std::floor(std::log10(elo)),
                               std::ceil(std::log10(ehi)) + (ehi == elo ? 1 : 0));
    e->setTitleText(chartText(QT_TRANSLATE_NOOP("Charts", "error [m]")));
    chart->addAxis(t, Qt::AlignBottom);
    chart->addAxis(e, Qt::AlignLeft);
    series->attachAxis(t);
    series->attachAxis(e);
    applyChartAppearance(chart);
    return chart;
}

QChart* createPhaseChart(std::span<const PhaseSample> samples, const QString& coordinateName,
                         const QString& velocityName, const QString& title,
                         std::span<const PhaseSample> exact, const QString& exactName) {
    QChart* chart = newChart(title);
    QVector<QPointF> points;
    points.reserve(static_cast<qsizetype>(samples.size()));
    double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
    const auto include = [&](const PhaseSample& s) {
        if (std::isfinite(s.coordinate) && std::isfinite(s.velocity)) {
            xlo = std::min(xlo, s.coordinate);
            xhi = std::max(xhi, s.coordinate);
            ylo = std::min(ylo, s.velocity);
            yhi = std::max(yhi, s.velocity);
        }
    };
    for (const PhaseSample& s : samples) {
        points.push_back({s.coordinate, s.velocity});
        include(s);
    }
    // A phase portrait is a curve, not a function of x: thin it by stride, not by buckets.
    if (points.size() > kMaxPlotPoints) {
        QVector<QPointF> thinned;
        const qsizetype stride = (points.size() + kMaxPlotPoints - 1) / kMaxPlotPoints;
        for (qsizetype i = 0; i < points.size(); i += stride) thinned.push_back(points[i]);
        thinned.push_back(points.back());
        points = std::move(thinned);
    }
    auto* series = new QLineSeries(chart);
    // The axes name the coordinates; the legend says which curve is which.
    series->setName(exact.empty() ? coordinateName + QStringLiteral(" – ") + velocityName
                                  : chartText(QT_TRANSLATE_NOOP("Charts", "simulation")));
    series->replace(points);
    QPen pen(energyColor(0));
    pen.setWidthF(1.8);
    series->setPen(pen);
    chart->addSeries(series);
    if (!points.isEmpty()) {
        auto* start = new QLineSeries(chart);
        start->setName(chartText(QT_TRANSLATE_NOOP("Charts", "start")));
        start->append(points.front());
        start->setPointsVisible(true);
        start->setMarkerSize(9);
        start->setColor(energyColor(4));
        chart->addSeries(start);
    }
    if (!exact.empty()) {
        // Dashed over the simulation's curve, which it should be seen to follow or leave.
        auto* reference = new QLineSeries(chart);
        reference->setName(exactName);
        QVector<QPointF> exactPoints;
        exactPoints.reserve(static_cast<qsizetype>(exact.size()));
        for (const PhaseSample& s : exact) {
            exactPoints.push_back({s.coordinate, s.velocity});
            include(s);
        }
        reference->replace(exactPoints);
        reference->setPen(QPen(QColor(0xd0, 0x60, 0x10), 1.6, Qt::DashLine));
        chart->addSeries(reference);
    }
    auto* x = new QValueAxis;
    x->setTitleText(coordinateName);
    auto* y = new QValueAxis;
    y->setTitleText(velocityName);
    fitAxis(x, xlo, xhi);
    fitAxis(y, ylo, yhi);
    attach(chart, x, y);
    applyChartAppearance(chart);
    return chart;
}

qreal legendRowWidth(const QChart* chart) {
    QLegend* legend = chart->legend();
    const QFontMetricsF metrics(legend->font());
    qreal row = 4.0 * metrics.height();  // the chart's and the legend's own margins
    for (QLegendMarker* marker : legend->markers()) {
        if (!marker->series() || marker->series()->property(kNoLegend).toBool()) continue;
        // Label, marker (a line 1.5 font heights long) and the gaps around them.
        row += metrics.horizontalAdvance(marker->label()) + 4.0 * metrics.height();
    }
    return row;
}

namespace {
// Qt cuts a bottom legend's labels to "ki…" when its one row is wider than the chart: down the
// side they show whole.
void fitLegendTo(QChart* chart, qreal width) {
    if (chart->legend()->isVisible() && legendRowWidth(chart) > width)
        chart->legend()->setAlignment(Qt::AlignRight);
}
}  // namespace

QByteArray renderChart(QChart* chart, const QString& format, QSize size) {
    fitLegendTo(chart, size.width());
    const bool png = format.compare(QLatin1String("png"), Qt::CaseInsensitive) == 0;
    if (!png && format.compare(QLatin1String("svg"), Qt::CaseInsensitive) != 0) return {};
    // Render through a scene: a chart needs one to lay itself out, but no view or window.
    QGraphicsScene scene;
    scene.addItem(chart);
    chart->setGeometry(QRectF(QPointF(0, 0), size));
    scene.setSceneRect(QRectF(QPointF(0, 0), size));
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    if (png) {
        QImage image(size, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::white);
        {
            QPainter painter(&image);
            painter.setRenderHint(QPainter::Antialiasing);
            scene.render(&painter);
        }
        if (!image.save(&buffer, "PNG")) buffer.buffer().clear();
    } else {
        QSvgGenerator svg;
        svg.setOutputDevice(&buffer);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(chart->title());
        QPainter painter(&svg);
        scene.render(&painter);
    }
    scene.removeItem(chart);
    return buffer.data();
}

void paintChart(QChart* chart, QPainter& painter, const QRectF& target) {
    fitLegendTo(chart, target.width());
    QGraphicsScene scene;
    scene.addItem(chart);
    const QRectF area(QPointF(0, 0), target.size());
    chart->setGeometry(area);
    scene.setSceneRect(area);
    painter.save();
    painter.fillRect(target, Qt::white);
    painter.setRenderHint(QPainter::Antialiasing);
    scene.render(&painter, target, area);
    painter.restore();
    scene.removeItem(chart);
}

}  // namespace phasebox::ui
