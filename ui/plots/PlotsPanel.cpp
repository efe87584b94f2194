#include "ui/plots/PlotsPanel.h"

#include <QChart>
#include <QChartView>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QSplitter>
#include <QToolButton>
#include <QVBoxLayout>

namespace phasebox::ui {

namespace {
// Swaps the view's chart; QChartView releases the old one without deleting it.
void replaceChart(QChartView* view, QChart* chart) {
    QChart* old = view->chart();
    view->setChart(chart);
    delete old;
}

void applyPresentation(QChart* chart, bool presentation) {
    if (!presentation) return;
    QFont font = chart->titleFont();
    font.setPointSizeF(font.pointSizeF() * 1.5);
    chart->setTitleFont(font);
    QFont legend = chart->legend()->font();
    legend.setPointSizeF(legend.pointSizeF() * 1.4);
    chart->legend()->setFont(legend);
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
    bar->addWidget(exportButton(Plot::Energy, tr("Export energy")));
    bar->addWidget(exportButton(Plot::Phase, tr("Export phase")));
    layout->addLayout(bar);

    auto* splitter = new QSplitter(Qt::Vertical, this);
    energyView_ = new QChartView(createEnergyChart({}, {}, tr("Energy")), splitter);
    auto* phaseBox = new QWidget(splitter);
    auto* phaseLayout = new QVBoxLayout(phaseBox);
    phaseLayout->setContentsMargins(0, 0, 0, 0);
    phaseView_ = new QChartView(createPhaseChart({}, QStringLiteral("x"), QStringLiteral("vx"),
                                                 tr("Phase space")),
                                phaseBox);
    phaseHint_ = new QLabel(tr("Click an object on the canvas to plot its phase space."), phaseBox);
    phaseHint_->setWordWrap(true);
    phaseLayout->addWidget(phaseHint_);
    phaseLayout->addWidget(phaseView_, 1);
    for (QChartView* view : {energyView_, phaseView_}) styleChart(view);
    splitter->addWidget(energyView_);
    splitter->addWidget(phaseBox);
    layout->addWidget(splitter, 1);
}

QToolButton* PlotsPanel::exportButton(Plot plot, const QString& text) {
    auto* button = new QToolButton(this);
    button->setText(text);
    button->setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(button);
    for (const QString& format : {QStringLiteral("png"), QStringLiteral("svg"), QStringLiteral("csv")})
        menu->addAction(format.toUpper() + QStringLiteral("…"),
                        this, [this, plot, format] { emit exportRequested(plot, format); });
    button->setMenu(menu);
    return button;
}

void PlotsPanel::styleChart(QChartView* view) {
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumHeight(160);
    applyPresentation(view->chart(), presentation_);
}

void PlotsPanel::setEnergy(std::span<const EnergySample> samples,
                           std::span<const PlotMarker> markers, const QString& title) {
    if (paused_) return;
    replaceChart(energyView_, createEnergyChart(samples, markers, title));
    styleChart(energyView_);
}

void PlotsPanel::setPhase(std::span<const PhaseSample> samples, const QString& coordinateName,
                          const QString& velocityName, const QString& title) {
    phaseHint_->setVisible(coordinateName.isEmpty());
    phaseView_->setVisible(!coordinateName.isEmpty());
    if (paused_) return;
    replaceChart(phaseView_, createPhaseChart(samples, coordinateName, velocityName, title));
    styleChart(phaseView_);
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

}  // namespace phasebox::ui
