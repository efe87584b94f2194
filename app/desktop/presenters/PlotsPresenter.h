#pragma once
// The Plots dock: energy, phase space and local error from the Recorder, redrawn at most every
// kPlotIntervalMs while running; the phase plot follows the selected particle or box. Also the
// plots' exports (PNG, SVG, CSV), drawn from the recorded samples rather than the screen.

#include "app/desktop/presenters/Presenter.h"
#include "ui/plots/PlotsPanel.h"

#include <QElapsedTimer>

QT_BEGIN_NAMESPACE
class QMenu;
QT_END_NAMESPACE

namespace phasebox {

class Document;
class Recorder;
class SimulationController;

class PlotsPresenter : public Presenter {
    Q_OBJECT

public:
    PlotsPresenter(ui::PlotsPanel& panel, Document& document, SimulationController& controller,
                   Recorder& recorder, QObject* parent = nullptr);

    void refresh() override;
    // Writes a plot as PNG, SVG or CSV, chosen by the file's extension.
    bool exportPlot(ui::PlotsPanel::Plot plot, const QString& path, QString* error) const;
    // Asks for a file name, then exports.
    void exportInteractively(ui::PlotsPanel::Plot plot, const QString& format);
    // "Energy Plot as PNG…" and the rest, into an Export menu.
    void addExportActions(QMenu& menu);
    // Larger type for a projector.
    void setPresentation(bool on);

    // A chart of a few thousand points costs a few milliseconds, which every frame would take
    // from the simulation.
    static constexpr qint64 kPlotIntervalMs = 250;

private:
    void followSelection();
    void choosePhaseCoordinate(const QString& coordinate);
    QString defaultPhaseCoordinate(const QString& id) const;
    QString energyTitle() const;
    QString errorTitle() const;
    QString errorNote() const;

    ui::PlotsPanel& panel_;
    Document& document_;
    SimulationController& controller_;
    Recorder& recorder_;
    QElapsedTimer sinceRefresh_;
};

}  // namespace phasebox
