#include "ui/plots/PlotsPanel.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QEvent>
#include <QFontMetricsF>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLocale>
#include <QMenu>
#include <QPen>
#include <QRegularExpression>
#include <QScatterSeries>
#include <QSplitter>
#include <QTabWidget>
#include <QToolButton>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <utility>

namespace phasebox::ui {

namespace {
// Two runs with different steps reach the same time with different rounding.
constexpr double kGhostTimeSlack = 1e-9;

// Swaps the view's chart; QChartView releases the old one without deleting it.
void replaceChart(QChartView* view, QChart* chart) {
    QChart* old = view->chart();
    view->setChart(chart);
    delete old;
}

void applyPresentation(QChart* chart, bool presentation) {
    if (!presentation) return;
    // The application's font is already 1.4 times larger in presentation mode (MainWindow), and
    // charts take theirs from it: a little more for the title only, so that a narrow dock still
    // has room for the curves and whole legend labels.
    QFont font = chart->titleFont();
    font.setPointSizeF(font.pointSizeF() * 1.15);
    chart->setTitleFont(font);
}

// Set on a chart whose own legend the panel's compact one stands in for.
constexpr char kCompactLegend[] = "phaseboxCompactLegend";

// A line's sample in the compact legend: solid, dashed or a dot, in the series' colour.
QString legendEntry(QLegendMarker* marker) {
    const auto* series = qobject_cast<const QXYSeries*>(marker->series());
    const QPen pen = series ? series->pen() : QPen(marker->brush().color());
    QString glyph = QStringLiteral("━━");
    if (qobject_cast<const QScatterSeries*>(marker->series()) || (series && series->count() == 1))
        glyph = QStringLiteral("●");
    else if (pen.style() != Qt::SolidLine)
        glyph = QStringLiteral("╍╍");
    const QColor colour = series && series->count() == 1 ? series->color() : pen.color();
    return QStringLiteral("<span style=\"color:%1\">%2</span>&nbsp;%3")
        .arg(colour.name(), glyph, marker->label().toHtmlEscaped());
}

// A legend along the bottom is a single row, and Qt cuts its labels to "kine…" when the row
// is wider than the view (six energy lines in a narrow dock); down the side it takes the width
// the time axis's numbers need. Where the row does not fit, the chart's legend hides and the
// panel's compact one below the chart shows the same names whole, in as many rows as it needs.
void fitLegend(QChartView* view, QLabel* compact) {
    QChart* chart = view->chart();
    QLegend* legend = chart->legend();
    const bool wanted = legend->isVisible() || chart->property(kCompactLegend).toBool();
    if (!wanted) {
        if (compact) compact->hide();
        return;
    }
    QStringList entries;
    for (QLegendMarker* marker : legend->markers()) {
        if (!marker->series() || marker->series()->property(kNoLegend).toBool()) continue;
        entries << legendEntry(marker);
    }
    const bool fits = !compact || legendRowWidth(chart) <= view->width();
    legend->setAlignment(Qt::AlignBottom);
    legend->setVisible(fits);
    chart->setProperty(kCompactLegend, !fits);
    if (!compact) return;
    compact->setVisible(!fits);
    if (fits) return;
    compact->setFont(legend->font());
    // Breaking spaces between the entries only, so that a name and its line stay together.
    compact->setText(entries.join(QStringLiteral("&nbsp;&nbsp; ")));
}

// Qt cuts a tick label to "-…" when it is wider than the room between two ticks (a phase plot
// in a narrow dock): fewer ticks along the bottom there, so that every number shows whole.
void fitTicks(QChartView* view) {
    QChart* chart = view->chart();
    const QLocale locale = chart->localizeNumbers() ? chart->locale() : QLocale::c();
    static const QRegularExpression precision(QStringLiteral("%\\.(\\d+)g"));
    for (QAbstractAxis* a : chart->axes(Qt::Horizontal)) {
        auto* axis = qobject_cast<QValueAxis*>(a);
        if (!axis) continue;
        const QRegularExpressionMatch match = precision.match(axis->labelFormat());
        const int digits = match.hasMatch() ? match.captured(1).toInt() : 4;
        const QFontMetricsF m(axis->labelsFont());
        const qreal em = m.height();
        // The plot's width: the view's less the vertical axis's labels and title and margins.
        const qreal plot = view->width() - 8.0 * em -
                           m.horizontalAdvance(locale.toString(axis->max(), 'g', digits));
        int count = 5;
        for (; count > 2; --count) {
            qreal widest = 0.0;
            for (int i = 0; i < count; ++i) {
                const double v = axis->min() + i * (axis->max() - axis->min()) / (count - 1);
                widest = std::max(widest, m.horizontalAdvance(locale.toString(v, 'g', digits)));
            }
            if (widest + 0.5 * em <= plot / (count - 1)) break;
        }
        axis->setTickCount(count);
    }
}

// The compact legend's label under a chart.
QLabel* compactLegend(QWidget* parent, const QString& objectName) {
    auto* label = new QLabel(parent);
    label->setObjectName(objectName);
    label->setTextFormat(Qt::RichText);
    label->setWordWrap(true);
    label->setAlignment(Qt::AlignHCenter);
    label->setContentsMargins(4, 0, 4, 2);
    label->hide();
    return label;
}
}  // namespace

PlotsPanel::PlotsPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);

    auto* bar = new QHBoxLayout;
    pauseButton_ = new QToolButton(this);
    pauseButton_->setText(tr("&Pause plots"));
    pauseButton_->setCheckable(true);
    pauseButton_->setToolTip(tr("Freeze the plots while the simulation goes on"));
    connect(pauseButton_, &QToolButton::toggled, this, &PlotsPanel::setPaused);
    auto* clear = new QToolButton(this);
    clear->setText(tr("C&lear"));
    clear->setToolTip(tr("Forget the recorded samples; the plots start again from now"));
    connect(clear, &QToolButton::clicked, this, &PlotsPanel::clearRequested);
    bar->addWidget(pauseButton_);
    bar->addWidget(clear);
    bar->addStretch(1);
    // One export menu for the three plots keeps the bar narrow enough for the dock.
    auto* exportAll = new QToolButton(this);
    exportAll->setText(tr("&Export"));
    exportAll->setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(exportAll);
    const std::pair<Plot, QString> plots[] = {{Plot::Energy, tr("Energy")},
                                              {Plot::Phase, tr("Phase space")},
                                              {Plot::Error, tr("Local error")}};
    for (const auto& [plot, name] : plots) {
        for (const QString& format :
             {QStringLiteral("png"), QStringLiteral("svg"), QStringLiteral("csv")})
            menu->addAction(tr("%1 as %2…").arg(name, format.toUpper()), this,
                            [this, plot = plot, format] { emit exportRequested(plot, format); });
        menu->addSeparator();
    }
    exportAll->setMenu(menu);
    bar->addWidget(exportAll);
    layout->addLayout(bar);

    // Energy on top, always in sight; phase space and the error estimate share the lower half.
    auto* splitter = new QSplitter(Qt::Vertical, this);
    auto* energyBox = new QWidget(splitter);
    auto* energyLayout = new QVBoxLayout(energyBox);
    energyLayout->setContentsMargins(0, 0, 0, 0);
    energyLayout->setSpacing(0);
    energyView_ = new QChartView(createEnergyChart({}, {}, tr("Energy")), energyBox);
    energyLegend_ = compactLegend(energyBox, QStringLiteral("energyLegend"));
    energyLayout->addWidget(energyView_, 1);
    energyLayout->addWidget(energyLegend_);
    lowerTabs_ = new QTabWidget(splitter);
    auto* phaseBox = new QWidget(lowerTabs_);
    auto* phaseLayout = new QVBoxLayout(phaseBox);
    phaseLayout->setContentsMargins(0, 0, 0, 0);
    phaseHint_ = new QLabel(tr("Click an object on the canvas to plot its phase space."), phaseBox);
    phaseHint_->setWordWrap(true);
    coordinateBox_ = new QComboBox(phaseBox);
    coordinateBox_->setToolTip(tr("The coordinate plotted against its velocity"));
    coordinateBox_->addItem(tr("x against vx"), QStringLiteral("x"));
    coordinateBox_->addItem(tr("y against vy"), QStringLiteral("y"));
    coordinateBox_->addItem(tr("angle against ω (boxes)"), QStringLiteral("angle"));
    connect(coordinateBox_, &QComboBox::activated, this,
            [this] { emit phaseCoordinateRequested(coordinateBox_->currentData().toString()); });
    // The hint has a row of its own: beside the chooser a narrow dock left it a column of one
    // or two words.
    phaseLayout->addWidget(phaseHint_);
    phaseLayout->addWidget(coordinateBox_);
    phaseView_ = new QChartView(
        createPhaseChart({}, QStringLiteral("x"), QStringLiteral("vx"), tr("Phase space")),
        phaseBox);
    phaseLegend_ = compactLegend(phaseBox, QStringLiteral("phaseLegend"));
    phaseLayout->addWidget(phaseView_, 1);
    phaseLayout->addWidget(phaseLegend_);
    phaseLayout->addStretch(0);  // the hint and chooser at the top while no chart shows
    auto* errorBox = new QWidget(lowerTabs_);
    auto* errorLayout = new QVBoxLayout(errorBox);
    errorLayout->setContentsMargins(0, 0, 0, 0);
    errorView_ = new QChartView(createErrorChart({}, tr("Local error estimate")), errorBox);
    errorHint_ = new QLabel(errorBox);
    errorHint_->setWordWrap(true);
    errorHint_->hide();
    errorLayout->addWidget(errorHint_);
    errorLayout->addWidget(errorView_, 1);
    energyView_->setAccessibleName(tr("Energy plot"));
    phaseView_->setAccessibleName(tr("Phase space plot"));
    errorView_->setAccessibleName(tr("Local error plot"));
    for (QChartView* view : {energyView_, phaseView_, errorView_}) {
        styleChart(view);
        view->installEventFilter(this);
    }
    lowerTabs_->addTab(phaseBox, tr("P&hase space"));
    lowerTabs_->addTab(errorBox, tr("Local e&rror"));
    splitter->addWidget(energyBox);
    splitter->addWidget(lowerTabs_);
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 1);
    layout->addWidget(splitter, 1);
}

