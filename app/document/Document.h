#pragma once
// The open scene: its setup (a SceneDesc: what Reset returns to and Save writes), the live
// World simulated from it, the file it came from, the undo stack and the selection.
//
// Every edit is a command on the undo stack (Commands.h) that changes the setup; after each
// redo or undo the document rebuilds the live world from the new setup. When the simulation
// has already run, every object that still exists (by id) carries its live state over, and
// the clock keeps its time, so adding a particle mid-run does not rewind the others. Switching
// the integrator or dt is the exception: it changes the live world's settings in place, which
// keeps the state bit for bit.
//
// The document only holds and edits; stepping is the SimulationController's, recording the
// Recorder's, files' format SceneIO's.

#include "app/document/PropertyTable.h"
#include "physics/scene/SceneDesc.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QUndoStack>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace phasebox {

class World;
class MouseSpringEffect;
class DocumentCommand;

// A change to a scene setup, run by an undo command both ways (Commands.h).
using SetupEdit = std::function<void(SceneDesc&)>;

class Document : public QObject {
    Q_OBJECT

public:
    explicit Document(QObject* parent = nullptr);
    ~Document() override;

    // ---- the scene ----------------------------------------------------------------------
    const SceneDesc& setup() const { return setup_; }
    // The live world. It is replaced by every edit, load, new scene and reset (sceneEdited or
    // sceneReset follows): never keep the reference across those.
    World& world() { return *world_; }
    // The threads each of the document's worlds steps with (0: every core); not part of the
    // scene, and no result depends on it but the timings (World::setWorkers).
    void setWorkers(int workers);
    int workers() const { return workers_; }
    const World& world() const { return *world_; }
    // Effects the scene lists that this engine does not simulate yet.
    QStringList unsupportedEffects() const { return unsupported_; }
    // True once the world's clock has left 0.
    bool hasRun() const;

    QUndoStack* undoStack() { return &undoStack_; }
    QString filePath() const { return filePath_; }
    // Whether an export may write path: not when it is the open scene's file under any name
    // (the path, another spelling, a hard or symbolic link), which the export would replace.
    // False with *error "PATH: this is the open scene's file (NAME); choose another name".
    bool mayWriteOutput(const QString& path, QString* error) const;
    static bool mayWriteOutput(const QString& path, const QString& sceneFile, QString* error);
    bool isModified() const { return !undoStack_.isClean(); }

    // ---- files --------------------------------------------------------------------------
    // An empty scene with gravity and a floor; no file.
    void newScene();
    // A bad file leaves everything as it was and returns SceneIO's messages in *error.
    bool load(const QString& path, QString* error);
    // Replaces the scene (objects without an id get their default ids written in, so that
    // deleting an object never renames the ones after it). False (nothing changed) when the
    // scene does not validate.
    bool loadFromDesc(const SceneDesc& scene, const QString& path = {}, QString* error = nullptr);
    // Writes sceneToSave() through SceneIO (QSaveFile: the old file survives a failure), then
    // marks the document clean and takes the path as its own.
    bool save(const QString& path, QString* error);
    // The setup with the instruments the window measures with now (CONTRACT §7), as Save and
    // the autosave write it.
    SceneDesc sceneToSave() const;

    // ---- instruments (CONTRACT §7) --------------------------------------------------------
    // A lesson's instruments belong to the window's presenters once it is open: the document
    // hands over those a file brought (instrumentsLoaded follows sceneReset on New and Open;
    // New brings none) and asks the source for them when it saves. The setup itself holds none,
    // so deleting an object a probe reads leaves an invalid probe, never an unbuildable setup.
    const InstrumentsDesc& loadedInstruments() const { return loadedInstruments_; }
    void setInstrumentsSource(std::function<InstrumentsDesc()> source) {
        instrumentsSource_ = std::move(source);
    }
    // Rebuilds the world from the setup: time 0, the setup's positions and velocities.
    void reset();

