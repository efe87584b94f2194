#include "ui/instruments/GraphsView.h"

#include "ui/instruments/ProbePicker.h"
#include "ui/plots/Charts.h"
#include "ui/plots/ProbeChart.h"

#include <QChart>
#include <QChartView>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineSeries>
#include <QMenu>
#include <QScrollArea>
#include <QSplitter>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace phasebox::ui {

// ---- one graph --------------------------------------------------------------------------------

ProbeGraphView::ProbeGraphView(QWidget* parent) : QFrame(parent) {
    setFrameShape(QFrame::StyledPanel);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);
    auto* row = new QHBoxLayout;
    y_ = new ProbePicker(tr("probe to plot"), {}, this);
    y_->setObjectName(QStringLiteral("graphY"));
    x_ = new ProbePicker(tr("time"), tr("time"), this);
    x_->setObjectName(QStringLiteral("graphX"));
    x_->setMinimumContentsLength(6);
    auto* against = new QLabel(tr("vs"), this);
    auto* exportButton = new QToolButton(this);
    exportButton->setText(tr("Export"));
    exportButton->setToolTip(tr("Save this graph as a picture or its samples as CSV"));
    exportButton->setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(exportButton);
    for (const QString& format :
         {QStringLiteral("png"), QStringLiteral("svg"), QStringLiteral("csv")})
        menu->addAction(tr("As %1…").arg(format.toUpper()), this,
                        [this, format] { emit exportRequested(format); });
    exportButton->setMenu(menu);
    auto* remove = new QToolButton(this);
    remove->setText(QStringLiteral("✕"));
    remove->setToolTip(tr("Close this graph"));
    remove->setAutoRaise(true);
    // Two short rows rather than one long one: the dock shares a 1024-pixel screen.
    row->addWidget(y_, 1);
    row->addWidget(exportButton);
    row->addWidget(remove);
    layout->addLayout(row);
    auto* againstRow = new QHBoxLayout;
    againstRow->addWidget(against);
    againstRow->addWidget(x_, 1);
    layout->addLayout(againstRow);
    message_ = new QLabel(this);
    message_->setWordWrap(true);
    layout->addWidget(message_);
    view_ = new QChartView(createProbeChart({}, tr("time [s]"), {}, {}, true), this);
    view_->setRenderHint(QPainter::Antialiasing);
    // Room for three y labels at least (applyNiceTicks; the dock scrolls when graphs pile up).
    view_->setMinimumHeight(150);
    layout->addWidget(view_, 1);
    connect(y_, &ProbePicker::probeEntered, this, &ProbeGraphView::yEntered);
    connect(x_, &ProbePicker::probeEntered, this, &ProbeGraphView::xEntered);
    connect(remove, &QToolButton::clicked, this, &ProbeGraphView::removeRequested);
}

void ProbeGraphView::setSeries(const QVector<QPointF>& points, const QString& xTitle,
                               const QString& yUnit, bool timeAxis, std::optional<QPointF> cursor) {
    QChart* old = view_->chart();
    // As many ticks as the width holds whole labels (about 70 px each), and as the plot's height
    // (the view's less about 70 px of x labels and margins) holds at about 22 px a label: Qt
    // Charts gives each label its share of the axis's height, elides a taller one to "…" and
    // drops one that overlaps the one below (six in a 141 px graph, a plot 70 px high, were each
    // elided; five in an 80 px plot lost one).
    const int ticks = std::clamp(view_->width() / 70, 2, 6);
    const int yTicks = std::clamp((view_->height() - 70) / 22, 2, 6);
    QChart* chart = createProbeChart(points, xTitle, yUnit, {}, timeAxis, ticks, yTicks);
    const QColor colour = palette().color(QPalette::Highlight);
    if (cursor && timeAxis)
        addTimeCursor(chart, cursor->x(), colour);
    else if (cursor)
        addPointCursor(chart, *cursor, colour);
    view_->setChart(chart);
    delete old;  // QChartView lets go of the old chart without deleting it
}

