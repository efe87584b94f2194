#include "app/desktop/presenters/InstrumentsPresenter.h"

#include "app/document/Document.h"
#include "app/io/ChartFile.h"
#include "app/sim/ProbeRecorder.h"
#include "app/sim/SimulationController.h"
#include "physics/world/World.h"
#include "ui/instruments/GraphsView.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/instruments/ProbeFormat.h"
#include "ui/instruments/ProbePicker.h"
#include "ui/instruments/ProbeTableView.h"
#include "ui/instruments/ReadoutView.h"
#include "ui/instruments/TimerView.h"
#include "ui/panels/BuiltinText.h"
#include "ui/panels/DisplayText.h"
#include "ui/panels/ShownNumber.h"
#include "ui/plots/ProbeChart.h"

#include <QAction>
#include <QApplication>
#include <QChart>
#include <QClipboard>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QMenu>
#include <QMessageBox>
#include <QRegularExpression>
#include <QSet>
#include <QStandardPaths>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace phasebox {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A parse error without the vocabulary that follows it: `unknown probe "p3.x": no object "p3"`.
QString shortReason(const QString& error) {
    const qsizetype known = error.indexOf(QLatin1String("; known:"));
    return known < 0 ? error : error.left(known);
}

// What kind of object an id names in the world, for the readouts' heading.
QString objectKind(const World& world, const std::string& id) {
    for (const Particle& p : world.particles())
        if (p.id == id)
            return p.cloth >= 0 ? InstrumentsPresenter::tr("cloth node")
                   : p.pinned   ? InstrumentsPresenter::tr("pinned particle")
                                : InstrumentsPresenter::tr("particle");
    for (const RigidBody& b : world.rigidBodies()) {
        if (b.id != id) continue;
        const QString shape = b.shape == RigidShape::Disk      ? InstrumentsPresenter::tr("disk")
                              : b.shape == RigidShape::Polygon ? InstrumentsPresenter::tr("polygon")
                                                               : InstrumentsPresenter::tr("box");
        return b.isStatic ? InstrumentsPresenter::tr("static %1").arg(shape) : shape;
    }
    return {};
}

bool isJoint(const World& world, const std::string& id) {
    for (const Joint& j : world.joints())
        if (j.id == id) return true;
    return false;
}
}  // namespace

InstrumentsPresenter::InstrumentsPresenter(ui::InstrumentsPanel& panel, Document& document,
                                           SimulationController& controller, ProbeRecorder& probes,
                                           QObject* parent)
    : Presenter(parent),
      panel_(panel),
      document_(document),
      controller_(controller),
      probes_(probes) {
    graphs_.resize(static_cast<std::size_t>(panel_.graphs()->count()));
    connect(&document_, &Document::sceneReset, this, &InstrumentsPresenter::onSceneReset);
    connect(&document_, &Document::sceneEdited, this, &InstrumentsPresenter::onSceneEdited);
    connect(&document_, &Document::instrumentsLoaded, this,
            [this] { applyInstruments(document_.loadedInstruments()); });
    connect(&document_, &Document::selectionChanged, this, [this] {
        updateOffered();
        refreshReadouts();
    });
    connect(&controller_, &SimulationController::stepped, this, [this] {
        refreshStopwatch();
        if (!panel_.isVisible()) return;
        if (panel_.currentTab() == ui::InstrumentsPanel::Tab::Readouts) refreshReadouts();
        if (sinceRefresh_.elapsed() >= kRefreshIntervalMs) refreshShown();
    });
    connect(&controller_, &SimulationController::runningChanged, this, [this] { refresh(); });
    // A blow-up restored an earlier frame: record it, which drops what came after it.
    connect(&controller_, &SimulationController::diverged, this, [this] {
        probes_.record(document_.world());
        refresh();
    });
    connect(&probes_, &ProbeRecorder::cleared, this, [this] { ++clears_; });

    ui::GraphsView* graphs = panel_.graphs();
    connect(graphs, &ui::GraphsView::graphAdded, this, [this](int index) {
        graphs_.insert(graphs_.begin() + index, Graph{});
        refreshGraph(index);
    });
    connect(graphs, &ui::GraphsView::graphRemoved, this, [this](int index) {
        graphs_.erase(graphs_.begin() + index);
        updateRecordedProbes();
    });
    connect(graphs, &ui::GraphsView::yEntered, this, [this](int index, const QString& probe) {
        setGraph(index, probe, graphs_[static_cast<std::size_t>(index)].x);
    });
    connect(graphs, &ui::GraphsView::xEntered, this, [this](int index, const QString& probe) {
        setGraph(index, graphs_[static_cast<std::size_t>(index)].y, probe);
    });
    connect(graphs, &ui::GraphsView::exportRequested, this,
            &InstrumentsPresenter::exportGraphInteractively);

    ui::TimerView* timer = panel_.timer();
    connect(timer, &ui::TimerView::probeEntered, this, [this](const QString& p) { timeProbe(p); });
    connect(timer, &ui::TimerView::startStopClicked, this,
            &InstrumentsPresenter::startStopStopwatch);
    connect(timer, &ui::TimerView::lapClicked, this, &InstrumentsPresenter::lapStopwatch);
    connect(timer, &ui::TimerView::resetClicked, this, &InstrumentsPresenter::resetStopwatch);

    ui::ProbeTableView* table = panel_.table();
    connect(table, &ui::ProbeTableView::columnEntered, this,
            [this](const QString& p) { addTableColumn(p); });
    connect(table, &ui::ProbeTableView::columnRemoved, this,
            &InstrumentsPresenter::removeTableColumn);
    connect(table, &ui::ProbeTableView::exportRequested, this,
            &InstrumentsPresenter::exportTableInteractively);
    connect(table, &ui::ProbeTableView::copyRequested, this, &InstrumentsPresenter::copyTable);

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
    menu.addAction(tr("Probe Table as CSV…"), this,
                   &InstrumentsPresenter::exportTableInteractively);
}

