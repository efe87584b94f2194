#include "app/desktop/presenters/EffectsPresenter.h"

#include "app/document/Document.h"
#include "app/sim/SimulationController.h"
#include "physics/core/EffectNames.h"
#include "physics/world/World.h"
#include "ui/panels/EffectsPanel.h"

#include <algorithm>
#include <string_view>
#include <vector>

namespace phasebox {

namespace {
QString qs(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}
}  // namespace

EffectsPresenter::EffectsPresenter(ui::EffectsPanel& panel, Document& document,
                                   SimulationController& controller, QObject* parent)
    : Presenter(parent), panel_(panel), document_(document), controller_(controller) {
    connect(&document_, &Document::sceneReset, this, [this] {
        switchedOff_.clear();
        updateRows();
    });
    connect(&document_, &Document::sceneEdited, this, &EffectsPresenter::updateRows);
    connect(&controller, &SimulationController::stepped, this, &EffectsPresenter::updateCosts);
    connect(&controller, &SimulationController::statsChanged, this, &EffectsPresenter::updateCosts);
    connect(&controller, &SimulationController::frameShown, this, &EffectsPresenter::updateCosts);
    connect(&panel_, &ui::EffectsPanel::effectToggled, this, &EffectsPresenter::setEnabled);
    connect(&panel_, &ui::EffectsPanel::addEffectRequested, this, &EffectsPresenter::add);
}

void EffectsPresenter::refresh() {
    showCosts();
}

void EffectsPresenter::setEnabled(const QString& name, bool on) {
    QString error;
    if (!document_.setEffectEnabled(name, on, &error)) {
        emit message(error);
    } else if (on) {
        switchedOff_.erase(name);
    } else {
        switchedOff_.insert(name);
    }
    updateRows();
}

void EffectsPresenter::add(const QString& name) {
    QString error;
    if (!document_.addEffect(name, &error)) emit message(error);
    switchedOff_.erase(name);
    updateRows();
}

void EffectsPresenter::updateRows() {
    std::vector<ui::EffectRow> rows;
    for (const QString& name : Document::effectNames()) {
        const bool on = document_.isEffectEnabled(name);
        if (on || switchedOff_.count(name)) rows.push_back({name, on, true, on ? 0.0 : -1.0, {}});
    }
    const World& world = document_.world();
    if (!world.springs().empty())
        rows.push_back(
            {qs(effectName::springs), true, false, 0.0, tr("Runs because the scene has springs")});
    if (world.contacts())
        rows.push_back({QStringLiteral("contacts"), true, false, 0.0,
                        tr("Runs because the scene holds things that can touch")});
    rows.push_back({ui::EffectsPanel::kIntegratorRow, true, false, 0.0,
                    tr("The integrator's own arithmetic")});
    panel_.setEffects(rows);
    updateCosts();
}

void EffectsPresenter::updateCosts() {
    showCosts();  // a new or reset world clears the last run's figures
}

void EffectsPresenter::showCosts() {
    const World& world = document_.world();
    // Means over the steps the profile timed (a world that has not stepped shows none: what
    // building it evaluated is no step), whichever frame the world shows.
    const StepProfile& profile = world.stepProfile();
    panel_.setCosts(world.effectCosts(), profile.steps, world.integratorSeconds());
    std::vector<ui::StageCost> stages;
    for (int i = 0; i < StepProfile::kStageCount; ++i) {
        const std::string_view name = StepProfile::kStageNames[static_cast<std::size_t>(i)];
        stages.push_back({QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())),
                          profile.steps > 0 && profile.ran(i) ? profile.msPerStep(i) : -1.0});
    }
    panel_.setStageCosts(stages);
    panel_.setCostNote(controller_.shownFrame() >= 0 && profile.steps > 0
                           ? tr("Costs per step of the whole run: a recorded frame keeps no "
                                "timing of its own.")
                           : QString());
}

}  // namespace phasebox
