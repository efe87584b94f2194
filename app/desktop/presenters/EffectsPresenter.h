#pragma once
// The Effects dock: the effects the scene lists (a check box each, switched on and off as undo
// steps), the stages the world runs because of what the scene holds (springs, contacts), and
// what each costs per step while the simulation runs, with the step profile (World::stepProfile):
// the cost of each stage of the step. Costs are means over the steps timed; a recorded frame
// keeps no timing, so at a frame the timeline shows they stay the run's, and say so.

#include "app/desktop/presenters/Presenter.h"

#include <set>

namespace phasebox {

class Document;
class SimulationController;
namespace ui {
class EffectsPanel;
}

class EffectsPresenter : public Presenter {
    Q_OBJECT

public:
    EffectsPresenter(ui::EffectsPanel& panel, Document& document, SimulationController& controller,
                     QObject* parent = nullptr);

    // The rows' costs from the world's profile, even before the first step.
    void refresh() override;

private:
    void setEnabled(const QString& name, bool on);
    void add(const QString& name);
    void updateRows();
    // The costs once the world has stepped (cheap enough for every frame).
    void updateCosts();
    void showCosts();

    ui::EffectsPanel& panel_;
    Document& document_;
    SimulationController& controller_;
    std::set<QString> switchedOff_;  // effects switched off this scene: shown unchecked
};

}  // namespace phasebox
