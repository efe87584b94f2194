#include "app/desktop/presenters/InstrumentBase.h"

#include "app/document/Document.h"
#include "app/sim/ProbeRecorder.h"
#include "app/sim/SimulationController.h"
#include "physics/world/World.h"
#include "ui/instruments/ProbePicker.h"

#include <limits>

namespace phasebox {

QString shortProbeReason(const QString& error) {
    const qsizetype known = error.indexOf(QLatin1String("; known:"));
    return known < 0 ? error : error.left(known);
}

bool isJointId(const World& world, const std::string& id) {
    for (const Joint& j : world.joints())
        if (j.id == id) return true;
    return false;
}

InstrumentBase::InstrumentBase(ui::InstrumentsPanel& panel, Document& document,
                               ProbeRecorder& probes, QObject* parent)
    : Presenter(parent), panel_(panel), document_(document), probes_(probes) {}

bool InstrumentBase::check(const QString& text, ui::ProbePicker* picker, QString* error) {
    QString why;
    if (text.isEmpty() || ProbeRecorder::parse(document_.world(), text, &why)) {
        if (picker) picker->setInvalid({});
        return true;
    }
    const QString reason = shortProbeReason(why);
    if (picker) picker->setInvalid(reason);
    emit message(reason);
    if (error) *error = why;
    return false;
}

double InstrumentBase::shownTime() const {
    if (!controller_ || controller_->shownFrame() < 0)
        return std::numeric_limits<double>::quiet_NaN();
    return document_.world().time();
}

}  // namespace phasebox