void PlotsPanel::styleChart(QChartView* view) {
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumHeight(120);
    applyPresentation(view->chart(), presentation_);
    fitLegend(view, legendOf(view));
    fitTicks(view);
}

QLabel* PlotsPanel::legendOf(const QChartView* view) const {
    return view == energyView_ ? energyLegend_ : view == phaseView_ ? phaseLegend_ : nullptr;
}

bool PlotsPanel::eventFilter(QObject* watched, QEvent* event) {
    // Plots are rebuilt only while running and not paused: the legend follows the dock's
    // width here.
    if (event->type() == QEvent::Resize)
        for (QChartView* view : {energyView_, phaseView_, errorView_})
            if (watched == view) {
                fitLegend(view, legendOf(view));
                fitTicks(view);
            }
    return QWidget::eventFilter(watched, event);
}

namespace {

// The recorded run's line, dashed and lighter than the live lines, on the chart's axes, which
// widen to hold it.
void addGhostLine(QChart* chart, const QString& name, QVector<QPointF> points, QColor colour,
                  bool hasMarkers) {
    const auto* x = qobject_cast<QValueAxis*>(chart->axes(Qt::Horizontal).value(0));
    const auto* y = qobject_cast<QValueAxis*>(chart->axes(Qt::Vertical).value(0));
    if (points.isEmpty() || !x || !y) return;
    double xlo = x->min(), xhi = x->max(), ylo = y->min(), yhi = y->max();
    for (const QPointF& p : std::as_const(points))
        if (std::isfinite(p.x()) && std::isfinite(p.y())) {
            xlo = std::min(xlo, p.x());
            xhi = std::max(xhi, p.x());
            ylo = std::min(ylo, p.y());
            yhi = std::max(yhi, p.y());
        }
    auto* line = new QLineSeries;
    line->setName(name);
    line->replace(points);
    colour.setAlphaF(0.6);
    line->setPen(QPen(colour, 2.0, Qt::DashLine));
    chart->addSeries(line);
    chart->axes(Qt::Horizontal).value(0)->setRange(xlo, xhi);
    chart->axes(Qt::Vertical).value(0)->setRange(ylo, yhi);
    // The energy plot's markers (vertical lines where the method or dt changed) span the
    // widened range too.
    for (QAbstractSeries* s : hasMarkers ? chart->series() : QList<QAbstractSeries*>{})
        if (auto* m = qobject_cast<QLineSeries*>(s);
            m && m->count() == 2 && m->at(0).x() == m->at(1).x())
            m->replace(QList<QPointF>{{m->at(0).x(), ylo}, {m->at(0).x(), yhi}});
    line->attachAxis(chart->axes(Qt::Horizontal).value(0));
    line->attachAxis(chart->axes(Qt::Vertical).value(0));
}

}  // namespace

