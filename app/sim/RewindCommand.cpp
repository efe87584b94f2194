#include "app/sim/RewindCommand.h"
#include "ui/panels/ShownNumber.h"

#include <QCoreApplication>

namespace phasebox {

RewindCommand::RewindCommand(SimulationController& controller, SimulationController::Branch dropped)
    : QUndoCommand(QCoreApplication::translate("RewindCommand", "Play from t = %1 s")
                       .arg(ui::shownNumber(dropped.time, 'f', 3))),
      controller_(controller),
      other_(std::move(dropped)) {}

}  // namespace phasebox
