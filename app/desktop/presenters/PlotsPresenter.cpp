#include "app/desktop/presenters/PlotsPresenter.h"

#include "app/document/Document.h"
#include "app/io/ChartFile.h"
#include "app/sim/Recorder.h"
#include "app/sim/SimulationController.h"
#include "physics/world/World.h"
#include "ui/plots/Charts.h"

#include <QChart>
#include <QDir>
#include <QFileDialog>
#include <QMenu>
#include <QMessageBox>
#include <QStandardPaths>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <utility>

namespace phasebox {

PlotsPresenter::PlotsPresenter(ui::PlotsPanel& panel, Document& document,
                               SimulationController& controller, Recorder& recorder,
                               QObject* parent)
    : Presenter(parent),
      panel_(panel),
      document_(document),
      controller_(controller),
      recorder_(recorder) {
    connect(&document_, &Document::sceneReset, this, [this] {
        recorder_.clear();
        recorder_.record(document_.world());
    });
    // New and Open: the phase plot waits for a choice in this scene, as in a new window.
    connect(&document_, &Document::instrumentsLoaded, this, [this] {
        const QString coordinate = QStringLiteral("x");
        recorder_.setPhaseTarget({}, coordinate);
        panel_.setPhaseCoordinate(coordinate);
        refresh();
    });
    connect(&document_, &Document::selectionChanged, this, &PlotsPresenter::followSelection);
    connect(&controller_, &SimulationController::frameShown, this, &PlotsPresenter::refresh);
    connect(&controller_, &SimulationController::stepped, this, [this] {
        if (sinceRefresh_.elapsed() >= kPlotIntervalMs) refresh();
    });
    connect(&panel_, &ui::PlotsPanel::clearRequested, &recorder_, &Recorder::clear);
    connect(&panel_, &ui::PlotsPanel::phaseCoordinateRequested, this,
            &PlotsPresenter::choosePhaseCoordinate);
    connect(&panel_, &ui::PlotsPanel::exportRequested, this, &PlotsPresenter::exportInteractively);
    connect(&panel_, &ui::PlotsPanel::pausedChanged, this, [this](bool paused) {
        if (!paused) refresh();
    });
    sinceRefresh_.start();
}

// Two lines: the quantity, then the method and step, so that neither is cut in a narrow dock
// (chart titles are rich text).
QString PlotsPresenter::energyTitle() const {
    const SimulationDesc& s = document_.setup().simulation;
    return tr("Energy<br>%1, dt %L2 s")
        .arg(QString::fromStdString(s.integrator))
        .arg(s.dt, 0, 'g', 4);
}

QString PlotsPresenter::errorTitle() const {
    const SimulationDesc& s = document_.setup().simulation;
    return tr("Local error per step<br>%1, dt %L2 s")
        .arg(QString::fromStdString(s.integrator))
        .arg(s.dt / s.substeps, 0, 'g', 4);
}

QString PlotsPresenter::errorNote() const {
    if (!controller_.estimatesErrors()) return tr("The live error estimate is off (View menu).");
    if (controller_.msPerStep() > SimulationController::kMaxEstimateStepMs)
        return tr("No live error estimate: a step takes %1 ms, and the estimate would cost three "
                  "more.")
            .arg(controller_.msPerStep(), 0, 'g', 3);
    return tr("Press Play: the error one step makes is estimated as the simulation runs.");
}

void PlotsPresenter::refresh() {
    sinceRefresh_.restart();
    // The timeline's moment: the world shows it (SimulationController::showFrame), and the phase
    // sample recorded at that very time marks it in the phase plot.
    if (controller_.shownFrame() >= 0) {
        const double t = document_.world().time();
        const std::vector<double>& times = recorder_.phaseTimes();
        const auto at = std::lower_bound(times.begin(), times.end(), t);
        std::optional<ui::PhaseSample> phase;
        if (at != times.end() && *at == t)
            phase = recorder_.phaseSamples()[static_cast<std::size_t>(at - times.begin())];
        panel_.setTimeCursor(t, phase);
    } else {
        panel_.setTimeCursor(std::numeric_limits<double>::quiet_NaN(), std::nullopt);
    }
    panel_.setEnergy(recorder_.energySamples(), recorder_.markers(), energyTitle());
    panel_.setError(recorder_.errorSamples(), errorTitle(), errorNote());
    const QString object = recorder_.phaseObject();
    if (object.isEmpty()) {
        panel_.setPhase({}, {}, {}, tr("Phase space"));
        return;
    }
    const QString coordinate = object + QLatin1Char('.') + recorder_.phaseCoordinate();
    panel_.setPhase(recorder_.phaseSamples(), coordinate,
                    object + QLatin1Char('.') + recorder_.phaseVelocityName(),
                    tr("Phase space of %1").arg(coordinate));
}

// The phase plot follows the first selected particle, box, disk or cloth node.
void PlotsPresenter::followSelection() {
    const QStringList selection = document_.selection();
    const QString first = selection.isEmpty() ? QString() : selection.first();
    const ObjectRef ref = findObject(document_.setup(), first.toStdString());
    const bool isNode = first.contains(QLatin1Char('['));
    const schema::KindInfo& kind = schema::kindInfo(ref.kind);
    if ((kind.body && !kind.nodes) || isNode) {
        const QString coordinate = defaultPhaseCoordinate(first);
        recorder_.setPhaseTarget(first, coordinate);
        panel_.setPhaseCoordinate(coordinate);
        // At an earlier moment of the timeline the world's clock is behind the series: recording
        // it would read as a new run and clear them.
        if (controller_.shownFrame() < 0) recorder_.record(document_.world());
    }
    refresh();
}

QString PlotsPresenter::defaultPhaseCoordinate(const QString& id) const {
    // The coordinate that moves: the larger live velocity component, or at rest the direction
    // gravity will move it.
    const World& w = document_.world();
    const std::string name = id.toStdString();
    Vec2 v = Vec2::Zero();
    for (std::size_t i = 0; i < w.particles().size(); ++i)
        if (w.particles()[i].id == name) v = w.particleVelocity(static_cast<int>(i));
    for (std::size_t i = 0; i < w.rigidBodies().size(); ++i)
        if (w.rigidBodies()[i].id == name) v = w.bodyVelocity(static_cast<int>(i));
    if (v.squaredNorm() == 0.0) {
        const auto& gravity = document_.setup().effects.gravity;
        if (gravity) v = Vec2(gravity->g[0], gravity->g[1]);
    }
    return std::abs(v.y()) > std::abs(v.x()) ? QStringLiteral("y") : QStringLiteral("x");
}

void PlotsPresenter::choosePhaseCoordinate(const QString& coordinate) {
    const QString object = recorder_.phaseObject();
    const ObjectRef ref = findObject(document_.setup(), object.toStdString());
    const bool turns = schema::kindInfo(ref.kind).rotates;
    if (object.isEmpty() || (coordinate == QLatin1String("angle") && !turns)) {
        emit message(object.isEmpty() ? tr("Click an object first.")
                                      : tr("Only rigid bodies have an angle."));
        panel_.setPhaseCoordinate(recorder_.phaseCoordinate());
        return;
    }
    recorder_.setPhaseTarget(object, coordinate);
    if (controller_.shownFrame() < 0) recorder_.record(document_.world());
    refresh();
}

bool PlotsPresenter::exportPlot(ui::PlotsPanel::Plot plot, const QString& path,
                                QString* error) const {
    using Plot = ui::PlotsPanel::Plot;
    if (!document_.mayWriteOutput(path, error)) return false;
    if (path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive)) {
        switch (plot) {
            case Plot::Energy:
                return recorder_.writeEnergyCsv(path, error);
            case Plot::Phase:
                return recorder_.writePhaseCsv(path, error);
            case Plot::Error:
                return recorder_.writeErrorCsv(path, error);
        }
    }
    // The picture is made from the recorded samples in a chart of its own, not grabbed from
    // the screen, so it is complete even while the plots are paused or the dock is hidden.
    std::unique_ptr<QChart> chart;
    if (plot == Plot::Energy) {
        chart.reset(
            ui::createEnergyChart(recorder_.energySamples(), recorder_.markers(), energyTitle()));
    } else if (plot == Plot::Error) {
        chart.reset(ui::createErrorChart(recorder_.errorSamples(), errorTitle()));
    } else {
        const QString object = recorder_.phaseObject();
        if (object.isEmpty()) {
            if (error) *error = tr("no object chosen for the phase plot: click one on the canvas");
            return false;
        }
        const QString coordinate = object + QLatin1Char('.') + recorder_.phaseCoordinate();
        const QString integrator = QString::fromStdString(document_.setup().simulation.integrator);
        chart.reset(ui::createPhaseChart(recorder_.phaseSamples(), coordinate,
                                         object + QLatin1Char('.') + recorder_.phaseVelocityName(),
                                         tr("Phase space of %1 (%2)").arg(coordinate, integrator),
                                         panel_.phaseReference(), panel_.phaseReferenceName()));
    }
    return writeChart(chart.get(), path, QSize(1200, 800), error);
}