void PlotsPanel::setGhost(GhostLines ghost) {
    ghost_ = std::move(ghost);
}

void PlotsPanel::setTimeCursor(double t, std::optional<PhaseSample> phase) {
    cursorTime_ = t;
    cursorPhase_ = std::isfinite(t) ? phase : std::nullopt;
}

void PlotsPanel::setEnergy(std::span<const EnergySample> samples,
                           std::span<const PlotMarker> markers, const QString& title) {
    // A screen reader reads the latest values, paused or not: a chart's curves are pixels.
    if (!samples.empty()) {
        const EnergySample& e = samples.back();
        const QLocale l;
        const auto n = [&l](double v) { return l.toString(v, 'g', 4); };
        energyView_->setAccessibleDescription(
            tr("At t = %1 s: kinetic %2 J, potential %3 J, total %4 J, work_nc %5 J, drift %6 J")
                .arg(n(e.t), n(e.kinetic), n(e.potential), n(e.kinetic + e.potential), n(e.workNc),
                     n(e.drift)));
    }
    if (paused_) return;
    QChart* chart = createEnergyChart(samples, markers, title);
    ghostUntil_ = std::isfinite(cursorTime_) ? cursorTime_
                  : samples.empty()          ? -std::numeric_limits<double>::infinity()
                                             : samples.back().t;
    if (!ghost_.name.isEmpty()) {
        QVector<QPointF> points;
        for (const QPointF& p : ghost_.energy)
            if (p.x() <= ghostUntil_ + kGhostTimeSlack) points.push_back(p);
        addGhostLine(chart, ghost_.name, decimate(points), energyColor(2), true);
    }
    addTimeCursor(chart, cursorTime_, palette().color(QPalette::Highlight));
    replaceChart(energyView_, chart);
    styleChart(energyView_);
}