// ---- following the document ------------------------------------------------------------------

void InstrumentsPresenter::onSceneReset() {
    // New, Open (a revert too), Reset: a new run starts from the setup's sample.
    probes_.clear();
    probes_.rebind(document_.world());
    probes_.record(document_.world());
    stopwatch_.reset();
    for (int i = 0; i < panel_.graphs()->count(); ++i) {
        panel_.graphs()->graph(i)->yPicker()->setInvalid({});
        panel_.graphs()->graph(i)->xPicker()->setInvalid({});
    }
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
    refreshReadouts();
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
                            isJoint(world, probe.chopped(6).toStdString()));
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

bool InstrumentsPresenter::check(const QString& text, ui::ProbePicker* picker, QString* error) {
    QString why;
    if (text.isEmpty() || ProbeRecorder::parse(document_.world(), text, &why)) {
        if (picker) picker->setInvalid({});
        return true;
    }
    const QString reason = shortReason(why);
    if (picker) picker->setInvalid(reason);
    emit message(reason);
    if (error) *error = why;
    return false;
}

void InstrumentsPresenter::updateRecordedProbes() {
    QStringList texts;
    for (const Graph& g : graphs_) texts << g.y << g.x;
    texts << periodProbe_ << tableProbes_;
    texts.removeAll(QString());
    probes_.setProbes(texts, document_.world());
}

// ---- what the user asks for -------------------------------------------------------------------

bool InstrumentsPresenter::setGraph(int index, const QString& y, const QString& x, QString* error) {
    if (index < 0 || index >= static_cast<int>(graphs_.size())) {
        if (error) *error = tr("no graph %1").arg(index + 1);
        return false;
    }
    ui::ProbeGraphView* view = panel_.graphs()->graph(index);
    Graph& graph = graphs_[static_cast<std::size_t>(index)];
    if (!check(y, view->yPicker(), error) || !check(x, view->xPicker(), error)) return false;
    view->yPicker()->setProbe(y);
    view->xPicker()->setProbe(x);
    if (graph.y == y && graph.x == x) return true;  // entered twice (Enter and activated)
    graph = Graph{y, x};
    updateRecordedProbes();
    refreshGraph(index);
    refreshTable();
    return true;
}

