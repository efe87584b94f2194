// InstrumentsPresenter: a lesson's instruments, set from its file and collected for Save
// (CONTRACT §7 `instruments`).

#include "app/desktop/presenters/InstrumentsPresenter.h"
#include "physics/scene/InstrumentsDesc.h"
#include "ui/instruments/GraphsView.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/instruments/ProbePicker.h"
#include "ui/instruments/ProbeTableView.h"
#include "ui/instruments/TimerView.h"

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
    periodProbe_.clear();
    panel_.timer()->picker()->setProbe({});
    panel_.timer()->picker()->setInvalid({});
    if (!savedTimers_.isEmpty()) timeProbe(savedTimers_.front());
    stopwatchUsed_ = in.stopwatch;
    tableProbes_.clear();
    for (const std::string& probe : in.probes)
        if (!tableProbes_.contains(text(probe))) tableProbes_ << text(probe);
    panel_.table()->picker()->setInvalid({});
    panel_.table()->setOwnColumns(tableProbes_);
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
    for (const Graph& g : graphs_)
        if (!g.y.isEmpty()) out.graphs.push_back({g.y.toStdString(), g.x.toStdString()});
    if (!periodProbe_.isEmpty()) out.timers.push_back(periodProbe_.toStdString());
    for (qsizetype i = 1; i < savedTimers_.size(); ++i)
        if (savedTimers_[i] != periodProbe_) out.timers.push_back(savedTimers_[i].toStdString());
    out.stopwatch = stopwatchUsed_ || stopwatch_.isRunning() || !stopwatch_.laps().empty();
    for (const QString& probe : tableProbes_) out.probes.push_back(probe.toStdString());
}

}  // namespace phasebox
