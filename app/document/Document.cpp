#include "app/document/Document.h"

#include "app/document/Commands.h"
#include "app/io/OutputFile.h"
#include "app/io/SceneIO.h"
#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/effects/MouseSpringEffect.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/scene/SceneSchema.h"
#include "physics/scene/StateTransfer.h"
#include "physics/world/World.h"
#include "ui/panels/BuiltinText.h"

#include <QFileInfo>
#include <QtGlobal>

#include <cmath>
#include <numbers>
#include <string_view>
#include <type_traits>
#include <unordered_set>
#include <utility>

namespace phasebox {

namespace {
// Power iterations of the stability checks made while drawing (the Parameters panel's too).
constexpr int kAdviceIterations = 200;

QString keyText(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

// The effects a user switches on and off, by scene-format name (the schema's effect tables but
// those the objects imply), paired with the same member of a second EffectsDesc (the
// remembered parameters): fn(std::optional<XDesc>& a, std::optional<XDesc>& b).
template <typename Fn>
bool visitEffect(EffectsDesc& a, EffectsDesc& b, const QString& name, Fn&& fn) {
    bool found = false;
    schema::forEachEffect([&](const auto& table, auto member) {
        if (found || table.implied || name != keyText(table.key)) return;
        fn(a.*member, b.*member);
        found = true;
    });
    return found;
}

QString sceneErrorText(const SceneError& e) {
    return QString::fromStdString(e.what());
}

// The mouse spring's stiffness for a body of (effective) mass m: a 3 Hz pull, quick enough to
// follow the hand, slow enough (ω·dt ≈ 0.3 at 60 Hz) for every explicit method's stability limit.
constexpr double kGrabOmega = 2.0 * std::numbers::pi * 3.0;

Vec2 vec(const Point2& p) {
    return {p[0], p[1]};
}
}  // namespace

Document::Document(QObject* parent) : QObject(parent) {
    connect(&undoStack_, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
    world_ = buildWorld(setup_).world;  // an empty world until newScene() or a load
    world_->setWorkers(workers_);
}

void Document::setWorkers(int workers) {
    workers_ = workers;
    world_->setWorkers(workers_);
}

Document::~Document() {
    // The stack clears itself when it is destroyed, which would signal cleanChanged into a
    // document that is already half gone.
    disconnect(&undoStack_, nullptr, this, nullptr);
}

bool Document::hasRun() const {
    return world_->time() > 0.0;
}

// ---- files -----------------------------------------------------------------------------------

void Document::newScene() {
    loadFromDesc(scenes::untitled(), QString());
}

bool Document::load(const QString& path, QString* error) {
    const SceneLoadResult result = SceneIO::load(path);
    if (!result.ok()) {
        if (error) *error = result.errorText();
        return false;
    }
    return loadFromDesc(*result.scene, path, error);
}

bool Document::loadFromDesc(const SceneDesc& scene, const QString& path, QString* error) {
    SceneDesc normalized = scene;
    assignDefaultIds(normalized);
    BuildResult built;
    try {
        built = buildWorld(normalized);
    } catch (const SceneError& e) {
        if (error) *error = sceneErrorText(e);
        return false;
    }
    QStringList unsupported;
    for (const std::string& name : built.unsupported) unsupported << QString::fromStdString(name);
    replaceScene(std::move(normalized), std::move(built.world), unsupported, path);
    return true;
}

void Document::replaceScene(SceneDesc scene, std::unique_ptr<World> world, QStringList unsupported,
                            const QString& path) {
    setup_ = std::move(scene);
    loadedInstruments_ = std::exchange(setup_.instruments, {});
    world_ = std::move(world);
    world_->setWorkers(workers_);
    mouseSpring_ = nullptr;
    grab_.reset();
    unsupported_ = std::move(unsupported);
    rememberedEffects_ = EffectsDesc{};
    ++interaction_;
    const bool pathChanged = path != filePath_;
    filePath_ = path;
    selection_.clear();
    // The old commands edit the old setup: they go with it (clear() signals the clean state).
    undoStack_.clear();
    emit sceneReset();
    emit instrumentsLoaded();
    emit selectionChanged();
    if (pathChanged) emit filePathChanged(filePath_);
}

SceneDesc Document::sceneToSave() const {
    SceneDesc scene = setup_;
    if (instrumentsSource_) scene.instruments = instrumentsSource_();
    return scene;
}

bool Document::save(const QString& path, QString* error) {
    if (!SceneIO::save(sceneToSave(), path, error)) return false;
    undoStack_.setClean();
    if (path != filePath_) {
        filePath_ = path;
        emit filePathChanged(filePath_);
    }
    return true;
}

void Document::reset() {
    try {
        BuildResult built = buildWorld(setup_);
        world_ = std::move(built.world);
        world_->setWorkers(workers_);
    } catch (const SceneError& e) {
        // Commands keep the setup valid; reaching this is a bug, but not one to crash on.
        qWarning("Document::reset: %s", e.what());
        return;
    }
    mouseSpring_ = nullptr;
    grab_.reset();
    emit sceneReset();
}

// ---- edits -----------------------------------------------------------------------------------

bool Document::push(DocumentCommand* command, QString* error) {
    if (!command->isValid()) {
        if (error) *error = command->errorString();
        delete command;
        return false;
    }
    undoStack_.push(command);  // runs redo()
    return true;
}

bool Document::addObject(const ObjectDesc& object, QString* error, QString* newId) {
    QStringList ids;
    if (!addObjects({object}, error, &ids)) return false;
    if (newId) *newId = ids.front();
    return true;
}

bool Document::addObjects(std::vector<ObjectDesc> objects, QString* error, QStringList* newIds) {
    auto* command = new AddObjectsCommand(*this, std::move(objects));
    const QStringList ids = command->objectIds();
    if (!push(command, error)) return false;
    if (newIds) *newIds = ids;
    return true;
}

bool Document::addDrawnObject(const ObjectDesc& object, QString* error, QString* newId,
                              QString* notice) {
    auto* add = new AddObjectsCommand(*this, {object});
    if (!add->isValid()) return push(add, error);
    if (newId) *newId = add->objectIds().front();
    // Stable now and not with the object: the method the advisor recommends instead, the
    // symplectic ones first (they keep the energy), then implicit Euler.
    std::string method;
    if (adviseStability(*world_, kAdviceIterations).currentStable) {
        BuildResult trial;
        try {
            trial = buildWorld(add->appliedTo(setup_));
        } catch (const SceneError&) {
            return push(add, error);  // validated: cannot happen; the command reports it
        }
        const StabilityAdvice after = adviseStability(*trial.world, kAdviceIterations);
        if (!after.currentStable) {
            for (const char* preferred :
                 {"symplectic_euler", "velocity_verlet", "implicit_euler", "implicit_midpoint"})
                for (const StepLimit& limit : after.recommended)
                    if (method.empty() && limit.integrator == preferred) method = preferred;
        }
    }
    if (method.empty()) return push(add, error);
    SimulationDesc simulation = setup_.simulation;
    const std::string before = simulation.integrator;
    simulation.integrator = method;
    // The switch is an undo step of its own after the object's: one Undo gives the method back
    // and keeps what was drawn, a second takes the object away.
    if (!push(add, error)) return false;
    const bool switched = push(new SetSimulationCommand(*this, simulation), error);
    if (switched && notice) {
        const auto label = [](const std::string& name) {
            const IntegratorInfo* info = findIntegrator(name);
            return info ? ui::integratorText(info->label) : QString::fromStdString(name);
        };
        *notice = tr("Switched to %1 so the %2 stays stable; Undo to go back to %3")
                      .arg(label(method), objectKindName(objectKind(object)), label(before));
    }
    return true;
}

bool Document::deleteObjects(const QStringList& ids, QString* error) {
    return push(new DeleteObjectsCommand(*this, ids), error);
}

bool Document::moveObject(const QString& id, const Point2& position, QString* error) {
    return push(new MoveObjectCommand(*this, id, position), error);
}

bool Document::setProperty(const QString& id, const QString& key, double value, QString* error) {
    return push(new SetPropertyCommand(*this, id, key, value), error);
}

bool Document::setPinned(const QString& id, bool pinned, QString* error) {
    return push(new SetPinnedCommand(*this, id, pinned), error);
}

bool Document::applySimulationSettings(const SimulationDesc& simulation, QString* error) {
    return push(new SetSimulationCommand(*this, simulation), error);
}

void Document::commitSetupEdit(const SetupEdit& edit, const QStringList& moved) {
    edit(setup_);
    BuildResult built;
    try {
        built = buildWorld(setup_);
    } catch (const SceneError& e) {
        qWarning("Document: an edit left an invalid scene: %s", e.what());
        return;
    }
    if (hasRun()) {
        // The moved objects start from their new setup values; a moved cloth with all its nodes.
        std::unordered_set<std::string> keep;
        for (const QString& qid : moved) {
            const std::string id = qid.toStdString();
            keep.insert(id);
            for (const std::string& node : nodeIds(setup_, findObject(setup_, id)))
                keep.insert(node);
        }
        transferState(*world_, *built.world, keep);
    }
    world_ = std::move(built.world);
    world_->setWorkers(workers_);
    unsupported_.clear();
    for (const std::string& name : built.unsupported) unsupported_ << QString::fromStdString(name);
    mouseSpring_ = nullptr;
    attachGrab();
    pruneSelection();
    emit sceneEdited();
}

void Document::commitSimulationEdit(const SetupEdit& edit) {
    edit(setup_);
    const SimulationDesc& sim = setup_.simulation;
    // Validated by the command; setSettings would throw (and change nothing) otherwise.
    world_->setSettings(simulationSettings(sim));
    emit simulationSettingsChanged();
}

// ---- effects ---------------------------------------------------------------------------------

QStringList Document::effectNames() {
    QStringList names;
    schema::forEachEffect([&](const auto& table, auto) {
        if (!table.implied) names << keyText(table.key);
    });
    return names;
}

bool Document::isEffectEnabled(const QString& name) const {
    bool enabled = false;
    EffectsDesc effects = setup_.effects, unused;
    visitEffect(effects, unused, name, [&](auto& effect, auto&) { enabled = effect.has_value(); });
    return enabled;
}

bool Document::setEffectEnabled(const QString& name, bool enabled, QString* error) {
    EffectsDesc effects = setup_.effects;
    bool change = false;
    const bool known =
        visitEffect(effects, rememberedEffects_, name, [&](auto& effect, auto& remembered) {
            if (effect.has_value() == enabled) return;
            change = true;
            if (enabled) {
                effect = remembered ? *remembered
                                    : typename std::decay_t<decltype(effect)>::value_type{};
            } else {
                remembered = effect;
                effect.reset();
            }
        });
    if (!known) {
        if (error)
            *error = tr("unknown effect \"%1\"; known: %2")
                         .arg(name, effectNames().join(QStringLiteral(", ")));
        return false;
    }
    if (!change) return true;
    const QString text = enabled ? tr("Switch on %1").arg(name) : tr("Switch off %1").arg(name);
    return push(new SetEffectCommand(*this, effects, text), error);
}

bool Document::addEffect(const QString& name, QString* error) {
    EffectsDesc unused;
    visitEffect(rememberedEffects_, unused, name,
                [](auto& remembered, auto&) { remembered.reset(); });
    return setEffectEnabled(name, true, error);
}

bool Document::setEffects(const EffectsDesc& effects, const QString& mergeKey, QString* error) {
    const QString text = mergeKey.isEmpty() ? tr("Change effects") : tr("Change %1").arg(mergeKey);
    return push(new SetEffectCommand(*this, effects, text, mergeKey), error);
}

// ---- selection -------------------------------------------------------------------------------

void Document::setSelection(const QStringList& ids) {
    if (ids == selection_) return;
    selection_ = ids;
    emit selectionChanged();
}

void Document::pruneSelection() {
    QStringList kept;
    for (const QString& id : selection_)
        if (findObject(setup_, id.toStdString()).isValid()) kept << id;
    setSelection(kept);
}

// ---- mouse spring ----------------------------------------------------------------------------

bool Document::grab(const QString& id, const Point2& localPoint, const Point2& target) {
    releaseGrab();
    const std::string name = id.toStdString();
    double mass = 0.0;
    for (const Particle& p : world_->particles())
        if (p.id == name && !p.pinned) mass = p.mass;
    for (const RigidBody& b : world_->rigidBodies())
        if (b.id == name && !b.isStatic)
            mass = MouseSpringEffect::effectiveMass(b.mass, b.inertia, vec(localPoint));
    if (!(mass > 0.0)) return false;
    grab_ = Grab{name, localPoint, target, mass * kGrabOmega * kGrabOmega};
    attachGrab();
    return mouseSpring_ != nullptr;
}

void Document::attachGrab() {
    if (!grab_) return;
    auto spring = std::make_unique<MouseSpringEffect>(grab_->id, vec(grab_->localPoint),
                                                      vec(grab_->target), grab_->stiffness);
    mouseSpring_ = spring.get();
    world_->addEffect(std::move(spring));
    world_->commit();  // binds the spring to its body now, so isAttached() tells the truth
    if (!mouseSpring_->isAttached()) releaseGrab();  // the body was deleted or pinned
}

void Document::moveGrab(const Point2& target) {
    if (!grab_) return;
    grab_->target = target;
    if (mouseSpring_) mouseSpring_->setTarget(vec(target));
}

void Document::releaseGrab() {
    if (mouseSpring_) world_->removeEffect(mouseSpring_);
    mouseSpring_ = nullptr;
    grab_.reset();
}

const MouseSpringEffect* Document::mouseSpring() const {
    return mouseSpring_;
}

bool Document::mayWriteOutput(const QString& path, QString* error) const {
    return mayWriteOutput(path, filePath_, error);
}

bool Document::mayWriteOutput(const QString& path, const QString& sceneFile, QString* error) {
    if (sceneFile.isEmpty() || sceneFile.startsWith(QLatin1Char(':'))) return true;
    const QString canonical = QFileInfo(path).canonicalFilePath();
    const bool same =
        OutputFile::sameFile(path, sceneFile) ||
        (!canonical.isEmpty() && canonical == QFileInfo(sceneFile).canonicalFilePath());
    if (!same) return true;
    if (error)
        *error = QStringLiteral("%1: this is the open scene's file (%2); choose another name")
                     .arg(path, QFileInfo(sceneFile).fileName());
    return false;
}

}  // namespace phasebox
