// InstrumentsPresenter: a lesson's instruments, set from its file and collected for Save
// (CONTRACT §7 `instruments`).

#include "app/desktop/presenters/InstrumentsPresenter.h"
#include "app/desktop/presenters/PeriodTimerPresenter.h"
#include "app/desktop/presenters/ProbeGraphsPresenter.h"
#include "app/desktop/presenters/ProbeTablePresenter.h"
#include "app/desktop/presenters/StopwatchPresenter.h"
#include "physics/scene/InstrumentsDesc.h"
#include "ui/instruments/GraphsView.h"
#include "ui/instruments/InstrumentsPanel.h"

#include <algorithm>

namespace phasebox {

namespace {
QString text(const std::string& s) {
    return QString::fromStdString(s);
}
}  // namespace

void InstrumentsPresenter::applyInstruments(const InstrumentsDesc& in) {
    // Every graph goes (the last one stays, emptied), then the lesson's are drawn.
    ui::GraphsView* graphs = panel_.graphs();
    while (graphs->count() > 1) graphs->removeGraph(graphs->count() - 1);
    graphs->removeGraph(0);
    const int wanted = std::min(static_cast<int>(in.graphs.size()), ui::GraphsView::kMaxGraphs);
    for (int i = 0; i < wanted; ++i) {
        if (i >= graphs->count() && !graphs->addGraph()) break;
        setGraph(i, text(in.graphs[std::size_t(i)].y), text(in.graphs[std::size_t(i)].x));
    }
    // The window has one period timer: it times the first; the others are kept for Save.
    savedTimers_.clear();
    for (const std::string& probe : in.timers) savedTimers_ << text(probe);
    timer_->clear();
    if (!savedTimers_.isEmpty()) timeProbe(savedTimers_.front());
    stopwatch_->setUsed(in.stopwatch);
    QStringList columns;
    for (const std::string& probe : in.probes) columns << text(probe);
    table_->setColumns(columns);
    updateRecordedProbes();
    refresh();

    // The dock opens on what the lesson measures with.
    if (!in.graphs.empty())
        panel_.showTab(ui::InstrumentsPanel::Tab::Graphs);
    else if (!in.timers.empty() || in.stopwatch)
        panel_.showTab(ui::InstrumentsPanel::Tab::Timer);
    else if (!in.probes.empty())
        panel_.showTab(ui::InstrumentsPanel::Tab::Table);
    else
        return;
    emit instrumentsWanted();
}

void InstrumentsPresenter::collectInstruments(InstrumentsDesc& out) const {
    for (const ProbeGraphsPresenter::Graph& g : graphs_->graphs())
        if (!g.y.isEmpty()) out.graphs.push_back({g.y.toStdString(), g.x.toStdString()});
    const QString timed = timer_->probe();
    if (!timed.isEmpty()) out.timers.push_back(timed.toStdString());
    for (qsizetype i = 1; i < savedTimers_.size(); ++i)
        if (savedTimers_[i] != timed) out.timers.push_back(savedTimers_[i].toStdString());
    const Stopwatch& watch = stopwatch_->stopwatch();
    out.stopwatch = stopwatch_->used() || watch.isRunning() || !watch.laps().empty();
    for (const QString& probe : table_->columns()) out.probes.push_back(probe.toStdString());
}

}  // namespace phasebox