    // ---- edits: each pushes one undoable command; false and *error when refused ----------
    bool addObject(const ObjectDesc& object, QString* error = nullptr, QString* newId = nullptr);
    // Several objects in one undo step (a paste); *newIds in their order.
    bool addObjects(std::vector<ObjectDesc> objects, QString* error = nullptr,
                    QStringList* newIds = nullptr);
    bool deleteObjects(const QStringList& ids, QString* error = nullptr);
    // Moves a particle, box, plane (its point), cloth (its origin) or a spring's anchor.
    bool moveObject(const QString& id, const Point2& position, QString* error = nullptr);
    // An object the user draws on the canvas. When it would make the current integrator
    // unstable at the current step (the scene was stable before: a cloth on a new scene under
    // symplectic Euler), the same undo step switches to a method the stability advisor finds
    // stable with margin; *notice then says so.
    bool addDrawnObject(const ObjectDesc& object, QString* error, QString* newId, QString* notice);
    bool setProperty(const QString& id, const QString& key, double value, QString* error = nullptr);
    // A particle's pinned flag or a box's static flag.
    bool setPinned(const QString& id, bool pinned, QString* error = nullptr);
    // Integrator, dt, sub-steps, tolerances: changes the live world's settings in place.
    bool applySimulationSettings(const SimulationDesc& simulation, QString* error = nullptr);

    // Effects by their scene-format names (gravity, drag, newtonian_gravity, buoyancy, wind,
    // flocking, particle_collisions). Switching one off removes it from the setup (absent =
    // not simulated, costs nothing); the document remembers its parameters for this session
    // so that switching it on again restores them.
    static QStringList effectNames();
    bool isEffectEnabled(const QString& name) const;
    bool setEffectEnabled(const QString& name, bool enabled, QString* error = nullptr);
    // Switches an effect on with its default parameters (forgetting remembered ones).
    bool addEffect(const QString& name, QString* error = nullptr);
    // Replaces the effects' parameters; consecutive calls with the same non-empty mergeKey
    // (say "gravity.g" while a slider moves) make one undo step.
    bool setEffects(const EffectsDesc& effects, const QString& mergeKey, QString* error = nullptr);

    // ---- for the undo commands of Commands.h, their only callers ---------------------------
    // Everything else edits through the functions above, so that each edit can be undone.
    // Runs edit on the setup, then rebuilds the world from it, carrying the live state over
    // when the simulation has run (except for the objects in moved, which start from their new
    // setup values); sceneEdited follows.
    void commitSetupEdit(const SetupEdit& edit, const QStringList& moved);
    // Runs edit (which changes the simulation settings only) on the setup, then applies the
    // settings to the live world in place, which keeps its state bit for bit;
    // simulationSettingsChanged follows.
    void commitSimulationEdit(const SetupEdit& edit);

    // Ends the current interaction: the next move or property edit starts a new undo step even
    // when it touches the same object and key (call on mouse release, editing finished).
    void finishInteraction() { ++interaction_; }
    int interaction() const { return interaction_; }

    // ---- selection ----------------------------------------------------------------------
    QStringList selection() const { return selection_; }
    void setSelection(const QStringList& ids);

    // ---- the mouse spring: a live-only pull, not part of the setup, not undoable ----------
    // Grabs a dynamic particle or box (localPoint in the box's frame) with a spring toward
    // target; it survives edits while the object exists. False when the object is not dynamic.
    bool grab(const QString& id, const Point2& localPoint, const Point2& target);
    void moveGrab(const Point2& target);
    void releaseGrab();
    bool isGrabbing() const { return grab_.has_value(); }
    // The spring in the live world, for drawing; nullptr when nothing is grabbed.
    const MouseSpringEffect* mouseSpring() const;

signals:
    // The world was rebuilt from scratch: new scene, load, reset.
    void sceneReset();
    // After sceneReset on New and Open (not Reset): set the instruments from
    // loadedInstruments().
    void instrumentsLoaded();
    // A command changed the setup and the world was rebuilt (live state carried over).
    void sceneEdited();
    // The simulation settings changed; the world is the same object.
    void simulationSettingsChanged();
    void filePathChanged(const QString& path);
    void modifiedChanged(bool modified);
    void selectionChanged();

private:
    struct Grab {
        std::string id;
        Point2 localPoint{0.0, 0.0};
        Point2 target{0.0, 0.0};
        double stiffness = 0.0;
    };

    bool push(DocumentCommand* command, QString* error);
    void replaceScene(SceneDesc scene, std::unique_ptr<World> world, QStringList unsupported,
                      const QString& path);
    void attachGrab();
    void pruneSelection();

    InstrumentsDesc loadedInstruments_;
    std::function<InstrumentsDesc()> instrumentsSource_;

    SceneDesc setup_;
    std::unique_ptr<World> world_;
    int workers_ = 0;
    QStringList unsupported_;
    QString filePath_;
    QUndoStack undoStack_;
    QStringList selection_;
    EffectsDesc rememberedEffects_;  // parameters of effects switched off this session
    std::optional<Grab> grab_;
    MouseSpringEffect* mouseSpring_ = nullptr;  // owned by world_
    int interaction_ = 0;
};

}  // namespace phasebox