bool InstrumentsPresenter::plotProbe(const QString& y, const QString& x, QString* error) {
    int index = -1;
    for (std::size_t i = 0; i < graphs_.size() && index < 0; ++i)
        if (graphs_[i].y.isEmpty() || (graphs_[i].y == y && graphs_[i].x == x))
            index = static_cast<int>(i);
    if (!check(y, nullptr, error) || !check(x, nullptr, error)) return false;
    if (index < 0) {
        if (!panel_.graphs()->addGraph()) {
            const QString why =
                tr("All %1 graphs are in use: close one first.").arg(ui::GraphsView::kMaxGraphs);
            emit message(why);
            if (error) *error = why;
            return false;
        }
        index = panel_.graphs()->count() - 1;
    }
    if (!setGraph(index, y, x, error)) return false;
    panel_.showTab(ui::InstrumentsPanel::Tab::Graphs);
    emit instrumentsWanted();
    return true;
}

bool InstrumentsPresenter::timeProbe(const QString& probe, QString* error) {
    if (!check(probe, panel_.timer()->picker(), error)) return false;
    panel_.timer()->picker()->setProbe(probe);
    if (probe == periodProbe_) return true;
    periodProbe_ = probe;
    updateRecordedProbes();
    refreshTimer();
    refreshTable();
    return true;
}

bool InstrumentsPresenter::addTableColumn(const QString& probe, QString* error) {
    if (probe.isEmpty() || !check(probe, panel_.table()->picker(), error)) return false;
    panel_.table()->picker()->setProbe({});
    if (!tableProbes_.contains(probe)) tableProbes_ << probe;
    panel_.table()->setOwnColumns(tableProbes_);
    updateRecordedProbes();
    refreshTable();
    return true;
}

void InstrumentsPresenter::removeTableColumn(const QString& probe) {
    tableProbes_.removeAll(probe);
    panel_.table()->setOwnColumns(tableProbes_);
    updateRecordedProbes();
    refreshTable();
}

void InstrumentsPresenter::startStopStopwatch() {
    const double now = document_.world().time();
    stopwatch_.isRunning() ? stopwatch_.stop(now) : stopwatch_.start(now);
    stopwatchUsed_ = true;
    refreshStopwatch();
}

void InstrumentsPresenter::lapStopwatch() {
    stopwatch_.lap(document_.world().time());
    refreshStopwatch();
}

void InstrumentsPresenter::resetStopwatch() {
    stopwatch_.reset();
    refreshStopwatch();
}

// ---- bringing the views up to date --------------------------------------------------------------

void InstrumentsPresenter::refresh() {
    sinceRefresh_.restart();
    refreshReadouts();
    refreshGraphs();
    refreshTimer();
    refreshStopwatch();
    refreshTable();
}

void InstrumentsPresenter::refreshShown() {
    sinceRefresh_.restart();
    switch (panel_.currentTab()) {
        case ui::InstrumentsPanel::Tab::Readouts:
            refreshReadouts();
            break;
        case ui::InstrumentsPanel::Tab::Graphs:
            refreshGraphs();
            break;
        case ui::InstrumentsPanel::Tab::Timer:
            refreshTimer();
            refreshStopwatch();
            break;
        case ui::InstrumentsPanel::Tab::Table:
            refreshTable();
            break;
    }
}

