#include "ui/instruments/TimerView.h"

#include "ui/instruments/ProbeFormat.h"
#include "ui/instruments/ProbePicker.h"
#include "ui/panels/ShownNumber.h"

#include <QFontDatabase>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>
#include <numbers>

namespace phasebox::ui {

namespace {
QTableWidget* newList(const QStringList& headers, QWidget* parent) {
    auto* table = new QTableWidget(0, static_cast<int>(headers.size()), parent);
    table->setHorizontalHeaderLabels(headers);
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setAlternatingRowColors(true);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    table->verticalHeader()->setDefaultSectionSize(table->fontMetrics().height() + 6);
    table->setMinimumHeight(90);
    return table;
}

// Fills a table of (number, time, interval since the previous) rows; the first interval is its
// time when fromZero (a stopwatch's first lap), else none.
void fillTimes(QTableWidget* table, const std::vector<double>& times, bool fromZero) {
    const QFont digits = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    table->setRowCount(static_cast<int>(times.size()));
    for (int r = 0; r < static_cast<int>(times.size()); ++r) {
        const QString cells[] = {QString::number(r + 1), shownNumber(times[r], 'f', 4),
                                 r > 0      ? shownNumber(times[r] - times[r - 1], 'f', 4)
                                 : fromZero ? shownNumber(times[r], 'f', 4)
                                            : QStringLiteral("—")};
        for (int c = 0; c < 3; ++c) {
            QTableWidgetItem* item = table->item(r, c);
            if (!item) {
                item = new QTableWidgetItem;
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                if (c > 0) item->setFont(digits);
                table->setItem(r, c, item);
            }
            item->setText(cells[c]);
        }
    }
}

QLabel* bigLabel(QWidget* parent) {
    auto* label = new QLabel(parent);
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setPointSizeF(font.pointSizeF() * 1.6);
    font.setBold(true);
    label->setFont(font);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}
}  // namespace

TimerView::TimerView(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter->setChildrenCollapsible(false);
    layout->addWidget(splitter);

    // The period timer.
    auto* periodBox = new QGroupBox(tr("Period timer"), splitter);
    auto* periodLayout = new QVBoxLayout(periodBox);
    auto* pickRow = new QHBoxLayout;
    picker_ = new ProbePicker(tr("probe to time, e.g. p0.x"), {}, periodBox);
    picker_->setObjectName(QStringLiteral("periodProbe"));
    pickRow->addWidget(new QLabel(tr("Probe:"), periodBox));
    pickRow->addWidget(picker_, 1);
    periodLayout->addLayout(pickRow);
    // The period, and under it its frequency: a narrow dock shows both whole.
    periodLabel_ = bigLabel(periodBox);
    periodLabel_->setObjectName(QStringLiteral("periodValue"));
    frequency_ = new QLabel(periodBox);
    frequency_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    periodLayout->addWidget(periodLabel_);
    periodLayout->addWidget(frequency_);
    detail_ = new QLabel(periodBox);
    detail_->setWordWrap(true);
    periodLayout->addWidget(detail_);
    crossings_ = newList({tr("#"), tr("crossing t [s]"), tr("interval [s]")}, periodBox);
    crossings_->setObjectName(QStringLiteral("crossings"));
    periodLayout->addWidget(crossings_, 1);
    connect(picker_, &ProbePicker::probeEntered, this, &TimerView::probeEntered);

    // The stopwatch.
    auto* watchBox = new QGroupBox(tr("Stopwatch (simulated time)"), splitter);
    auto* watchLayout = new QVBoxLayout(watchBox);
    auto* watchRow = new QHBoxLayout;
    stopwatch_ = bigLabel(watchBox);
    stopwatch_->setObjectName(QStringLiteral("stopwatchValue"));
    // Tool buttons: a push button's style keeps it 80 px wide, too wide for three in a narrow
    // dock.
    startStop_ = new QToolButton(watchBox);
    startStop_->setText(tr("Start"));
    startStop_->setObjectName(QStringLiteral("stopwatchStart"));
    lap_ = new QToolButton(watchBox);
    lap_->setText(tr("Lap"));
    auto* reset = new QToolButton(watchBox);
    reset->setText(tr("Reset"));
    // The reading above its buttons, so that a narrow dock shows both whole.
    watchLayout->addWidget(stopwatch_);
    watchRow->addWidget(startStop_);
    watchRow->addWidget(lap_);
    watchRow->addWidget(reset);
    watchRow->addStretch(1);
    watchLayout->addLayout(watchRow);
    laps_ = newList({tr("#"), tr("split [s]"), tr("lap [s]")}, watchBox);
    watchLayout->addWidget(laps_, 1);
    connect(startStop_, &QToolButton::clicked, this, &TimerView::startStopClicked);
    connect(lap_, &QToolButton::clicked, this, &TimerView::lapClicked);
    connect(reset, &QToolButton::clicked, this, &TimerView::resetClicked);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);

    setPeriod(std::nullopt,
              tr("Pick a probe, then press Play: the period is measured from its "
                 "upward crossings of the middle of its range."),
              {});
    setStopwatch(0.0, false, {});
}

void TimerView::setPeriod(std::optional<double> period, const QString& detail,
                          const std::vector<double>& crossings) {
    period_ = period;
    if (period && *period > 0.0) {
        periodLabel_->setText(tr("T = %1 s").arg(formatReading(*period)));
        frequency_->setText(tr("f = %1 Hz\nω = %2 rad/s")
                                .arg(formatReading(1.0 / *period))
                                .arg(formatReading(2.0 * std::numbers::pi / *period)));
    } else {
        periodLabel_->setText(tr("T = —"));
        frequency_->clear();
    }
    detail_->setText(detail);
    fillTimes(crossings_, crossings, false);
    crossings_->scrollToBottom();
}

QString TimerView::periodText() const {
    return periodLabel_->text();
}

int TimerView::crossingCount() const {
    return crossings_->rowCount();
}

void TimerView::setStopwatch(double elapsed, bool running, const std::vector<double>& laps) {
    stopwatch_->setText(QStringLiteral("%1 s").arg(shownNumber(elapsed, 'f', 3)));
    startStop_->setText(running ? tr("Stop") : tr("Start"));
    lap_->setEnabled(running);
    if (static_cast<int>(laps.size()) != laps_->rowCount()) {
        fillTimes(laps_, laps, true);
        laps_->scrollToBottom();
    }
}

QString TimerView::stopwatchText() const {
    return stopwatch_->text();
}

int TimerView::lapCount() const {
    return laps_->rowCount();
}

}  // namespace phasebox::ui
