#include "ui/plots/WorkPrecisionChart.h"

#include "physics/integrators/Integrator.h"

#include <QChart>
#include <QFont>
#include <QGraphicsSimpleTextItem>
#include <QLegend>
#include <QLineSeries>
#include <QPen>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace phasebox::ui {

namespace {

// Ten distinguishable colours (the "tab10" palette), one per registry entry, so an integrator
// has the same colour in every diagram.
QColor integratorColor(const QString& name) {
    static const QColor palette[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e),
                                     QColor(0x2c, 0xa0, 0x2c), QColor(0xd6, 0x27, 0x28),
                                     QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                     QColor(0xe3, 0x77, 0xc2), QColor(0x7f, 0x7f, 0x7f),
                                     QColor(0xbc, 0xbd, 0x22), QColor(0x17, 0xbe, 0xcf)};
    const auto registry = integratorRegistry();
    for (std::size_t i = 0; i < registry.size(); ++i)
        if (name ==
            QLatin1String(registry[i].name.data(), static_cast<qsizetype>(registry[i].name.size())))
            return palette[i % std::size(palette)];
    return QColor(0x30, 0x30, 0x30);
}

Qt::PenStyle integratorLineStyle(const QString& name) {
    const IntegratorInfo* info = findIntegrator(name.toStdString());
    if (!info) return Qt::SolidLine;
    if (info->adaptive) return Qt::DotLine;
    return info->implicit ? Qt::DashLine : Qt::SolidLine;
}

// Half decades with a margin, so every point sits inside without a band of empty decade,
// and grid lines at the powers of 10.
void fitDecades(QValueAxis* axis, double lo, double hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) lo = hi = 0.0;
    lo = std::floor(2.0 * (lo - 0.1)) / 2.0;
    hi = std::ceil(2.0 * (hi + 0.1)) / 2.0;
    axis->setRange(lo, hi);
    axis->setTickType(QValueAxis::TicksDynamic);
    axis->setTickAnchor(0.0);
    axis->setTickInterval(hi - lo > 12.0 ? 2.0 : 1.0);
    axis->setMinorTickCount(0);
    axis->setLabelFormat(QStringLiteral("%.0f"));
}

struct PointLabel {
    QGraphicsSimpleTextItem* item;
    QPointF value;
    QLineSeries* series;
};

}  // namespace

QChart* createWorkPrecisionChart(std::span<const WorkPrecisionPoint> points, const QString& title) {
    auto* chart = new QChart;
    chart->setTitle(title);
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->setBackgroundRoundness(0);
    chart->legend()->setAlignment(Qt::AlignRight);

    // Lines in order of first appearance, points in the order given (the study's dt order).
    std::vector<QString> names;
    for (const WorkPrecisionPoint& p : points)
        if (std::find(names.begin(), names.end(), p.integrator) == names.end())
            names.push_back(p.integrator);

    double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
    auto labels = std::make_shared<std::vector<PointLabel>>();
    QFont labelFont = chart->font();
    labelFont.setPointSizeF(std::max(6.0, labelFont.pointSizeF() * 0.75));
    for (const QString& name : names) {
        auto* series = new QLineSeries(chart);
        series->setName(name);
        const QColor color = integratorColor(name);
        QPen pen(color);
        pen.setWidthF(2.0);
        pen.setStyle(integratorLineStyle(name));
        series->setPen(pen);
        series->setPointsVisible(true);
        series->setMarkerSize(6.0);
        int runs = 0, diverged = 0;
        for (const WorkPrecisionPoint& p : points) {
            if (p.integrator != name) continue;
            ++runs;
            // A diverged run (error ∞) or an exact one (error 0) has no place on a log axis;
            // the legend says how many diverged, so that a missing line is not a mystery.
            diverged += std::isinf(p.error);
            if (!(std::isfinite(p.error) && p.error > 0.0 && p.cpuSeconds > 0.0)) continue;
            const QPointF value(std::log10(p.cpuSeconds), std::log10(p.error));
            series->append(value);
            xlo = std::min(xlo, value.x());
            xhi = std::max(xhi, value.x());
            ylo = std::min(ylo, value.y());
            yhi = std::max(yhi, value.y());
            if (p.label.isEmpty()) continue;
            auto* item = new QGraphicsSimpleTextItem(p.label, chart);
            item->setFont(labelFont);
            item->setBrush(color.darker(130));
            item->setZValue(10.0);
            labels->push_back({item, value, series});
        }
        if (diverged > 0)
            series->setName(
                diverged == runs
                    ? QStringLiteral("%1 (diverged)").arg(name)
                    : QStringLiteral("%1 (%2 of %3 diverged)").arg(name).arg(diverged).arg(runs));
        chart->addSeries(series);
    }

    auto* x = new QValueAxis;
    x->setTitleText(QStringLiteral("log10 CPU time [s]   (left = cheaper)"));
    auto* y = new QValueAxis;
    y->setTitleText(QStringLiteral("log10 position error   (down = more accurate)"));
    fitDecades(x, xlo, xhi);
    fitDecades(y, ylo, yhi);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    for (QAbstractSeries* s : chart->series()) {
        s->attachAxis(x);
        s->attachAxis(y);
    }

    // Point labels are plain text items on the chart: Qt 6.4's series labels can show only the
    // coordinates, not the dt. They follow the points whenever the plot area is laid out. Each
    // takes the first free corner around its point; one with no free corner (a point that
    // coincides with another, as midpoint and heun do on a linear force) is left out rather
    // than printed over its neighbour.
    QObject::connect(chart, &QChart::plotAreaChanged, chart, [chart, labels](const QRectF& area) {
        std::vector<QRectF> taken;
        for (const PointLabel& l : *labels) {
            const QPointF at = chart->mapToPosition(l.value, l.series);
            const QSizeF size = l.item->boundingRect().size();
            const QPointF corners[] = {{6.0, -size.height() - 1.0},
                                       {6.0, 1.0},
                                       {-size.width() - 6.0, -size.height() - 1.0},
                                       {-size.width() - 6.0, 1.0}};
            bool placed = false;
            for (const QPointF& corner : corners) {
                const QRectF rect(at + corner, size);
                const bool free = area.contains(rect) &&
                                  std::none_of(taken.begin(), taken.end(),
                                               [&](const QRectF& r) { return r.intersects(rect); });
                if (!free) continue;
                l.item->setPos(rect.topLeft());
                taken.push_back(rect);
                placed = true;
                break;
            }
            l.item->setVisible(placed);
        }
    });
    return chart;
}

}  // namespace phasebox::ui