void ProbeGraphView::setMessage(const QString& text, bool warning) {
    message_->setText(text);
    message_->setVisible(!text.isEmpty());
    message_->setStyleSheet(warning ? QStringLiteral("QLabel { color: #d62728; }") : QString());
}

QString ProbeGraphView::message() const {
    return message_->text();
}

int ProbeGraphView::pointCount() const {
    int points = 0;
    for (QAbstractSeries* s : view_->chart()->series())
        if (auto* line = qobject_cast<QLineSeries*>(s);
            line && line->name() != QLatin1String(kCursorName))
            points += static_cast<int>(line->count());
    return points;
}

QVector<QPointF> ProbeGraphView::cursor() const {
    return chartCursor(view_->chart());
}

// ---- the stack of graphs ------------------------------------------------------------------------

GraphsView::GraphsView(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    auto* bar = new QHBoxLayout;
    add_ = new QToolButton(this);
    add_->setText(tr("+ Add graph"));
    add_->setToolTip(tr("Another graph below, up to %1").arg(kMaxGraphs));
    connect(add_, &QToolButton::clicked, this, [this] { addGraph(); });
    auto* hint = new QLabel(tr("Any probe against time or another probe."), this);
    hint->setWordWrap(true);
    bar->addWidget(hint, 1);
    bar->addWidget(add_);
    layout->addLayout(bar);
    // The graphs share the height; past what the dock holds at their smallest, they scroll
    // rather than push the dock (and the window) taller.
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    splitter_ = new QSplitter(Qt::Vertical, scroll);
    splitter_->setChildrenCollapsible(false);
    scroll->setWidget(splitter_);
    layout->addWidget(scroll, 1);
    addGraph();
}

int GraphsView::indexOf(const ProbeGraphView* graph) const {
    for (int i = 0; i < graphs_.size(); ++i)
        if (graphs_[i] == graph) return i;
    return -1;
}

ProbeGraphView* GraphsView::addGraph() {
    if (graphs_.size() >= kMaxGraphs) return nullptr;
    auto* graph = new ProbeGraphView(splitter_);
    graph->setObjectName(QStringLiteral("graph%1").arg(graphs_.size()));
    graph->yPicker()->setOffered(offered_);
    graph->xPicker()->setOffered(offered_);
    // The signals name the graph by its index at the time they are sent.
    connect(graph, &ProbeGraphView::yEntered, this,
            [this, graph](const QString& p) { emit yEntered(indexOf(graph), p); });
    connect(graph, &ProbeGraphView::xEntered, this,
            [this, graph](const QString& p) { emit xEntered(indexOf(graph), p); });
    connect(graph, &ProbeGraphView::exportRequested, this,
            [this, graph](const QString& f) { emit exportRequested(indexOf(graph), f); });
    connect(graph, &ProbeGraphView::removeRequested, this,
            [this, graph] { removeGraph(indexOf(graph)); });
    graphs_.append(graph);
    splitter_->addWidget(graph);
    add_->setEnabled(graphs_.size() < kMaxGraphs);
    emit graphAdded(static_cast<int>(graphs_.size()) - 1);
    return graph;
}

void GraphsView::removeGraph(int index) {
    if (index < 0 || index >= graphs_.size()) return;
    if (graphs_.size() == 1) {
        // The last graph stays, emptied: a tab with nothing in it explains nothing.
        graphs_[0]->yPicker()->setProbe({});
        graphs_[0]->xPicker()->setProbe({});
        emit yEntered(0, {});
        emit xEntered(0, {});
        return;
    }
    ProbeGraphView* graph = graphs_.takeAt(index);
    graph->hide();
    graph->deleteLater();
    for (int i = 0; i < graphs_.size(); ++i)
        graphs_[i]->setObjectName(QStringLiteral("graph%1").arg(i));
    add_->setEnabled(true);
    emit graphRemoved(index);
}

void GraphsView::setOffered(const QStringList& probes) {
    offered_ = probes;
    for (ProbeGraphView* graph : std::as_const(graphs_)) {
        graph->yPicker()->setOffered(probes);
        graph->xPicker()->setOffered(probes);
    }
}

}  // namespace phasebox::ui