void PlotsPanel::setPhase(std::span<const PhaseSample> samples, const QString& coordinateName,
                          const QString& velocityName, const QString& title) {
    phaseHint_->setText(coordinateName.isEmpty()
                            ? tr("Click an object on the canvas to plot its phase space.")
                            : QString());
    phaseHint_->setVisible(coordinateName.isEmpty());
    phaseView_->setVisible(!coordinateName.isEmpty());
    if (!samples.empty()) {
        const QLocale l;
        phaseView_->setAccessibleDescription(
            tr("Latest: %1 = %2, %3 = %4")
                .arg(coordinateName, l.toString(samples.back().coordinate, 'g', 4), velocityName,
                     l.toString(samples.back().velocity, 'g', 4)));
    }
    if (paused_) return;
    QChart* chart = createPhaseChart(samples, coordinateName, velocityName, title, phaseReference_,
                                     phaseReferenceName_);
    if (!ghost_.name.isEmpty() && ghost_.phaseCoordinate == coordinateName) {
        QVector<QPointF> points;
        for (std::size_t k = 0; k < ghost_.phase.size() && k < ghost_.phaseTimes.size(); ++k)
            if (ghost_.phaseTimes[k] <= ghostUntil_ + kGhostTimeSlack)
                points.push_back({ghost_.phase[k].coordinate, ghost_.phase[k].velocity});
        if (points.size() > kMaxPlotPoints) {  // a curve: thinned by stride, as the live one
            QVector<QPointF> thinned;
            const qsizetype stride = (points.size() + kMaxPlotPoints - 1) / kMaxPlotPoints;
            for (qsizetype i = 0; i < points.size(); i += stride) thinned.push_back(points[i]);
            thinned.push_back(points.back());
            points = std::move(thinned);
        }
        addGhostLine(chart, ghost_.name, points, QColor(0x60, 0x60, 0x60), false);
    }
    if (cursorPhase_)
        addPointCursor(chart, {cursorPhase_->coordinate, cursorPhase_->velocity},
                       palette().color(QPalette::Highlight));
    replaceChart(phaseView_, chart);
    styleChart(phaseView_);
}

void PlotsPanel::setPhaseReference(std::vector<PhaseSample> samples, const QString& name) {
    phaseReference_ = std::move(samples);
    phaseReferenceName_ = name;
}

void PlotsPanel::setError(std::span<const QPointF> samples, const QString& title,
                          const QString& emptyText) {
    errorHint_->setText(emptyText);
    errorHint_->setVisible(samples.empty() && !emptyText.isEmpty());
    if (paused_) return;
    replaceChart(errorView_, createErrorChart(samples, title));
    styleChart(errorView_);
}

void PlotsPanel::setPhaseCoordinate(const QString& coordinate) {
    const int index = coordinateBox_->findData(coordinate);
    if (index >= 0) coordinateBox_->setCurrentIndex(index);
}

void PlotsPanel::setPaused(bool paused) {
    if (paused == paused_) return;
    paused_ = paused;
    pauseButton_->setChecked(paused);
    pauseButton_->setText(paused ? tr("Resume &plots") : tr("&Pause plots"));
    emit pausedChanged(paused);
}

void PlotsPanel::setPresentation(bool on) {
    presentation_ = on;
    // Takes effect with the next chart (a few frames away while running).
}

PlotsPanel::Plot PlotsPanel::lowerPlot() const {
    return lowerTabs_->currentIndex() == 1 ? Plot::Error : Plot::Phase;
}

void PlotsPanel::showLowerPlot(Plot plot) {
    if (plot != Plot::Energy) lowerTabs_->setCurrentIndex(plot == Plot::Error ? 1 : 0);
}

}  // namespace phasebox::ui
