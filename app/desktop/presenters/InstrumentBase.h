#pragma once
// What the instruments of the Instruments dock (ui::InstrumentsPanel) share: the panel, the
// document whose world they read, the ProbeRecorder that records their probes, and the check
// that refuses typed text that is no probe of the scene. InstrumentsPresenter owns one presenter
// per instrument and gathers the probes they record.

#include "app/desktop/presenters/Presenter.h"

#include <QString>

#include <string>

namespace phasebox {

class Document;
class ProbeRecorder;
class SimulationController;
class World;
namespace ui {
class InstrumentsPanel;
class ProbePicker;
}  // namespace ui

// A parse error without the vocabulary that follows it: `unknown probe "p3.x": no object "p3"`.
QString shortProbeReason(const QString& error);
// Whether an id names a joint of the world.
bool isJointId(const World& world, const std::string& id);

class InstrumentBase : public Presenter {
    Q_OBJECT

public:
    InstrumentBase(ui::InstrumentsPanel& panel, Document& document, ProbeRecorder& probes,
                   QObject* parent = nullptr);

    // The controller whose timeline the instrument follows (none: it shows the live state).
    void setController(const SimulationController* controller) { controller_ = controller; }

signals:
    // The instrument asks for the dock to be shown.
    void instrumentsWanted();
    // The probes this instrument records changed: the recorder's set is gathered anew.
    void probesChanged();
    // The table shows this instrument's probes: it is out of date.
    void tableStale();

protected:
    // Parses text; on failure marks the picker (if any), says why and returns false.
    bool check(const QString& text, ui::ProbePicker* picker, QString* error);
    // The time of the recorded frame the timeline shows (the world is in its state), NaN at the
    // live end.
    double shownTime() const;

    ui::InstrumentsPanel& panel_;
    Document& document_;
    ProbeRecorder& probes_;
    const SimulationController* controller_ = nullptr;
};

}  // namespace phasebox
