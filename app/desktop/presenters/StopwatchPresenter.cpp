#include "app/desktop/presenters/StopwatchPresenter.h"

#include "app/document/Document.h"
#include "physics/world/World.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/instruments/TimerView.h"

namespace phasebox {

StopwatchPresenter::StopwatchPresenter(ui::InstrumentsPanel& panel, Document& document,
                                       ProbeRecorder& probes, QObject* parent)
    : InstrumentBase(panel, document, probes, parent) {
    ui::TimerView* timer = panel_.timer();
    connect(timer, &ui::TimerView::startStopClicked, this, &StopwatchPresenter::startStop);
    connect(timer, &ui::TimerView::lapClicked, this, &StopwatchPresenter::lap);
    connect(timer, &ui::TimerView::resetClicked, this, &StopwatchPresenter::reset);
}

void StopwatchPresenter::startStop() {
    const double now = document_.world().time();
    stopwatch_.isRunning() ? stopwatch_.stop(now) : stopwatch_.start(now);
    used_ = true;
    refresh();
}

void StopwatchPresenter::lap() {
    stopwatch_.lap(document_.world().time());
    refresh();
}

void StopwatchPresenter::reset() {
    stopwatch_.reset();
    refresh();
}

void StopwatchPresenter::refresh() {
    panel_.timer()->setStopwatch(stopwatch_.elapsed(document_.world().time()),
                                 stopwatch_.isRunning(), stopwatch_.laps());
}

}  // namespace phasebox
