#include "app/desktop/presenters/TimelinePresenter.h"

#include "app/sim/SimulationController.h"

#include <QAction>

#include <algorithm>

namespace phasebox {

TimelinePresenter::TimelinePresenter(ui::TimelineBar& bar, SimulationController& controller,
                                     QObject* parent)
    : Presenter(parent), bar_(bar), controller_(controller) {
    controller_.setRunRecording(&recording_);
    connect(&controller_, &SimulationController::stepped, this, &TimelinePresenter::refresh);
    connect(&controller_, &SimulationController::frameShown, this, &TimelinePresenter::refresh);
    connect(&bar_, &ui::TimelineBar::frameRequested, this,
            [this](int index) { controller_.showFrame(index); });
    connect(&bar_, &ui::TimelineBar::stepRequested, this, &TimelinePresenter::stepFrames);
    connect(&bar_, &ui::TimelineBar::startRequested, this, [this] { controller_.showFrame(0); });
    connect(&bar_, &ui::TimelineBar::budgetRequested, this, [this](std::size_t bytes) {
        recording_.setBudgetBytes(bytes);
        refresh();
    });
    refresh();
}

void TimelinePresenter::createActions(QWidget& window) {
    const auto add = [&](const char* name, const QString& text, const QKeySequence& key,
                         auto slot) {
        QAction* a = addWindowAction(window, QLatin1String(name), text, key);
        connect(a, &QAction::triggered, this, slot);
    };
    add("frameBack", tr("One Frame Back"), QKeySequence(Qt::Key_Comma), [this] { stepFrames(-1); });
    add("frameForward", tr("One Frame Forward"), QKeySequence(Qt::Key_Period),
        [this] { stepFrames(1); });
    add("jumpToStart", tr("Jump to Start"), QKeySequence(Qt::Key_Home),
        [this] { controller_.showFrame(0); });
}

void TimelinePresenter::stepFrames(int delta) {
    const int count = recording_.frameCount();
    if (count == 0) return;
    const int shown = controller_.shownFrame() >= 0 ? controller_.shownFrame() : count - 1;
    controller_.showFrame(std::clamp(shown + delta, 0, count - 1));
}

void TimelinePresenter::refresh() {
    const int count = recording_.frameCount();
    const int shown = controller_.shownFrame() >= 0 ? controller_.shownFrame() : count - 1;
    const double shownTime = count > 0 ? recording_.frame(shown).time : 0.0;
    const double endTime = count > 0 ? recording_.frame(count - 1).time : 0.0;
    bar_.setFrames(count, std::max(0, shown), shownTime, endTime);
    bar_.setMemory(recording_.bytesUsed(), recording_.budgetBytes());
}

}  // namespace phasebox