void InstrumentsPresenter::refreshReadouts() {
    ui::ReadoutView* view = panel_.readouts();
    const World& world = document_.world();
    std::vector<std::string> objects;
    QString joint;
    for (const QString& id : document_.selection()) {
        const std::string name = id.toStdString();
        if (!objectKind(world, name).isEmpty())
            objects.push_back(name);
        else if (joint.isEmpty() && isJoint(world, name))
            joint = id;
    }
    if (objects.empty() && joint.isEmpty()) {
        view->showHint(
            tr("Click an object on the canvas to read its position, velocity, "
               "energy and momentum; Shift-click a second and a third for the "
               "distance and the angle between them."));
        return;
    }
    QList<ui::ReadoutRow> rows;
    // A row of one or two probes; left out when the first does not parse (angle of a particle).
    const auto addRow = [&](const QString& label, const QStringList& texts) {
        ui::ReadoutRow row;
        row.label = label;
        for (const QString& text : texts) {
            const std::optional<Probe> probe = ProbeRecorder::parse(world, text, nullptr);
            if (!probe) return;
            if (row.unit.isEmpty()) row.unit = ui::probeUnit(probe->kind);
            row.values << evaluateProbe(world, *probe);
            row.probes << text;
        }
        rows << row;
    };
    QString subject;
    if (!objects.empty()) {
        const QString id = QString::fromStdString(objects.front());
        subject = QStringLiteral("%1 (%2)").arg(id, objectKind(world, objects.front()));
        const auto p = [&id](const char* field) { return id + QLatin1Char('.') + field; };
        addRow(tr("position (x, y)"), {p("x"), p("y")});
        addRow(tr("velocity (vx, vy)"), {p("vx"), p("vy")});
        addRow(tr("speed"), {p("speed")});
        addRow(tr("angle"), {p("angle")});
        addRow(tr("angular velocity ω"), {p("omega")});
        addRow(tr("kinetic energy"), {p("kinetic")});
        addRow(tr("momentum (px, py)"), {p("px"), p("py")});
        addRow(tr("angular momentum L"), {p("L")});
        addRow(tr("contact force"), {QStringLiteral("contact_force(%1)").arg(id)});
    }
    if (objects.size() >= 2) {
        const QString a = QString::fromStdString(objects[0]),
                      b = QString::fromStdString(objects[1]);
        subject = QStringLiteral("%1, %2").arg(a, b);
        addRow(tr("distance %1–%2").arg(a, b), {QStringLiteral("distance(%1,%2)").arg(a, b)});
        if (objects.size() >= 3) {
            const QString c = QString::fromStdString(objects[2]);
            subject += QStringLiteral(", ") + c;
            addRow(tr("angle %1–%2–%3").arg(a, b, c),
                   {QStringLiteral("angle(%1,%2,%3)").arg(a, b, c)});
        }
    }
    if (!joint.isEmpty()) {
        if (subject.isEmpty()) subject = tr("%1 (joint)").arg(joint);
        addRow(tr("constraint force of %1").arg(joint), {QStringLiteral("force(%1)").arg(joint)});
        // Hinges, rods and ropes: the pendulum's angle (the row is left out for the others).
        addRow(tr("angle of %1").arg(joint), {joint + QStringLiteral(".angle")});
    }
    const bool live = document_.hasRun();
    const QString state =
        live ? tr("live, t = %1 s").arg(ui::shownNumber(world.time(), 'f', 2)) : tr("setup");
    view->setReadout(subject, state, live, rows);
}

QString InstrumentsPresenter::axisTitle(const QString& probe) const {
    if (probe.isEmpty()) return tr("time [s]");
    const int i = probes_.indexOf(probe);
    if (i < 0 || !probes_.isValid(i)) return probe;
    return ui::probeTitle(probe, probes_.parsed(i)->kind);
}

QVector<QPointF> InstrumentsPresenter::graphPoints(const Graph& graph) const {
    QVector<QPointF> points;
    const int yi = probes_.indexOf(graph.y);
    const int xi = graph.x.isEmpty() ? -1 : probes_.indexOf(graph.x);
    if (yi < 0 || (!graph.x.isEmpty() && xi < 0)) return points;
    const std::vector<double>& t = probes_.times();
    const std::vector<double>& y = probes_.values(yi);
    const std::vector<double>* x = xi >= 0 ? &probes_.values(xi) : &t;
    points.reserve(static_cast<qsizetype>(t.size()));
    for (std::size_t r = 0; r < t.size(); ++r)
        if (!std::isnan(y[r]) && !std::isnan((*x)[r])) points.push_back({(*x)[r], y[r]});
    return points;
}

void InstrumentsPresenter::refreshGraphs() {
    for (int i = 0; i < static_cast<int>(graphs_.size()); ++i) refreshGraph(i);
}