void PlotsPresenter::addExportActions(QMenu& menu) {
    using Plot = ui::PlotsPanel::Plot;
    for (const auto& [plot, name] :
         {std::pair{Plot::Energy, tr("Energy Plot")}, std::pair{Plot::Phase, tr("Phase Plot")},
          std::pair{Plot::Error, tr("Error Plot")}})
        for (const QString& format :
             {QStringLiteral("png"), QStringLiteral("svg"), QStringLiteral("csv")})
            menu.addAction(tr("%1 as %2…").arg(name, format.toUpper()), this,
                           [this, plot = plot, format] { exportInteractively(plot, format); });
}

void PlotsPresenter::setPresentation(bool on) {
    panel_.setPresentation(on);
    refresh();
}

void PlotsPresenter::exportInteractively(ui::PlotsPanel::Plot plot, const QString& format) {
    const QString base = plot == ui::PlotsPanel::Plot::Energy  ? QStringLiteral("energy")
                         : plot == ui::PlotsPanel::Plot::Phase ? QStringLiteral("phase")
                                                               : QStringLiteral("error");
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    const QString path = QFileDialog::getSaveFileName(
        panel_.window(), tr("Export Plot"), QDir(dir).filePath(base + QLatin1Char('.') + format),
        format.toUpper() + QStringLiteral(" (*.") + format + QLatin1Char(')'));
    if (path.isEmpty()) return;
    QString error;
    if (!exportPlot(plot, path, &error))
        QMessageBox::warning(panel_.window(), tr("Export failed"), error);
    else
        emit message(tr("Wrote %1").arg(QDir::toNativeSeparators(path)));
}

}  // namespace phasebox
