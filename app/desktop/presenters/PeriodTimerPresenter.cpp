#include "app/desktop/presenters/PeriodTimerPresenter.h"

#include "app/sim/ProbeRecorder.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/instruments/ProbeFormat.h"
#include "ui/instruments/ProbePicker.h"
#include "ui/instruments/TimerView.h"
#include "ui/panels/ShownNumber.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace phasebox {

PeriodTimerPresenter::PeriodTimerPresenter(ui::InstrumentsPanel& panel, Document& document,
                                           ProbeRecorder& probes, QObject* parent)
    : InstrumentBase(panel, document, probes, parent) {
    connect(panel_.timer(), &ui::TimerView::probeEntered, this,
            [this](const QString& p) { timeProbe(p); });
}

bool PeriodTimerPresenter::timeProbe(const QString& probe, QString* error) {
    if (!check(probe, panel_.timer()->picker(), error)) return false;
    panel_.timer()->picker()->setProbe(probe);
    if (probe == probe_) return true;
    probe_ = probe;
    emit probesChanged();
    refresh();
    emit tableStale();
    return true;
}

void PeriodTimerPresenter::clear() {
    probe_.clear();
    panel_.timer()->picker()->setProbe({});
    panel_.timer()->picker()->setInvalid({});
}

void PeriodTimerPresenter::refresh() {
    ui::TimerView* view = panel_.timer();
    if (probe_.isEmpty()) {
        view->setPeriod(std::nullopt,
                        tr("Pick a probe (an object's x for a swing), then press Play: the period "
                           "is the mean interval between its upward crossings of the middle of "
                           "its range."),
                        {});
        return;
    }
    const int i = probes_.indexOf(probe_);
    if (i < 0 || !probes_.isValid(i)) {
        view->setPeriod(
            std::nullopt,
            i < 0 ? QString()
                  : tr("%1 cannot be read in this scene.").arg(shortProbeReason(probes_.error(i))),
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
                     .arg(probe_);
    } else {
        // The level to the range's fifth digit: a swing about 0 shows 0.0000, not 3e-06.
        const double range = s.max - s.min;
        const int decimals =
            range > 0.0 ? std::clamp(4 - static_cast<int>(std::floor(std::log10(range))), 0, 12)
                        : 4;
        detail =
            tr("Mean interval between the upward crossings of %1 through %2 %3, the middle "
               "of its range [%4, %5] %3, each interpolated within its step.")
                .arg(probe_,
                     ui::shownNumber(level, 'f', decimals).replace(QLatin1Char('-'), QChar(0x2212)),
                     unit, ui::formatReading(s.min), ui::formatReading(s.max));
    }
    view->setPeriod(s.period, detail, crossings);
}

}  // namespace phasebox