void InstrumentsPresenter::refreshGraph(int index) {
    ui::ProbeGraphView* view = panel_.graphs()->graph(index);
    if (!view || index >= static_cast<int>(graphs_.size())) return;
    const Graph& graph = graphs_[static_cast<std::size_t>(index)];
    const bool timeAxis = graph.x.isEmpty();
    if (graph.y.isEmpty()) {
        view->setMessage(tr("Pick a probe to plot, or type one (p0.x, system.total, "
                            "distance(A,B), …)."),
                         false);
        view->setSeries({}, axisTitle({}), {}, true);
        return;
    }
    QString problem;
    for (const QString& probe : {graph.y, graph.x}) {
        const int i = probe.isEmpty() ? -1 : probes_.indexOf(probe);
        if (i >= 0 && !probes_.isValid(i) && problem.isEmpty())
            problem = tr("%1 cannot be read in this scene (was its object deleted or renamed?)")
                          .arg(shortReason(probes_.error(i)));
    }
    const QVector<QPointF> points = graphPoints(graph);
    QString note;
    if (problem.isEmpty() && points.size() <= 1)
        note = tr("Press Play: %1 is recorded at every step.").arg(graph.y);
    else if (problem.isEmpty() && !points.isEmpty() && timeAxis &&
             points.front().x() > probes_.times().front())
        note = tr("Recorded since t = %1 s, when it was chosen.")
                   .arg(ui::shownNumber(points.front().x(), 'f', 2));
    view->setMessage(problem.isEmpty() ? note : problem, !problem.isEmpty());
    const int yi = probes_.indexOf(graph.y);
    const QString unit =
        yi >= 0 && probes_.isValid(yi) ? ui::probeUnit(probes_.parsed(yi)->kind) : QString();
    view->setSeries(points, axisTitle(graph.x), unit, timeAxis);
}

void InstrumentsPresenter::refreshTimer() {
    ui::TimerView* view = panel_.timer();
    if (periodProbe_.isEmpty()) {
        view->setPeriod(std::nullopt,
                        tr("Pick a probe (an object's x for a swing), then press Play: the period "
                           "is the mean interval between its upward crossings of the middle of "
                           "its range."),
                        {});
        return;
    }
    const int i = probes_.indexOf(periodProbe_);
    if (i < 0 || !probes_.isValid(i)) {
        view->setPeriod(
            std::nullopt,
            i < 0 ? QString()
                  : tr("%1 cannot be read in this scene.").arg(shortReason(probes_.error(i))),
            {});
        return;
    }
    const ProbeSummary s = probes_.summary(i);
    const std::vector<double> crossings = probes_.crossings(i);
    const QString unit = ui::probeUnit(probes_.parsed(i)->kind);
    const double level = 0.5 * (s.min + s.max);
    QString detail;
    if (!s.period) {
        detail = tr("Waiting for two upward crossings of the middle of the range of %1 "
                    "(%n so far).",
                    nullptr, static_cast<int>(crossings.size()))
                     .arg(periodProbe_);
    } else {
        // The level to the range's fifth digit: a swing about 0 shows 0.0000, not 3e-06.
        const double range = s.max - s.min;
        const int decimals =
            range > 0.0 ? std::clamp(4 - static_cast<int>(std::floor(std::log10(range))), 0, 12)
                        : 4;
        detail =
            tr("Mean interval between the upward crossings of %1 through %2 %3, the middle "
               "of its range [%4, %5] %3, each interpolated within its step.")
                .arg(periodProbe_,
                     ui::shownNumber(level, 'f', decimals).replace(QLatin1Char('-'), QChar(0x2212)),
                     unit, ui::formatReading(s.min), ui::formatReading(s.max));
    }
    view->setPeriod(s.period, detail, crossings);
}

void InstrumentsPresenter::refreshStopwatch() {
    panel_.timer()->setStopwatch(stopwatch_.elapsed(document_.world().time()),
                                 stopwatch_.isRunning(), stopwatch_.laps());
}

