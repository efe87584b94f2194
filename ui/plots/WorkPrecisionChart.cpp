#include "ui/plots/WorkPrecisionChart.h"

#include "physics/integrators/Integrator.h"

#include "ui/plots/Charts.h"

#include <QCategoryAxis>
#include <QChart>
#include <QFont>
#include <QGraphicsLayout>
#include <QGraphicsSimpleTextItem>
#include <QLegend>
#include <QLineSeries>
#include <QPen>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
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

// Half decades with a margin, so every point and its marker sit inside without a band of
// empty decade, and grid lines at the powers of 10. The axis holds log10 of the value and its
// labels the value itself (10⁻⁶), as a student reads it, without a log axis that Qt Charts
// cannot label a point on.
QCategoryAxis* decadesAround(double lo, double hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) lo = hi = 0.0;
    lo = std::floor(2.0 * (lo - 0.2)) / 2.0;
    hi = std::ceil(2.0 * (hi + 0.2)) / 2.0;
    return createDecadeAxis(lo, hi, hi - lo > 12.0 ? 2 : 1);
}

struct PointLabel {
    QGraphicsSimpleTextItem* item;
    QPointF value;
    QLineSeries* series;
    int priority;  // 0 for a line's first and last point, 1 for the others
};

}  // namespace

// Point labels are plain text items on the chart: Qt 6.4's series labels can show only the
// coordinates, not the dt. They follow the points whenever the plot area is laid out or their
// font changes. Each takes the first free place around its point (right, left, above, below,
// then the corners), free meaning clear of every label placed before it and of every point's
// marker; one with no free place (crowded points, or a point that coincides with another, as
// midpoint and heun do on a linear force) is left out rather than printed over its neighbour.
// The first and last point of a line come first, so the range of dt is always readable.
class DtLabels : public QObject {
    Q_OBJECT

public:
    DtLabels(QChart* chart, std::vector<PointLabel> labels)
        : QObject(chart), chart_(chart), labels_(std::move(labels)) {
        std::stable_sort(
            labels_.begin(), labels_.end(),
            [](const PointLabel& a, const PointLabel& b) { return a.priority < b.priority; });
        connect(chart, &QChart::plotAreaChanged, this, &DtLabels::place);
    }

    void setFont(const QFont& font) {
        for (const PointLabel& l : labels_) l.item->setFont(font);
        place(chart_->plotArea());
    }

    void place(const QRectF& area) {
        std::vector<QRectF> taken;
        constexpr double kMarker = 5.0;  // half a marker, and a hair
        for (const PointLabel& l : labels_) {
            const QPointF at = chart_->mapToPosition(l.value, l.series);
            taken.emplace_back(at - QPointF(kMarker, kMarker), QSizeF(2 * kMarker, 2 * kMarker));
        }
        for (const PointLabel& l : labels_) {
            const QPointF at = chart_->mapToPosition(l.value, l.series);
            const QSizeF size = l.item->boundingRect().size();
            const double w = size.width(), h = size.height(), gap = kMarker + 2.0;
            const QPointF corners[] = {{gap, -h / 2},
                                       {-w - gap, -h / 2},
                                       {-w / 2, -h - gap},
                                       {-w / 2, gap},
                                       {gap - 2, -h - gap + 2},
                                       {gap - 2, gap - 2},
                                       {-w - gap + 2, -h - gap + 2},
                                       {-w - gap + 2, gap - 2}};
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
    }

private:
    QChart* chart_;
    std::vector<PointLabel> labels_;
};

QString workPrecisionErrorTitle() {
    return QObject::tr("position error [m], lower is better");
}

QString workPrecisionTimeTitle() {
    return QObject::tr("CPU time [s], left is faster");
}

QChart* createWorkPrecisionChart(std::span<const WorkPrecisionPoint> points, const QString& title) {
    return createWorkPrecisionChart(points, title, QFont());
}

QChart* createWorkPrecisionChart(std::span<const WorkPrecisionPoint> points, const QString& title,
                                 const QFont& font) {
    auto* chart = new QChart;
    applyChartLocale(chart);
    chart->setTitle(title);
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->setBackgroundRoundness(0);
    // The room goes to the plot: Qt's default margins leave a wide empty frame.
    chart->setMargins(QMargins(6, 4, 6, 4));
    chart->layout()->setContentsMargins(0, 0, 0, 0);
    chart->legend()->setAlignment(Qt::AlignRight);

    // Lines in order of first appearance, points in the order given (the study's dt order).
    std::vector<QString> names;
    for (const WorkPrecisionPoint& p : points)
        if (std::find(names.begin(), names.end(), p.integrator) == names.end())
            names.push_back(p.integrator);

    double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
    std::vector<PointLabel> labels;
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
        std::optional<std::size_t> firstLabel;  // 1-based index into labels
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
            item->setBrush(color.darker(130));
            item->setZValue(10.0);
            labels.push_back({item, value, series, 1});
            if (!firstLabel) firstLabel = labels.size();
        }
        // A line's ends first: they say which dt it runs from and to.
        if (firstLabel) {
            labels[*firstLabel - 1].priority = 0;
            labels.back().priority = 0;
        }
        if (diverged > 0)
            series->setName(
                diverged == runs
                    ? QStringLiteral("%1 (diverged)").arg(name)
                    : QStringLiteral("%1 (%2 of %3 diverged)").arg(name).arg(diverged).arg(runs));
        chart->addSeries(series);
    }

    QCategoryAxis* x = decadesAround(xlo, xhi);
    x->setTitleText(workPrecisionTimeTitle());
    QCategoryAxis* y = decadesAround(ylo, yhi);
    y->setTitleText(workPrecisionErrorTitle());
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    for (QAbstractSeries* s : chart->series()) {
        s->attachAxis(x);
        s->attachAxis(y);
    }

    new DtLabels(chart, std::move(labels));
    setWorkPrecisionFont(chart, font);
    applyChartAppearance(chart);
    return chart;
}

void setWorkPrecisionFont(QChart* chart, const QFont& font) {
    // Sizes from the given font, never below what a projector at the back of a room shows.
    QFont text = font;
    if (text.pointSizeF() > 0.0) text.setPointSizeF(std::max(10.0, text.pointSizeF()));
    QFont bold = text;
    bold.setBold(true);
    QFont title = bold;
    if (title.pointSizeF() > 0.0) title.setPointSizeF(text.pointSizeF() * 1.15);
    QFont label = text;
    if (label.pointSizeF() > 0.0) label.setPointSizeF(std::max(9.0, text.pointSizeF() * 0.9));
    chart->setTitleFont(title);
    chart->legend()->setFont(text);
    for (QAbstractAxis* axis : chart->axes()) {
        axis->setTitleFont(bold);
        axis->setLabelsFont(text);
    }
    if (auto* labels = chart->findChild<DtLabels*>(QString(), Qt::FindDirectChildrenOnly))
        labels->setFont(label);
}

}  // namespace phasebox::ui

#include "WorkPrecisionChart.moc"
