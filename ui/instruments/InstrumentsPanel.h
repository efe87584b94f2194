#pragma once
// The Instruments dock: a teacher's measuring kit, one tab each, all reading probes
// (CONTRACT §7): readouts of the selection, graphs of any probe, a period timer with a
// stopwatch, and the data table of what was recorded.

#include <QStringList>
#include <QWidget>

QT_BEGIN_NAMESPACE
class QTabWidget;
QT_END_NAMESPACE

namespace phasebox::ui {

class GraphsView;
class ProbeTableView;
class ReadoutView;
class TimerView;

class InstrumentsPanel : public QWidget {
    Q_OBJECT

public:
    enum class Tab { Readouts, Graphs, Timer, Table };

    explicit InstrumentsPanel(QWidget* parent = nullptr);

    ReadoutView* readouts() const { return readouts_; }
    GraphsView* graphs() const { return graphs_; }
    TimerView* timer() const { return timer_; }
    ProbeTableView* table() const { return table_; }

    Tab currentTab() const;
    void showTab(Tab tab);
    // The probes the scene offers, for every picker.
    void setOffered(const QStringList& probes);

signals:
    void tabChanged(phasebox::ui::InstrumentsPanel::Tab tab);

private:
    QTabWidget* tabs_ = nullptr;
    ReadoutView* readouts_ = nullptr;
    GraphsView* graphs_ = nullptr;
    TimerView* timer_ = nullptr;
    ProbeTableView* table_ = nullptr;
};

}  // namespace phasebox::ui