void InstrumentsPresenter::refreshTable() {
    QStringList headers{tr("t [s]")};
    const std::vector<double>& times = probes_.times();
    // Each column's largest magnitude sets its decimals (the time's: microseconds).
    QVector<double> scales{1.0};
    for (int i = 0; i < probes_.probeCount(); ++i) {
        const QString text = probes_.probeText(i);
        headers << (probes_.isValid(i) ? ui::probeTitle(text, probes_.parsed(i)->kind)
                                       : tr("%1 (invalid)").arg(text));
        double scale = 0.0;
        for (const double v : probes_.values(i))
            if (std::isfinite(v)) scale = std::max(scale, std::abs(v));
        scales << scale;
    }
    const ProbeRecorder* probes = &probes_;
    const auto source = [probes](int row, int column) {
        const std::vector<double>& t = probes->times();
        if (row < 0 || static_cast<std::size_t>(row) >= t.size()) return kNaN;
        if (column == 0) return t[static_cast<std::size_t>(row)];
        if (column - 1 >= probes->probeCount()) return kNaN;
        const std::vector<double>& v = probes->values(column - 1);
        return static_cast<std::size_t>(row) < v.size() ? v[static_cast<std::size_t>(row)] : kNaN;
    };
    panel_.table()->setTable(headers, static_cast<int>(times.size()), source,
                             clears_ * 64 + static_cast<long long>(std::log2(probes_.stride())),
                             scales);
}

// ---- exports ----------------------------------------------------------------------------------

bool InstrumentsPresenter::exportGraph(int index, const QString& path, QString* error) const {
    if (!document_.mayWriteOutput(path, error)) return false;
    if (index < 0 || index >= static_cast<int>(graphs_.size()) ||
        graphs_[static_cast<std::size_t>(index)].y.isEmpty()) {
        if (error) *error = tr("graph %1 plots nothing: pick a probe first").arg(index + 1);
        return false;
    }
    const Graph& graph = graphs_[static_cast<std::size_t>(index)];
    if (path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive))
        return probes_.writeCsv(
            path, graph.x.isEmpty() ? QStringList{graph.y} : QStringList{graph.x, graph.y}, error);
    // Drawn from the recorded samples in a chart of its own, so the picture is whole even
    // while the dock is hidden; the title says what and where.
    const SceneDesc& setup = document_.setup();
    const QString title =
        tr("%1 against %2 — %3 (%4, dt %5 s)")
            .arg(graph.y, graph.x.isEmpty() ? tr("time") : graph.x,
                 setup.name.empty() ? tr("Untitled") : ui::shownText(ui::sceneText(setup.name)),
                 QString::fromStdString(setup.simulation.integrator))
            .arg(ui::shownNumber(setup.simulation.dt, 'g', 4));
    std::unique_ptr<QChart> chart(ui::createProbeChart(
        graphPoints(graph), axisTitle(graph.x), axisTitle(graph.y), title, graph.x.isEmpty()));
    return writeChart(chart.get(), path, QSize(1200, 800), error);
}

bool InstrumentsPresenter::exportTable(const QString& path, QString* error) const {
    if (!document_.mayWriteOutput(path, error)) return false;
    return probes_.writeCsv(path, {}, error);
}

void InstrumentsPresenter::copyTable() const {
    const auto [first, last] = panel_.table()->selectedRows();
    QApplication::clipboard()->setText(probes_.text({}, QLatin1Char('\t'), first, last));
}

void InstrumentsPresenter::exportGraphInteractively(int index, const QString& format) {
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    QString base = graphs_[static_cast<std::size_t>(index)].y;
    base.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_.-]+")), QStringLiteral("_"));
    const QString path = QFileDialog::getSaveFileName(
        panel_.window(), tr("Export Graph"),
        QDir(dir).filePath((base.isEmpty() ? QStringLiteral("graph") : base) + QLatin1Char('.') +
                           format),
        format.toUpper() + QStringLiteral(" (*.") + format + QLatin1Char(')'));
    if (path.isEmpty()) return;
    QString error;
    if (!exportGraph(index, path, &error))
        QMessageBox::warning(panel_.window(), tr("Export failed"), error);
    else
        emit message(tr("Wrote %1").arg(QDir::toNativeSeparators(path)));
}

void InstrumentsPresenter::exportTableInteractively() {
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString path = QFileDialog::getSaveFileName(
        panel_.window(), tr("Export Probe Table"), QDir(dir).filePath(QStringLiteral("probes.csv")),
        tr("CSV (*.csv)"));
    if (path.isEmpty()) return;
    QString error;
    if (!exportTable(path, &error))
        QMessageBox::warning(panel_.window(), tr("Export failed"), error);
    else
        emit message(tr("Wrote %1").arg(QDir::toNativeSeparators(path)));
}

}  // namespace phasebox
