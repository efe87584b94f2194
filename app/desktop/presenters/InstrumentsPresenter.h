#pragma once
// The Instruments dock (ui::InstrumentsPanel): readouts of the selection, graphs of probes, the
// period timer and stopwatch, and the data table, all fed from the ProbeRecorder, which records
// exactly the probes they show (the graphs', the timer's and the table's own columns).
//
// It keeps the instruments honest about the scene: the pickers offer only probes that parse in
// the current world (the selection's first); typed text that is no probe is refused with the
// reason; after every rebuild of the world the probes are parsed again, so a probe whose object
// was deleted or renamed is shown as invalid rather than read from another object. New, Open
// (reopening a file: a revert) and Reset, all Document::sceneReset, clear every recording and the
// stopwatch; an edit at the setup (t = 0) records the setup sample anew.
//
// Each instrument has a presenter of its own (ReadoutsPresenter, ProbeGraphsPresenter,
// PeriodTimerPresenter, StopwatchPresenter, ProbeTablePresenter); this one owns them, follows the
// document and the controller for them, keeps the pickers' offer and gathers the probes they
// record.

#include "app/desktop/presenters/Presenter.h"
#include "app/sim/Stopwatch.h"

#include <QElapsedTimer>
#include <QString>
#include <QStringList>

QT_BEGIN_NAMESPACE
class QMenu;
QT_END_NAMESPACE

namespace phasebox {

struct InstrumentsDesc;
class Document;
class ProbeRecorder;
class SimulationController;
class ReadoutsPresenter;
class ProbeGraphsPresenter;
class PeriodTimerPresenter;
class StopwatchPresenter;
class ProbeTablePresenter;
namespace ui {
class InstrumentsPanel;
}  // namespace ui

class InstrumentsPresenter : public Presenter {
    Q_OBJECT

public:
    InstrumentsPresenter(ui::InstrumentsPanel& panel, Document& document,
                         SimulationController& controller, ProbeRecorder& probes,
                         QObject* parent = nullptr);

    void refresh() override;
    // Start/stop and lap of the stopwatch, Instruments (raise the dock), for the Tools menu.
    void createActions(QWidget& window);
    // "Probe Table as CSV…", for File → Export.
    void addExportActions(QMenu& menu);

    // The probes the pickers offer now.
    QStringList offered() const { return offered_; }
    // The canvas instruments' probes (a ruler's distance(A,B), a protractor's angle(A,B,C)):
    // offered first, after the selection's, while they stand.
    void setInstrumentProbes(const QStringList& probes);

    // Plots y against x ("" = time) in the first empty graph, or a new one; false with a
    // message (and *error) when either is not a probe of the scene or no graph is left.
    bool plotProbe(const QString& y, const QString& x = {}, QString* error = nullptr);
    // Sets graph index's probes; false (graph unchanged) when one is not a probe.
    bool setGraph(int index, const QString& y, const QString& x = {}, QString* error = nullptr);
    // The period timer's probe ("" for none).
    bool timeProbe(const QString& probe, QString* error = nullptr);
    bool addTableColumn(const QString& probe, QString* error = nullptr);
    void removeTableColumn(const QString& probe);

    // A graph as PNG, SVG (its chart, 1200 × 800) or CSV (t, then x when against a probe, then
    // y), chosen by the file's extension.
    bool exportGraph(int index, const QString& path, QString* error) const;
    // The data table as CSV: t and every recorded probe.
    bool exportTable(const QString& path, QString* error) const;
    // Copies the table's selected rows (all when none) as tab-separated text.
    void copyTable() const;

    // A lesson's instruments (CONTRACT §7, InstrumentsLesson.cpp): set from the opened file
    // (replacing every graph, the timer and the table; New brings none), and what is set now
    // for Save: probes, graphs, timers and the stopwatch.
    void applyInstruments(const InstrumentsDesc& instruments);
    void collectInstruments(InstrumentsDesc& instruments) const;

    Stopwatch& stopwatch();
    void startStopStopwatch();
    void lapStopwatch();
    void resetStopwatch();

    // Readouts cost little and follow every frame; the graphs, timer and table are rebuilt at
    // most this often while running (a chart of a few thousand points costs milliseconds).
    static constexpr qint64 kRefreshIntervalMs = 250;
    // Past this many objects only the selection's probes are listed (typing still works).
    static constexpr int kMaxListedObjects = 300;

signals:
    // An instrument was asked for (from the readouts' menu, the command line): show the dock.
    void instrumentsWanted();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void onSceneReset();
    void onSceneEdited();
    void updateOffered();
    // The probes of every instrument, in the order the table shows them.
    void updateRecordedProbes();
    void refreshShown();

    ui::InstrumentsPanel& panel_;
    Document& document_;
    SimulationController& controller_;
    ProbeRecorder& probes_;
    ReadoutsPresenter* readouts_;
    ProbeGraphsPresenter* graphs_;
    PeriodTimerPresenter* timer_;
    StopwatchPresenter* stopwatch_;
    ProbeTablePresenter* table_;
    QStringList savedTimers_;  // the lesson's period timers (the window times the first)
    QStringList offered_;
    QStringList instrumentProbes_;
    QElapsedTimer sinceRefresh_;
};

}  // namespace phasebox
