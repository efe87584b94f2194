#pragma once
// The Instruments dock's readouts (Readouts tab): the selection's position, velocity, energy and
// momentum, the distance and angle between two or three selected objects, a joint's force.

#include "app/desktop/presenters/InstrumentBase.h"

namespace phasebox {

class ReadoutsPresenter : public InstrumentBase {
    Q_OBJECT

public:
    ReadoutsPresenter(ui::InstrumentsPanel& panel, Document& document, ProbeRecorder& probes,
                      QObject* parent = nullptr);

    void refresh() override;
};

}  // namespace phasebox
