#include "ui/plots/ProbeChart.h"

#include "ui/plots/Charts.h"

#include <QChart>
#include <QLegend>
#include <QLineSeries>
#include <QPen>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace phasebox::ui {

namespace {
// Below this spread relative to its size, a series is a constant to rounding.
constexpr double kConstantRelative = 1e-9;
// Below this size, a value is zero to rounding (a free system's momentum of 1e-17).
constexpr double kZeroAbsolute = 1e-12;
}  // namespace

NiceTicks niceTicks(double lo, double hi, int maxTicks) {
    NiceTicks ticks;
    maxTicks = std::max(maxTicks, 2);
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) {
        ticks.first = std::isfinite(lo) ? std::floor(lo) : 0.0;
        return ticks;
    }
    // The smallest of 1, 2, 5 × 10^k that puts at most maxTicks + 1 ticks in [lo, hi]. A step of
    // (hi − lo)/maxTicks or more always does; a smaller one may too (ticks 0, 2, 4 in [−0.2, 4.1]
    // at maxTicks 2, where the step of 5 would leave the single tick 0).
    const double raw = (hi - lo) / maxTicks;
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    const auto tickCount = [&](double step) {
        return std::floor(hi / step + 1e-9) - std::ceil(lo / step - 1e-9) + 1.0;
    };
    double step = 10.0 * decade;
    for (const double m : {0.1, 0.2, 0.5, 1.0, 2.0, 5.0})
        if (m * decade >= raw * (1.0 - 1e-12) || tickCount(m * decade) <= maxTicks + 1) {
            step = m * decade;
            break;
        }
    ticks.step = step;
    ticks.first = std::ceil(lo / step - 1e-9) * step;
    const double magnitude = std::max(std::abs(lo), std::abs(hi));
    const int stepExponent = static_cast<int>(std::floor(std::log10(step) + 1e-12));
    // Fixed decimals up to six (a height of 1.49975 m read as it is, not as 1.49975e+00);
    // scientific past them or from a million on.
    if (magnitude >= 1e6 || stepExponent < -6) {
        // Scientific: as many digits as tell the ticks apart.
        const int digits =
            std::clamp(static_cast<int>(std::floor(std::log10(magnitude))) - stepExponent, 0, 6);
        ticks.labelFormat = QStringLiteral("%.%1e").arg(digits);
    } else {
        ticks.labelFormat = QStringLiteral("%.%1f").arg(std::max(0, -stepExponent));
    }
    return ticks;
}

void applyNiceTicks(QValueAxis* axis, double lo, double hi, int maxTicks) {
    const NiceTicks ticks = niceTicks(lo, hi, maxTicks);
    axis->setRange(lo, hi);
    axis->setTickType(QValueAxis::TicksDynamic);
    axis->setTickAnchor(ticks.first);
    axis->setTickInterval(ticks.step);
    axis->setLabelFormat(ticks.labelFormat);
    axis->setMinorTickCount(0);
}

std::pair<double, double> paddedRange(double lo, double hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) return {-1.0, 1.0};
    const double size = std::max(std::abs(lo), std::abs(hi));
    if (size < kZeroAbsolute) return {-1.0, 1.0};
    if (hi - lo <= kConstantRelative * size) {
        const double mid = 0.5 * (lo + hi);
        return {mid - 0.1 * size, mid + 0.1 * size};
    }
    const double pad = 0.05 * (hi - lo);
    return {lo - pad, hi + pad};
}

QChart* createProbeChart(const QVector<QPointF>& points, const QString& xTitle,
                         const QString& yTitle, const QString& title, bool timeAxis, int maxXTicks,
                         int maxYTicks) {
    auto* chart = new QChart;
    applyChartLocale(chart);
    chart->setTitle(title);
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->setBackgroundRoundness(0);
    chart->legend()->setVisible(false);  // one line: its name is on the axis
    chart->setMargins(QMargins(4, title.isEmpty() ? 2 : 4, 8, 2));

    QVector<QPointF> finite;
    finite.reserve(points.size());
    double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
    for (const QPointF& p : points) {
        if (!std::isfinite(p.x()) || !std::isfinite(p.y())) continue;
        finite.push_back(p);
        xlo = std::min(xlo, p.x());
        xhi = std::max(xhi, p.x());
        ylo = std::min(ylo, p.y());
        yhi = std::max(yhi, p.y());
    }
    auto* series = new QLineSeries(chart);
    series->setName(yTitle);
    if (timeAxis) {
        series->replace(decimate(finite));
    } else if (finite.size() > kMaxPlotPoints) {
        // A curve, not a function of x: thin it by stride, as the phase plot does.
        QVector<QPointF> thinned;
        const qsizetype stride = (finite.size() + kMaxPlotPoints - 1) / kMaxPlotPoints;
        for (qsizetype i = 0; i < finite.size(); i += stride) thinned.push_back(finite[i]);
        thinned.push_back(finite.back());
        series->replace(thinned);
    } else {
        series->replace(finite);
    }
    QPen pen(energyColor(0));
    pen.setWidthF(1.8);
    series->setPen(pen);
    chart->addSeries(series);

    auto* x = new QValueAxis;
    x->setTitleText(xTitle);
    auto* y = new QValueAxis;
    y->setTitleText(yTitle);
    if (finite.isEmpty()) {
        xlo = 0.0;
        xhi = 1.0;
        ylo = -1.0;
        yhi = 1.0;
    }
    if (timeAxis) {
        // Time runs exactly over the samples, as in the energy plot.
        applyNiceTicks(x, xlo, xhi > xlo ? xhi : xlo + 1.0, maxXTicks);
    } else {
        const auto [lo, hi] = paddedRange(xlo, xhi);
        applyNiceTicks(x, lo, hi, maxXTicks);
    }
    const auto [lo, hi] = paddedRange(ylo, yhi);
    applyNiceTicks(y, lo, hi, maxYTicks);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    series->attachAxis(x);
    series->attachAxis(y);
    applyChartAppearance(chart);
    return chart;
}

}  // namespace phasebox::ui
