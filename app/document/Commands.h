#pragma once
// The edits of a scene: one QUndoCommand subclass per kind (Qt's undoframework, KDE Step).
// Each command changes the document's setup both ways (apply/revert), and the document then
// rebuilds its live world. Drags and property edits merge (id()/mergeWith()) into one undo
// step while they stay within one interaction of the document (Document::finishInteraction).
//
// A command checks its edit on a copy of the setup when it is made. An edit that would make
// the scene invalid is refused: isValid() is false and errorString() says why, in
// validateScene()'s words ("particles[0].mass: must be > 0 (got -1)"). A refused command that
// is pushed anyway does nothing and marks itself obsolete, so the stack drops it.

#include "app/document/Document.h"
#include "app/document/PropertyTable.h"
#include "physics/scene/SceneDesc.h"

#include <QString>
#include <QStringList>
#include <QUndoCommand>

#include <utility>
#include <vector>

namespace phasebox {

class DocumentCommand : public QUndoCommand {
public:
    bool isValid() const { return error_.isEmpty(); }
    const QString& errorString() const { return error_; }
    // The scene as the edit would leave it (the edit not made): for looking ahead.
    SceneDesc appliedTo(SceneDesc scene) const {
        apply(scene);
        return scene;
    }

    void redo() override;
    void undo() override;

protected:
    DocumentCommand(Document& document, const QString& text);

    // The edit, both ways, on any scene: the document's setup, or a copy to validate.
    virtual void apply(SceneDesc& scene) const = 0;
    virtual void revert(SceneDesc& scene) const = 0;
    // Ids whose live state gives way to their new setup values (objects the edit placed).
    virtual QStringList movedIds() const { return {}; }
    // Hands apply or revert to the document, which runs it on the setup and rebuilds the
    // world (the default; Document::commitSetupEdit).
    virtual void commit(const SetupEdit& edit);

    // Runs apply() on a copy of the setup and refuses the edit if validateScene() complains;
    // subclasses call it at the end of their constructor.
    void validate();
    void refuse(const QString& message) { error_ = message; }
    const SceneDesc& setup() const;
    Document& document() const { return document_; }
    // Merging: the same kind of command, made during the same interaction.
    bool sameInteraction(const DocumentCommand& other) const {
        return other.interaction_ == interaction_;
    }

private:
    Document& document_;
    QString error_;
    int interaction_;
};

// Merge ids (QUndoCommand::id): commands of one kind merge with each other only.
enum CommandId : int { kMoveObjectId = 1, kSetPropertyId, kSetSimulationId, kSetEffectId };

// Adds objects of any kind in one undo step: one from a tool, or a pasted group. An empty id
// is replaced by the first free one of its kind (p0, p1…, b0…, d0…, poly0…, plane0…, s0…,
// cloth0…), taken in order, so a spring among the objects must name its ends' final ids.
class AddObjectsCommand final : public DocumentCommand {
public:
    AddObjectsCommand(Document& document, std::vector<ObjectDesc> objects);
    const QStringList& objectIds() const { return ids_; }

protected:
    void apply(SceneDesc& scene) const override;
    void revert(SceneDesc& scene) const override;

private:
    std::vector<ObjectDesc> objects_;
    QStringList ids_;
};

// Deletes objects; a body (schema::KindInfo::body) takes the connectors (springs, joints)
// attached to it along. Undo puts everything back at its original index.
class DeleteObjectsCommand final : public DocumentCommand {
public:
    DeleteObjectsCommand(Document& document, const QStringList& ids);

protected:
    void apply(SceneDesc& scene) const override;
    void revert(SceneDesc& scene) const override;

private:
    // The removed objects, ascending by kind and index.
    std::vector<std::pair<ObjectRef, ObjectDesc>> removed_;
};

// Places an object: sets the point field its kind is placed by (schema::KindInfo::placeKey: a
// body's position, a plane's point, a cloth's origin) or a connector's anchor.
// Consecutive moves of one object merge: a drag is one undo step.
class MoveObjectCommand final : public DocumentCommand {
public:
    MoveObjectCommand(Document& document, const QString& id, const Point2& position);
    int id() const override { return kMoveObjectId; }
    bool mergeWith(const QUndoCommand* other) override;

protected:
    void apply(SceneDesc& scene) const override;
    void revert(SceneDesc& scene) const override;
    QStringList movedIds() const override { return {QString::fromStdString(id_)}; }

private:
    void place(SceneDesc& scene, const Point2& position) const;

    std::string id_;
    ObjectRef ref_;
    Point2 from_{0.0, 0.0}, to_{0.0, 0.0};
};

// Sets one property (a key of PropertyTable.h: `mass`, `size.w`, `velocity.x`, …) of one
// object. Consecutive edits of the same property of the same object merge.
class SetPropertyCommand final : public DocumentCommand {
public:
    SetPropertyCommand(Document& document, const QString& id, const QString& key, double value);
    int id() const override { return kSetPropertyId; }
    bool mergeWith(const QUndoCommand* other) override;

protected:
    void apply(SceneDesc& scene) const override;
    void revert(SceneDesc& scene) const override;
    QStringList movedIds() const override;

private:
    QString objectId_, key_;
    ObjectRef ref_;
    ObjectDesc before_, after_;  // the whole object: undo restores it exactly
    bool moves_ = false;
};

// Sets the flag that holds an object in place (schema::KindInfo::pinKey): pins or unpins a
// particle, makes a rigid body static or dynamic.
class SetPinnedCommand final : public DocumentCommand {
public:
    SetPinnedCommand(Document& document, const QString& id, bool pinned);

protected:
    void apply(SceneDesc& scene) const override;
    void revert(SceneDesc& scene) const override;

private:
    void set(SceneDesc& scene, bool pinned) const;

    ObjectRef ref_;
    bool before_ = false, pinned_ = false;
};

// Changes the simulation settings (integrator, dt, sub-steps, tolerance, …) of the setup and
// of the live world in place, so that the state is kept exactly. Consecutive edits of the same
// field merge.
class SetSimulationCommand final : public DocumentCommand {
public:
    SetSimulationCommand(Document& document, const SimulationDesc& simulation);
    int id() const override { return kSetSimulationId; }
    bool mergeWith(const QUndoCommand* other) override;

protected:
    void apply(SceneDesc& scene) const override { scene.simulation = after_; }
    void revert(SceneDesc& scene) const override { scene.simulation = before_; }
    void commit(const SetupEdit& edit) override;

private:
    SimulationDesc before_, after_;
    QString field_;  // the one field that changed (`integrator`, `dt`, …); empty for several
};

// Replaces the effects (switching one on or off, or changing its parameters). Consecutive
// commands with the same non-empty merge key merge.
class SetEffectCommand final : public DocumentCommand {
public:
    SetEffectCommand(Document& document, const EffectsDesc& effects, const QString& text,
                     const QString& mergeKey = {});
    int id() const override { return kSetEffectId; }
    bool mergeWith(const QUndoCommand* other) override;

protected:
    void apply(SceneDesc& scene) const override { scene.effects = after_; }
    void revert(SceneDesc& scene) const override { scene.effects = before_; }

private:
    EffectsDesc before_, after_;
    QString mergeKey_;
};

}  // namespace phasebox
