#include "app/desktop/presenters/PropertiesPresenter.h"

#include "app/document/Document.h"
#include "app/document/PropertyTable.h"
#include "app/sim/SimulationController.h"
#include "physics/scene/StateTransfer.h"
#include "physics/world/World.h"
#include "ui/panels/PropertiesPanel.h"
#include "ui/panels/ShownNumber.h"

#include <variant>
#include <vector>

namespace phasebox {

PropertiesPresenter::PropertiesPresenter(ui::PropertiesPanel& panel, Document& document,
                                         SimulationController& controller, QObject* parent)
    : Presenter(parent), panel_(panel), document_(document), controller_(controller) {
    connect(&document_, &Document::sceneReset, this, [this] { update(true); });
    connect(&document_, &Document::sceneEdited, this, [this] { update(true); });
    connect(&document_, &Document::selectionChanged, this, [this] {
        update(true);
        if (panel_.hasObject()) emit objectShown();
    });
    connect(&controller, &SimulationController::stepped, this, &PropertiesPresenter::refresh);
    connect(&panel_, &ui::PropertiesPanel::propertyEdited, this, &PropertiesPresenter::edit);
}

void PropertiesPresenter::update(bool rebuild) {
    const QStringList selection = document_.selection();
    const SceneDesc& setup = document_.setup();
    const ObjectRef ref =
        findObject(setup, selection.size() == 1 ? selection.first().toStdString() : std::string());
    if (!ref.isValid()) {
        shownId_.clear();
        panel_.clearObject();
        return;
    }
    const QString id = QString::fromStdString(objectId(setup, ref));  // a cloth node: its cloth
    // Once the clock has left 0 the numbers are the run's (what the canvas shows), labelled
    // live; at the setup they are what Reset returns to. An edit of a live position or
    // velocity starts the object from the number typed (Document::moveObject's rule).
    const World& world = document_.world();
    // Only bodies have a state of their own in a scene (a cloth's nodes, a spring, a joint and
    // a plane keep their setup numbers while it runs).
    const schema::KindInfo& kind = schema::kindInfo(ref.kind);
    const bool body = kind.body && !kind.nodes;
    const bool live = body && document_.hasRun();
    // The selected body alone, snapshotted (this runs every frame: not the whole scene).
    SceneDesc liveScene;
    if (live) {
        std::visit([&](const auto& desc) { arrayOf(liveScene, desc).push_back(desc); },
                   objectDesc(setup, ref));
        liveScene = snapshotScene(world, liveScene);
    }
    std::vector<ui::PropertyField> fields;
    for (const PropertyRow& row : propertiesOf(live ? liveScene : setup, id))
        fields.push_back({row.key, row.label, row.unit, row.value, row.minimum, row.maximum,
                          row.decimals, row.isBool});
    if (rebuild || id != shownId_) {
        shownId_ = id;
        panel_.setObject(objectKindName(ref.kind) + QStringLiteral(" ") + id, fields);
    } else {
        panel_.updateValues(fields);
    }
    // A moment the timeline shows is the run's state then, and named so.
    const bool recorded = controller_.shownFrame() >= 0;
    const QString note = live && recorded ? tr("Recorded at t = %1 s; Reset shows the setup")
                                                .arg(ui::shownNumber(world.time(), 'f', 3))
                         : live ? tr("Live at t = %1 s; Reset shows the setup")
                                      .arg(ui::shownNumber(world.time(), 'f', 3))
                         : document_.hasRun()
                             ? tr("The setup's numbers (the run is at t = %1 s)")
                                   .arg(ui::shownNumber(world.time(), 'f', 3))
                             : tr("Setup: the state at t = 0, what Reset returns to");
    panel_.setStateNote(note, live);
}

void PropertiesPresenter::edit(const QString& key, double value) {
    QString error;
    // The row that pins the object (a particle's pinned, a box's static) goes through the pin
    // command, like the pin tool.
    const ObjectKind kind = findObject(document_.setup(), shownId_.toStdString()).kind;
    const bool ok = key == pinPropertyKey(kind)
                        ? document_.setPinned(shownId_, value != 0.0, &error)
                        : document_.setProperty(shownId_, key, value, &error);
    if (ok)
        panel_.clearError();
    else
        panel_.showError(error);
    document_.finishInteraction();
}

}  // namespace phasebox
