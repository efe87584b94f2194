#pragma once
// The Instruments dock's stopwatch (Timer tab) on simulated time: start/stop, laps, reset.

#include "app/desktop/presenters/InstrumentBase.h"
#include "app/sim/Stopwatch.h"

namespace phasebox {

class StopwatchPresenter : public InstrumentBase {
    Q_OBJECT

public:
    StopwatchPresenter(ui::InstrumentsPanel& panel, Document& document, ProbeRecorder& probes,
                       QObject* parent = nullptr);

    void refresh() override;

    Stopwatch& stopwatch() { return stopwatch_; }
    const Stopwatch& stopwatch() const { return stopwatch_; }
    void startStop();
    void lap();
    void reset();

    // A lesson times by hand: it was started once, or the lesson asks for it.
    bool used() const { return used_; }
    void setUsed(bool used) { used_ = used; }

private:
    Stopwatch stopwatch_;
    bool used_ = false;
};

}  // namespace phasebox
