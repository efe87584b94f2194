#include "app/desktop/presenters/ProbeGraphsPresenter.h"

#include "app/document/Document.h"
#include "app/io/ChartFile.h"
#include "app/sim/ProbeRecorder.h"
#include "ui/instruments/GraphsView.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/instruments/ProbeFormat.h"
#include "ui/instruments/ProbePicker.h"
#include "ui/panels/BuiltinText.h"
#include "ui/panels/DisplayText.h"
#include "ui/panels/ShownNumber.h"
#include "ui/plots/ProbeChart.h"

#include <QChart>
#include <QDir>
#include <QFileDialog>
#include <QMessageBox>
#include <QRegularExpression>
#include <QStandardPaths>

#include <cmath>
#include <limits>
#include <memory>

namespace phasebox {

ProbeGraphsPresenter::ProbeGraphsPresenter(ui::InstrumentsPanel& panel, Document& document,
                                           ProbeRecorder& probes, QObject* parent)
    : InstrumentBase(panel, document, probes, parent) {
    graphs_.resize(static_cast<std::size_t>(panel_.graphs()->count()));
    ui::GraphsView* graphs = panel_.graphs();
    connect(graphs, &ui::GraphsView::graphAdded, this, [this](int index) {
        graphs_.insert(graphs_.begin() + index, Graph{});
        refreshGraph(index);
    });
    connect(graphs, &ui::GraphsView::graphRemoved, this, [this](int index) {
        graphs_.erase(graphs_.begin() + index);
        emit probesChanged();
    });
    connect(graphs, &ui::GraphsView::yEntered, this, [this](int index, const QString& probe) {
        setGraph(index, probe, graphs_[static_cast<std::size_t>(index)].x);
    });
    connect(graphs, &ui::GraphsView::xEntered, this, [this](int index, const QString& probe) {
        setGraph(index, graphs_[static_cast<std::size_t>(index)].y, probe);
    });
    connect(graphs, &ui::GraphsView::exportRequested, this,
            &ProbeGraphsPresenter::exportGraphInteractively);
}

void ProbeGraphsPresenter::clearInvalid() {
    for (int i = 0; i < panel_.graphs()->count(); ++i) {
        panel_.graphs()->graph(i)->yPicker()->setInvalid({});
        panel_.graphs()->graph(i)->xPicker()->setInvalid({});
    }
}

bool ProbeGraphsPresenter::setGraph(int index, const QString& y, const QString& x, QString* error) {
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
    emit probesChanged();
    refreshGraph(index);
    emit tableStale();
    return true;
}

bool ProbeGraphsPresenter::plotProbe(const QString& y, const QString& x, QString* error) {
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

void ProbeGraphsPresenter::refresh() {
    for (int i = 0; i < static_cast<int>(graphs_.size()); ++i) refreshGraph(i);
}

QString ProbeGraphsPresenter::axisTitle(const QString& probe) const {
    if (probe.isEmpty()) return tr("time [s]");
    const int i = probes_.indexOf(probe);
    if (i < 0 || !probes_.isValid(i)) return probe;
    return ui::probeTitle(probe, probes_.parsed(i)->kind);
}

QVector<QPointF> ProbeGraphsPresenter::graphPoints(const Graph& graph) const {
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

void ProbeGraphsPresenter::refreshGraph(int index) {
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
                          .arg(shortProbeReason(probes_.error(i)));
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
    view->setSeries(points, axisTitle(graph.x), unit, timeAxis, cursor(graph));
}

std::optional<QPointF> ProbeGraphsPresenter::cursor(const Graph& graph) const {
    const double t = shownTime();
    if (!std::isfinite(t)) return std::nullopt;
    // The probes read from the world, which is in the shown frame's state: the values the run
    // recorded at that step, whether or not a thinned series kept its sample.
    const auto value = [this](const QString& probe) {
        const int i = probes_.indexOf(probe);
        return i >= 0 && probes_.isValid(i) ? evaluateProbe(document_.world(), *probes_.parsed(i))
                                            : std::numeric_limits<double>::quiet_NaN();
    };
    return QPointF(graph.x.isEmpty() ? t : value(graph.x), value(graph.y));
}

bool ProbeGraphsPresenter::exportGraph(int index, const QString& path, QString* error) const {
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

void ProbeGraphsPresenter::exportGraphInteractively(int index, const QString& format) {
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

}  // namespace phasebox
