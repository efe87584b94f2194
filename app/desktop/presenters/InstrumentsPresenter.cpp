#include "app/desktop/presenters/InstrumentsPresenter.h"

#include "app/desktop/presenters/PeriodTimerPresenter.h"
#include "app/desktop/presenters/ProbeGraphsPresenter.h"
#include "app/desktop/presenters/ProbeTablePresenter.h"
#include "app/desktop/presenters/ReadoutsPresenter.h"
#include "app/desktop/presenters/StopwatchPresenter.h"
#include "app/document/Document.h"
#include "app/sim/ProbeRecorder.h"
#include "app/sim/SimulationController.h"
#include "physics/world/World.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/instruments/ReadoutView.h"

#include <QAction>
#include <QEvent>
#include <QMenu>
#include <QSet>
#include <QTimer>

#include <vector>

namespace phasebox {

InstrumentsPresenter::InstrumentsPresenter(ui::InstrumentsPanel& panel, Document& document,
                                           SimulationController& controller, ProbeRecorder& probes,
                                           QObject* parent)
    : Presenter(parent),
      panel_(panel),
      document_(document),
      controller_(controller),
      probes_(probes),
      readouts_(new ReadoutsPresenter(panel, document, probes, this)),
      graphs_(new ProbeGraphsPresenter(panel, document, probes, this)),
      timer_(new PeriodTimerPresenter(panel, document, probes, this)),
      stopwatch_(new StopwatchPresenter(panel, document, probes, this)),
      table_(new ProbeTablePresenter(panel, document, probes, this)) {
    for (InstrumentBase* instrument :
         std::initializer_list<InstrumentBase*>{readouts_, graphs_, timer_, stopwatch_, table_}) {
        connect(instrument, &Presenter::message, this, &Presenter::message);
        connect(instrument, &InstrumentBase::instrumentsWanted, this,
                &InstrumentsPresenter::instrumentsWanted);
        connect(instrument, &InstrumentBase::probesChanged, this,
                &InstrumentsPresenter::updateRecordedProbes);
        connect(instrument, &InstrumentBase::tableStale, table_, &ProbeTablePresenter::refresh);
        instrument->setController(&controller_);
    }
    connect(&document_, &Document::sceneReset, this, &InstrumentsPresenter::onSceneReset);
    connect(&document_, &Document::sceneEdited, this, &InstrumentsPresenter::onSceneEdited);
    connect(&document_, &Document::instrumentsLoaded, this,
            [this] { applyInstruments(document_.loadedInstruments()); });
    connect(&document_, &Document::selectionChanged, this, [this] {
        updateOffered();
        readouts_->refresh();
    });
    connect(&controller_, &SimulationController::stepped, this, [this] {
        stopwatch_->refresh();
        if (!panel_.isVisible()) return;
        if (panel_.currentTab() == ui::InstrumentsPanel::Tab::Readouts) readouts_->refresh();
        if (sinceRefresh_.elapsed() >= kRefreshIntervalMs) refreshShown();
    });
    connect(&controller_, &SimulationController::runningChanged, this, [this] { refresh(); });
    // The timeline moved: the shown instrument follows at once (cursor, row, heading), the
    // others when shown.
    connect(&controller_, &SimulationController::frameShown, this, [this] {
        if (panel_.isVisible()) refreshShown();
    });
    // A blow-up restored an earlier frame: record it, which drops what came after it.
    connect(&controller_, &SimulationController::diverged, this, [this] {
        probes_.record(document_.world());
        refresh();
    });

    ui::ReadoutView* readouts = panel_.readouts();
    connect(readouts, &ui::ReadoutView::graphRequested, this,
            [this](const QString& p) { plotProbe(p); });
    connect(readouts, &ui::ReadoutView::periodRequested, this, [this](const QString& p) {
        if (!timeProbe(p)) return;
        panel_.showTab(ui::InstrumentsPanel::Tab::Timer);
        emit instrumentsWanted();
    });
    connect(&panel_, &ui::InstrumentsPanel::tabChanged, this, [this] { refreshShown(); });
    panel_.installEventFilter(this);  // shown again (dock raised): bring it up to date
    sinceRefresh_.start();
}

bool InstrumentsPresenter::eventFilter(QObject* watched, QEvent* event) {
    if (watched == &panel_ && event->type() == QEvent::Show)
        QTimer::singleShot(0, this, [this] { refreshShown(); });
    return Presenter::eventFilter(watched, event);
}

void InstrumentsPresenter::createActions(QWidget& window) {
    connect(addWindowAction(window, QStringLiteral("showInstruments"), tr("&Instruments"),
                            Qt::CTRL | Qt::Key_I),
            &QAction::triggered, this, [this] { emit instrumentsWanted(); });
    QAction* watch = addWindowAction(window, QStringLiteral("stopwatch"),
                                     tr("Start/Stop S&topwatch"), Qt::CTRL | Qt::Key_T);
    watch->setToolTip(tr("The stopwatch on simulated time (Instruments → Timer)"));
    connect(watch, &QAction::triggered, this, [this] {
        startStopStopwatch();
        panel_.showTab(ui::InstrumentsPanel::Tab::Timer);
        emit instrumentsWanted();
    });
    connect(addWindowAction(window, QStringLiteral("stopwatchLap"), tr("Stopwatch &Lap"),
                            Qt::CTRL | Qt::Key_L),
            &QAction::triggered, this, &InstrumentsPresenter::lapStopwatch);
}

void InstrumentsPresenter::addExportActions(QMenu& menu) {
    menu.addAction(tr("Probe Table as CSV…"), table_,
                   &ProbeTablePresenter::exportTableInteractively);
}

// ---- following the document ------------------------------------------------------------------

void InstrumentsPresenter::onSceneReset() {
    // New, Open (a revert too), Reset: a new run starts from the setup's sample.
    probes_.clear();
    probes_.rebind(document_.world());
    probes_.record(document_.world());
    stopwatch_->stopwatch().reset();
    graphs_->clearInvalid();
    updateOffered();
    refresh();
}

void InstrumentsPresenter::onSceneEdited() {
    probes_.rebind(document_.world());
    if (!document_.hasRun()) {
        // At the setup the one sample is the setup's: record the edited one.
        probes_.clear();
        probes_.record(document_.world());
    }
    updateOffered();
    readouts_->refresh();
    // A drag edits many times a second: the graphs follow at the refresh rate.
    if (sinceRefresh_.elapsed() >= kRefreshIntervalMs)
        refreshShown();
    else
        QTimer::singleShot(kRefreshIntervalMs, this, [this] { refreshShown(); });
}

void InstrumentsPresenter::updateOffered() {
    const World& world = document_.world();
    QStringList list;
    QSet<QString> seen;
    const auto add = [&](const QString& text) {
        if (seen.contains(text)) return;
        seen.insert(text);
        list << text;
    };
    // The selection's probes first: what was just clicked is what is wanted.
    std::vector<std::string> objects;
    for (const QString& id : document_.selection()) {
        const std::string name = id.toStdString();
        const std::vector<std::string> fields = objectProbes(world, name);
        if (!fields.empty()) objects.push_back(name);
        for (const std::string& f : fields) add(QString::fromStdString(f));
        for (const std::string& f : jointProbes(world, name)) add(QString::fromStdString(f));
    }
    std::vector<QString> instruments(instrumentProbes_.begin(), instrumentProbes_.end());
    if (objects.size() >= 2) {
        const QString a = QString::fromStdString(objects[0]),
                      b = QString::fromStdString(objects[1]);
        instruments.push_back(QStringLiteral("distance(%1,%2)").arg(a, b));
        if (objects.size() >= 3) {
            const QString c = QString::fromStdString(objects[2]);
            instruments.push_back(QStringLiteral("distance(%1,%2)").arg(b, c));
            instruments.push_back(QStringLiteral("angle(%1,%2,%3)").arg(a, b, c));
        }
    }
    for (const QString& text : instruments)
        if (ProbeRecorder::parse(world, text, nullptr)) add(text);
    std::size_t count = world.rigidBodies().size();
    for (const Particle& p : world.particles()) count += p.cloth < 0 ? 1 : 0;
    const bool all = count <= static_cast<std::size_t>(kMaxListedObjects);
    for (const std::string& text : listProbes(world)) {
        const QString probe = QString::fromStdString(text);
        const bool joint = probe.startsWith(QLatin1String("force(")) ||
                           (probe.endsWith(QLatin1String(".angle")) &&
                            isJointId(world, probe.chopped(6).toStdString()));
        if (all || probe.startsWith(QLatin1String("system.")) || joint) add(probe);
    }
    offered_ = list;
    panel_.setOffered(list);
}

void InstrumentsPresenter::setInstrumentProbes(const QStringList& probes) {
    if (probes == instrumentProbes_) return;
    instrumentProbes_ = probes;
    updateOffered();
}

void InstrumentsPresenter::updateRecordedProbes() {
    QStringList texts;
    for (const ProbeGraphsPresenter::Graph& g : graphs_->graphs()) texts << g.y << g.x;
    texts << timer_->probe() << table_->columns();
    texts.removeAll(QString());
    probes_.setProbes(texts, document_.world());
}

// ---- what the user asks for, forwarded to the instruments -------------------------------------

bool InstrumentsPresenter::setGraph(int index, const QString& y, const QString& x, QString* error) {
    return graphs_->setGraph(index, y, x, error);
}

bool InstrumentsPresenter::plotProbe(const QString& y, const QString& x, QString* error) {
    return graphs_->plotProbe(y, x, error);
}

bool InstrumentsPresenter::timeProbe(const QString& probe, QString* error) {
    return timer_->timeProbe(probe, error);
}

bool InstrumentsPresenter::addTableColumn(const QString& probe, QString* error) {
    return table_->addColumn(probe, error);
}

void InstrumentsPresenter::removeTableColumn(const QString& probe) {
    table_->removeColumn(probe);
}

Stopwatch& InstrumentsPresenter::stopwatch() {
    return stopwatch_->stopwatch();
}

void InstrumentsPresenter::startStopStopwatch() {
    stopwatch_->startStop();
}

void InstrumentsPresenter::lapStopwatch() {
    stopwatch_->lap();
}

void InstrumentsPresenter::resetStopwatch() {
    stopwatch_->reset();
}

bool InstrumentsPresenter::exportGraph(int index, const QString& path, QString* error) const {
    return graphs_->exportGraph(index, path, error);
}

bool InstrumentsPresenter::exportTable(const QString& path, QString* error) const {
    return table_->exportTable(path, error);
}

void InstrumentsPresenter::copyTable() const {
    table_->copyTable();
}

// ---- bringing the views up to date --------------------------------------------------------------

void InstrumentsPresenter::refresh() {
    sinceRefresh_.restart();
    readouts_->refresh();
    graphs_->refresh();
    timer_->refresh();
    stopwatch_->refresh();
    table_->refresh();
}

void InstrumentsPresenter::refreshShown() {
    sinceRefresh_.restart();
    switch (panel_.currentTab()) {
        case ui::InstrumentsPanel::Tab::Readouts:
            readouts_->refresh();
            break;
        case ui::InstrumentsPanel::Tab::Graphs:
            graphs_->refresh();
            break;
        case ui::InstrumentsPanel::Tab::Timer:
            timer_->refresh();
            stopwatch_->refresh();
            break;
        case ui::InstrumentsPanel::Tab::Table:
            table_->refresh();
            break;
    }
}

}  // namespace phasebox
