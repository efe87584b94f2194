#include "ui/panels/TimelineBar.h"
#include "ui/panels/ShownNumber.h"

#include <QAction>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>

#include <algorithm>

namespace phasebox::ui {

namespace {
constexpr std::size_t kMiB = std::size_t{1} << 20;
}  // namespace

TimelineBar::TimelineBar(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("timeline"));
    // The canvas above decides the width: the bar must not widen the central area beyond what
    // the docks leave it in a small window (its slider takes what is left).
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(4, 2, 4, 2);
    const auto button = [this, row](const char* name, QStyle::StandardPixmap icon,
                                    const QString& tip) {
        auto* b = new QToolButton(this);
        b->setObjectName(QLatin1String(name));
        b->setIcon(style()->standardIcon(icon));
        b->setToolTip(tip);
        b->setAccessibleName(tip);
        b->setAutoRaise(true);
        row->addWidget(b);
        return b;
    };
    start_ = button("timelineStart", QStyle::SP_MediaSkipBackward, tr("Jump to the start (Home)"));
    back_ = button("timelineBack", QStyle::SP_MediaSeekBackward, tr("One frame back (,)"));
    forward_ = button("timelineForward", QStyle::SP_MediaSeekForward, tr("One frame forward (.)"));
    slider_ = new QSlider(Qt::Horizontal, this);
    slider_->setObjectName(QStringLiteral("timelineSlider"));
    slider_->setAccessibleName(tr("Recorded time"));
    slider_->setToolTip(tr("Drag to any recorded moment; Play goes on from there"));
    slider_->setRange(0, 0);
    slider_->setMinimumWidth(60);
    row->addWidget(slider_, 1);
    time_ = new QLabel(this);
    time_->setObjectName(QStringLiteral("timelineTime"));
    time_->setMinimumWidth(
        time_->fontMetrics().horizontalAdvance(QStringLiteral("000.000 / 000.000 s")));
    row->addWidget(time_);
    compare_ = new QToolButton(this);
    compare_->setObjectName(QStringLiteral("timelineCompare"));
    compare_->setToolButtonStyle(Qt::ToolButtonTextOnly);
    compare_->hide();
    row->addWidget(compare_);
    memory_ = new QLabel(this);
    memory_->setObjectName(QStringLiteral("timelineMemory"));
    memory_->setToolTip(tr("Memory the recording holds, of its budget"));
    row->addWidget(memory_);
    budget_ = new QSpinBox(this);
    budget_->setObjectName(QStringLiteral("timelineBudget"));
    budget_->setAccessibleName(tr("Recording budget"));
    budget_->setToolTip(tr("The recording's memory budget: beyond it older frames are thinned"));
    budget_->setRange(16, 16384);
    budget_->setSuffix(tr(" MB"));
    budget_->setKeyboardTracking(false);
    row->addWidget(budget_);

    connect(slider_, &QSlider::valueChanged, this, &TimelineBar::frameRequested);
    connect(start_, &QToolButton::clicked, this, &TimelineBar::startRequested);
    connect(back_, &QToolButton::clicked, this, [this] { emit stepRequested(-1); });
    connect(forward_, &QToolButton::clicked, this, [this] { emit stepRequested(1); });
    connect(budget_, &QSpinBox::valueChanged, this,
            [this](int mb) { emit budgetRequested(static_cast<std::size_t>(mb) * kMiB); });
}

void TimelineBar::setCompareAction(QAction* action) {
    if (compare_->defaultAction() == action && compare_->isVisibleTo(this) == (action != nullptr))
        return;
    if (action) {
        compare_->setDefaultAction(action);
        compare_->setAccessibleName(action->text().remove(QLatin1Char('&')));
        compare_->setToolTip(action->toolTip());
    }
    compare_->setVisible(action != nullptr);
    // The button takes the memory figure's place: under the canvas of a 1024 px window both do
    // not fit beside a usable slider (the budget field stays).
    memory_->setVisible(action == nullptr);
}

void TimelineBar::setFrames(int count, int shown, double shownTime, double endTime) {
    const QSignalBlocker block(slider_);
    slider_->setRange(0, std::max(0, count - 1));
    slider_->setValue(shown);
    back_->setEnabled(shown > 0);
    start_->setEnabled(shown > 0);
    forward_->setEnabled(shown < count - 1);
    time_->setText(
        tr("%1 / %2 s").arg(shownNumber(shownTime, 'f', 3), shownNumber(endTime, 'f', 3)));
}

void TimelineBar::setMemory(std::size_t usedBytes, std::size_t budgetBytes) {
    memory_->setText(
        tr("%1 MB of").arg(shownNumber(static_cast<double>(usedBytes) / kMiB, 'f', 1)));
    const QSignalBlocker block(budget_);
    budget_->setValue(static_cast<int>(budgetBytes / kMiB));
}

int TimelineBar::shownFrame() const {
    return slider_->value();
}

}  // namespace phasebox::ui
