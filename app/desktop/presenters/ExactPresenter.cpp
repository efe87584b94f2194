#include "app/desktop/presenters/ExactPresenter.h"

#include "app/document/Document.h"
#include "app/sim/Recorder.h"
#include "app/sim/SimulationController.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneView.h"
#include "ui/panels/ShownNumber.h"
#include "ui/plots/PlotsPanel.h"

#include <QAction>

#include <algorithm>
#include <cmath>

namespace phasebox {

ExactPresenter::ExactPresenter(ui::SceneView& view, ui::PlotsPanel& plots, Document& document,
                               SimulationController& controller, const Recorder& recorder,
                               QObject* parent)
    : Presenter(parent), view_(view), plots_(plots), document_(document), recorder_(recorder) {
    connect(&document_, &Document::sceneReset, this, &ExactPresenter::rebuild);
    connect(&document_, &Document::sceneEdited, this, &ExactPresenter::rebuild);
    connect(&document_, &Document::simulationSettingsChanged, this, &ExactPresenter::rebuild);
    connect(&document_, &Document::selectionChanged, this, [this] {
        updatePhase();
        emit phaseReferenceChanged();
        refresh();
    });
    connect(&controller, &SimulationController::stepped, this, &ExactPresenter::refresh);
    sincePhase_.start();
    rebuild();
}

void ExactPresenter::createActions(QWidget& window) {
    action_ = addWindowAction(window, QStringLiteral("viewExact"), tr("E&xact Solution"),
                              QKeySequence(Qt::SHIFT | Qt::Key_E));
    action_->setCheckable(true);
    action_->setChecked(shown_);
    action_->setToolTip(
        tr("Draw the exact (closed-form) motion beside the simulation, dashed, "
           "when the scene has one: oscillators, free fall, orbits, pendulums, Atwood "
           "machines, rolling and sliding on ramps (until a contact begins or ends)"));
    connect(action_, &QAction::toggled, this, &ExactPresenter::setShown);
}

void ExactPresenter::setShown(bool on) {
    shown_ = on;
    if (action_ && action_->isChecked() != on) action_->setChecked(on);
    updatePhase();
    emit phaseReferenceChanged();
    refresh();
}

QString ExactPresenter::kind() const {
    return reference_ ? QString::fromStdString(reference_->kind()) : QString();
}

void ExactPresenter::rebuild() {
    reference_.reset();
    paths_.clear();
    const SceneDesc& setup = document_.setup();
    const std::size_t objects = setup.particles.size() + setup.boxes.size() + setup.disks.size() +
                                setup.polygons.size() + setup.cloths.size() * 100;
    if (objects > 0 && objects <= static_cast<std::size_t>(kMaxObjects)) {
        // The closed form starts from the setup at t = 0; the live world may be far from it.
        const World& live = document_.world();
        std::unique_ptr<World> built;
        if (live.time() != 0.0) built = buildWorld(setup).world;
        const World& start = built ? *built : live;
        const double duration = setup.simulation.duration;
        reference_ = findDisplayReference(setup, start, duration);
        dimension_ = start.dimension();
        if (reference_) {
            // Each moving particle's and body's path over the run (one period is enough for
            // what repeats; free motion over the whole duration).
            const std::vector<double> periods = reference_->periods();
            const double span = std::min(
                reference_->validUntil(),
                periods.empty()
                    ? duration
                    : std::min(duration, *std::max_element(periods.begin(), periods.end())));
            std::vector<int> dofs;
            for (const Particle& p : start.particles())
                if (p.dof >= 0 && p.cloth < 0 && reference_->covers(p.dof)) dofs.push_back(p.dof);
            for (const RigidBody& b : start.rigidBodies())
                if (b.dof >= 0 && reference_->covers(b.dof)) dofs.push_back(b.dof);
            if (dofs.size() > static_cast<std::size_t>(kMaxPaths)) dofs.resize(kMaxPaths);
            for (const int dof : dofs) {
                QPolygonF path;
                path.reserve(kPathSamples + 1);
                for (int i = 0; i <= kPathSamples; ++i) {
                    const double t = span * i / kPathSamples;
                    path.append(
                        QPointF(reference_->position(dof, t), reference_->position(dof + 1, t)));
                }
                paths_.append(path);
            }
        }
    }
    updatePhase();
    emit phaseReferenceChanged();
    refresh();
}

int ExactPresenter::phaseDof() const {
    const std::string id = recorder_.phaseObject().toStdString();
    if (id.empty()) return -1;
    const World& world = document_.world();
    const QString coordinate = recorder_.phaseCoordinate();
    const int axis = coordinate == QLatin1String("y") ? 1 : 0;
    for (const Particle& p : world.particles())
        if (p.id == id)
            return p.dof < 0 || coordinate == QLatin1String("angle") ? -1 : p.dof + axis;
    for (const RigidBody& b : world.rigidBodies())
        if (b.id == id)
            return b.dof < 0 ? -1 : b.dof + (coordinate == QLatin1String("angle") ? 2 : axis);
    return -1;
}

void ExactPresenter::updatePhase() {
    sincePhase_.restart();
    const World& world = document_.world();
    const int dof = shown_ && reference_ && world.dimension() == dimension_ ? phaseDof() : -1;
    if (dof < 0 || !reference_->covers(dof)) {
        if (!plots_.phaseReference().empty()) plots_.setPhaseReference({}, {});
        return;
    }
    // Over the times the simulation has covered, so the two curves can be compared as they grow
    // (up to where the closed form holds).
    const double end = std::min(world.time(), reference_->validUntil());
    std::vector<ui::PhaseSample> samples;
    samples.reserve(kPhaseSamples + 1);
    for (int i = 0; i <= kPhaseSamples; ++i) {
        const double t = end * i / kPhaseSamples;
        samples.push_back({reference_->position(dof, t), reference_->velocity(dof, t)});
    }
    plots_.setPhaseReference(std::move(samples), tr("exact"));
}

void ExactPresenter::refresh() {
    const World& world = document_.world();
    if (!shown_ || !reference_ || world.dimension() != dimension_) {
        if (!view_.referenceOverlay().isEmpty()) view_.setReferenceOverlay({});
        return;
    }
    if (sincePhase_.elapsed() >= kPhaseIntervalMs) updatePhase();
    ui::ReferenceOverlay overlay;
    overlay.paths = paths_;
    const double t = world.time();
    // Past the first contact that can happen the closed form says nothing: no ghosts then.
    const bool holds = t <= reference_->validUntil();
    int ghosts = holds ? 0 : kMaxPaths;
    for (const Particle& p : world.particles()) {
        if (p.dof < 0 || p.cloth >= 0 || !reference_->covers(p.dof) || ghosts++ >= kMaxPaths)
            continue;
        ui::ReferenceOverlay::Ghost ghost;
        ghost.centre = QPointF(reference_->position(p.dof, t), reference_->position(p.dof + 1, t));
        ghost.radius = p.radius;
        overlay.ghosts.append(ghost);
    }
    for (const RigidBody& b : world.rigidBodies()) {
        if (b.dof < 0 || !reference_->covers(b.dof) || ghosts++ >= kMaxPaths) continue;
        ui::ReferenceOverlay::Ghost ghost;
        ghost.centre = QPointF(reference_->position(b.dof, t), reference_->position(b.dof + 1, t));
        ghost.radius = b.shape == RigidShape::Disk ? b.radius : 0.0;
        // A rectangle turned by the closed form's angle, or by the simulation's where the
        // closed form gives none.
        if (b.shape == RigidShape::Rectangle) {
            ghost.size = QSizeF(b.size.x(), b.size.y());
            ghost.angle = reference_->covers(b.dof + 2) ? reference_->position(b.dof + 2, t)
                                                        : world.positions()[b.dof + 2];
        }
        overlay.ghosts.append(ghost);
    }
    overlay.label =
        std::isinf(reference_->validUntil())
            ? tr("dashed: exact solution (%1)").arg(kind())
            : tr("dashed: exact solution (%1) until t = %2 s, where a contact begins or ends")
                  .arg(kind())
                  .arg(ui::shownNumber(reference_->validUntil(), 'f', 2));
    view_.setReferenceOverlay(overlay);
}

}  // namespace phasebox
