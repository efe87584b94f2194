#pragma once
// The Instruments dock's period timer (Timer tab): the mean interval between a probe's upward
// crossings of the middle of its range.

#include "app/desktop/presenters/InstrumentBase.h"

#include <QString>

namespace phasebox {

class PeriodTimerPresenter : public InstrumentBase {
    Q_OBJECT

public:
    PeriodTimerPresenter(ui::InstrumentsPanel& panel, Document& document, ProbeRecorder& probes,
                         QObject* parent = nullptr);

    void refresh() override;

    // The timed probe ("" for none); false (unchanged) when it is not a probe.
    bool timeProbe(const QString& probe, QString* error = nullptr);
    QString probe() const { return probe_; }
    // Times nothing and clears the picker (a lesson's timers replace it).
    void clear();

private:
    QString probe_;
};

}  // namespace phasebox
