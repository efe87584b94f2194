#pragma once
// The live plots: energy against time and the phase space of one coordinate, stacked in a
// splitter, with Pause, Clear and Export buttons. The charts are the ones of Charts.h, so a
// plot on screen is the plot `phasebox-cli run --plot-energy` writes.
//
// The panel only shows data and emits requests; the app feeds it (at a few frames per second:
// rebuilding a chart of a few thousand decimated points costs a few milliseconds) and does the
// exporting.

#include "ui/plots/Charts.h"

#include <QWidget>

#include <limits>
#include <optional>
#include <span>
#include <vector>

QT_BEGIN_NAMESPACE
class QChartView;
class QComboBox;
class QTabWidget;
class QLabel;
class QToolButton;
QT_END_NAMESPACE

namespace phasebox::ui {

// A recorded run drawn beside the live one (Compare from here): its total energy and its phase
// trace, dashed and lighter, under one legend name. Drawn up to the time the plots reach (the
// last energy sample, or the timeline's cursor), so the two runs are seen to part as they run.
struct GhostLines {
    QString name;
    std::vector<QPointF> energy;  // (t, kinetic + potential)
    std::vector<double> phaseTimes;
    std::vector<PhaseSample> phase;
    QString phaseCoordinate;  // the phase plot's coordinate name the trace is of
};

class PlotsPanel : public QWidget {
    Q_OBJECT

public:
    enum class Plot { Energy, Phase, Error };

    explicit PlotsPanel(QWidget* parent = nullptr);

    // Replaces what the energy plot shows (ignored while paused).
    void setEnergy(std::span<const EnergySample> samples, std::span<const PlotMarker> markers,
                   const QString& title);
    // Replaces the phase plot; an empty coordinate name shows how to choose an object.
    void setPhase(std::span<const PhaseSample> samples, const QString& coordinateName,
                  const QString& velocityName, const QString& title);

    // The exact solution's curve in the phase plot's coordinates, kept for every later
    // setPhase (empty: none, the scene has no closed form or the overlay is off).
    void setPhaseReference(std::vector<PhaseSample> samples, const QString& name);
    const std::vector<PhaseSample>& phaseReference() const { return phaseReference_; }
    const QString& phaseReferenceName() const { return phaseReferenceName_; }

    // The live error estimate; an empty series shows why there is none (text).
    void setError(std::span<const QPointF> samples, const QString& title, const QString& emptyText);

    // The moment the timeline shows, marked in the plots from their next update: a vertical
    // line at time t in the energy plot (NaN: none, the live end) and the state then in the
    // phase plot (none when phase is empty).
    void setTimeCursor(double t, std::optional<PhaseSample> phase);
    double timeCursor() const { return cursorTime_; }

    // The ghost lines from the next update on (an empty name: none).
    void setGhost(GhostLines ghost);
    const GhostLines& ghost() const { return ghost_; }

    // The plot shown below the energy plot (Phase or Error), and showing one there.
    Plot lowerPlot() const;
    void showLowerPlot(Plot plot);
    // Shows which coordinate the phase plot has (no signal).
    void setPhaseCoordinate(const QString& coordinate);

    bool isPaused() const { return paused_; }
    void setPaused(bool paused);
    // Larger fonts and lines for presentation mode.
    void setPresentation(bool on);

    QChartView* energyView() const { return energyView_; }
    QChartView* phaseView() const { return phaseView_; }
    QChartView* errorView() const { return errorView_; }
    // The names of a chart's lines below it, in as many rows as they need, when one row under
    // the chart would cut them (a narrow dock); hidden while the chart's own legend shows.
    QLabel* energyLegend() const { return energyLegend_; }
    QLabel* phaseLegend() const { return phaseLegend_; }

signals:
    void clearRequested();
    // The user chose another coordinate for the phase plot: "x", "y" or "angle".
    void phaseCoordinateRequested(const QString& coordinate);
    void pausedChanged(bool paused);
    // format: "png", "svg" or "csv".
    void exportRequested(phasebox::ui::PlotsPanel::Plot plot, const QString& format);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void styleChart(QChartView* view);
    QLabel* legendOf(const QChartView* view) const;

    QChartView* energyView_ = nullptr;
    QChartView* phaseView_ = nullptr;
    QChartView* errorView_ = nullptr;
    QLabel* errorHint_ = nullptr;
    QLabel* energyLegend_ = nullptr;
    QLabel* phaseLegend_ = nullptr;
    QLabel* phaseHint_ = nullptr;
    QComboBox* coordinateBox_ = nullptr;
    QTabWidget* lowerTabs_ = nullptr;
    QToolButton* pauseButton_ = nullptr;
    bool paused_ = false;
    bool presentation_ = false;
    std::vector<PhaseSample> phaseReference_;
    QString phaseReferenceName_;
    double cursorTime_ = std::numeric_limits<double>::quiet_NaN();
    std::optional<PhaseSample> cursorPhase_;
    GhostLines ghost_;
    double ghostUntil_ = -std::numeric_limits<double>::infinity();
};

}  // namespace phasebox::ui
