#include "app/document/Commands.h"

#include "app/document/Document.h"
#include "physics/scene/SceneSchema.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string_view>

namespace phasebox {

namespace {
QString joinIssues(const std::vector<SceneIssue>& issues) {
    QStringList lines;
    for (const SceneIssue& issue : issues)
        lines << QString::fromStdString(issue.path + ": " + issue.message);
    return lines.join(QLatin1Char('\n'));
}

QString quotedId(const std::string& id) {
    return QLatin1Char('"') + QString::fromStdString(id) + QLatin1Char('"');
}

// Removes the listed objects (ascending by kind and index), back to front so that the indices
// stay valid.
void eraseAt(SceneDesc& scene, const std::vector<std::pair<ObjectRef, ObjectDesc>>& removed) {
    for (auto it = removed.rbegin(); it != removed.rend(); ++it)
        std::visit(
            [&](const auto& desc) {
                auto& array = arrayOf(scene, desc);
                array.erase(array.begin() + static_cast<std::ptrdiff_t>(it->first.index));
            },
            it->second);
}
// Puts them back, front to back: each lands at its original index.
void insertAt(SceneDesc& scene, const std::vector<std::pair<ObjectRef, ObjectDesc>>& removed) {
    for (const auto& [ref, object] : removed)
        std::visit(
            [&](const auto& desc) {
                auto& array = arrayOf(scene, desc);
                array.insert(array.begin() + static_cast<std::ptrdiff_t>(ref.index), desc);
            },
            object);
}

// Whether a connector's end names this body: the object itself or one of its nodes.
bool attachedTo(const std::string& end, const std::string& id, bool nodes) {
    if (end == id) return true;
    return nodes && end.size() > id.size() + 2 && end.compare(0, id.size(), id) == 0 &&
           end[id.size()] == '[';
}

// The point field a move sets on an object of this kind; empty when it moves with its bodies.
std::string_view placeKeyOf(ObjectKind kind) {
    const schema::KindInfo& info = schema::kindInfo(kind);
    return info.anchorPlaces ? schema::key::anchor : info.placeKey;
}

// The object's pin flag (schema::KindInfo::pinKey); nullopt when it has none.
std::optional<bool> pinOf(const SceneDesc& scene, ObjectRef ref) {
    std::optional<bool> pinned;
    visitObject(scene, ref, [&](const auto& desc) {
        auto copy = desc;
        if (const bool* flag = boolField(copy, schema::kindInfo(ref.kind).pinKey)) pinned = *flag;
    });
    return pinned;
}

bool sameSimulation(const SimulationDesc& a, const SimulationDesc& b) {
    return a.integrator == b.integrator && a.dt == b.dt && a.substeps == b.substeps &&
           a.tolerance == b.tolerance && a.newtonIterations == b.newtonIterations &&
           a.duration == b.duration && a.solver == b.solver && a.contactModel == b.contactModel &&
           a.contactStiffness == b.contactStiffness && a.contactDamping == b.contactDamping &&
           a.sleep == b.sleep;
}

// The one field in which two settings differ, or empty when they differ in several (or none).
QString changedField(const SimulationDesc& a, const SimulationDesc& b) {
    QStringList fields;
    for (const schema::Field<SimulationDesc>& field : schema::table<SimulationDesc>().fields) {
        std::visit(
            [&]<typename V>(V SimulationDesc::*member) {
                // The settings' own types; the variant's other alternatives never occur here.
                if constexpr (std::is_arithmetic_v<V> || std::is_enum_v<V> ||
                              std::is_same_v<V, std::string> ||
                              std::is_same_v<V, std::optional<double>> ||
                              std::is_same_v<V, std::map<std::string, double>>)
                    if (a.*member != b.*member)
                        fields << QString::fromUtf8(field.key.data(),
                                                    static_cast<qsizetype>(field.key.size()));
            },
            field.member);
    }
    return fields.size() == 1 ? fields.front() : QString();
}
}  // namespace

// ---- DocumentCommand -------------------------------------------------------------------------

DocumentCommand::DocumentCommand(Document& document, const QString& text)
    : QUndoCommand(text), document_(document), interaction_(document.interaction()) {}

void DocumentCommand::redo() {
    if (!isValid()) {
        setObsolete(true);  // QUndoStack::push drops it
        return;
    }
    commit([this](SceneDesc& scene) { apply(scene); });
}

void DocumentCommand::undo() {
    commit([this](SceneDesc& scene) { revert(scene); });
}

void DocumentCommand::commit(const SetupEdit& edit) {
    document_.commitSetupEdit(edit, movedIds());
}
const SceneDesc& DocumentCommand::setup() const {
    return document_.setup();
}

void DocumentCommand::validate() {
    if (!isValid()) return;
    SceneDesc trial = setup();
    apply(trial);
    if (const auto issues = validateScene(trial); !issues.empty()) refuse(joinIssues(issues));
}

// ---- AddObjectsCommand -----------------------------------------------------------------------

AddObjectsCommand::AddObjectsCommand(Document& document, std::vector<ObjectDesc> objects)
    : DocumentCommand(document, {}), objects_(std::move(objects)) {
    // Fresh ids are taken one after another, so that two new boxes become b3 and b4.
    SceneDesc trial = setup();
    for (ObjectDesc& object : objects_) {
        std::visit(
            [&](auto& desc) {
                if (desc.id.empty())
                    desc.id = uniqueObjectId(trial, defaultIdPrefix(objectKind(object)));
                ids_ << QString::fromStdString(desc.id);
                arrayOf(trial, desc).push_back(desc);
            },
            object);
    }
    if (objects_.size() == 1)
        setText(QObject::tr("Add %1 %2").arg(objectKindName(objectKind(objects_[0])), ids_[0]));
    else
        setText(QObject::tr("Paste %n objects", nullptr, static_cast<int>(objects_.size())));
    if (objects_.empty()) refuse(QObject::tr("nothing to add"));
    validate();
}

void AddObjectsCommand::apply(SceneDesc& scene) const {
    for (const ObjectDesc& object : objects_)
        std::visit([&](const auto& desc) { arrayOf(scene, desc).push_back(desc); }, object);
}

void AddObjectsCommand::revert(SceneDesc& scene) const {
    // The stack undoes in reverse order, so the objects are the last of their arrays again.
    for (auto it = objects_.rbegin(); it != objects_.rend(); ++it)
        std::visit([&](const auto& desc) { arrayOf(scene, desc).pop_back(); }, *it);
}

// ---- DeleteObjectsCommand --------------------------------------------------------------------

DeleteObjectsCommand::DeleteObjectsCommand(Document& document, const QStringList& ids)
    : DocumentCommand(document, {}) {
    const SceneDesc& scene = setup();
    std::set<std::pair<ObjectKind, std::size_t>> marked;
    std::vector<std::pair<std::string, bool>> bodies;  // deleted bodies (id, has nodes)
    QStringList names;
    for (const QString& qid : ids) {
        const ObjectRef ref = findObject(scene, qid.toStdString());
        if (!ref.isValid()) continue;
        marked.insert({ref.kind, ref.index});
        const std::string name = objectId(scene, ref);
        if (!names.contains(QString::fromStdString(name))) names << QString::fromStdString(name);
        const schema::KindInfo& info = schema::kindInfo(ref.kind);
        if (info.body) bodies.emplace_back(name, info.nodes);
    }
    // A connector (a spring, a joint) cannot outlive a body it holds.
    const auto holds = [&](const std::string& a, const std::optional<std::string>& b) {
        for (const auto& [id, nodes] : bodies)
            if (attachedTo(a, id, nodes) || (b && attachedTo(*b, id, nodes))) return true;
        return false;
    };
    forEachKind([&]<typename D>(std::type_identity<D>, ObjectKind kind) {
        if constexpr (schema::Connector<D>) {
            const std::vector<D>& array = arrayOf<D>(scene);
            for (std::size_t i = 0; i < array.size(); ++i)
                if (holds(array[i].a, array[i].b)) marked.insert({kind, i});
        }
    });
    for (const auto& [kind, index] : marked)
        removed_.emplace_back(ObjectRef{kind, index}, objectDesc(scene, {kind, index}));

    if (names.isEmpty())
        refuse(QObject::tr("nothing to delete: no object has the id %1")
                   .arg(ids.join(QStringLiteral(", "))));
    setText(names.size() == 1
                ? QObject::tr("Delete %1").arg(names.front())
                : QObject::tr("Delete %n objects", nullptr, static_cast<int>(names.size())));
    validate();
}

void DeleteObjectsCommand::apply(SceneDesc& scene) const {
    eraseAt(scene, removed_);
}

void DeleteObjectsCommand::revert(SceneDesc& scene) const {
    insertAt(scene, removed_);
}

// ---- MoveObjectCommand -----------------------------------------------------------------------

MoveObjectCommand::MoveObjectCommand(Document& document, const QString& id, const Point2& position)
    : DocumentCommand(document, QObject::tr("Move %1").arg(id)),
      id_(id.toStdString()),
      ref_(findObject(setup(), id_)),
      to_(position) {
    const SceneDesc& scene = setup();
    const std::string_view placeKey = placeKeyOf(ref_.kind);
    std::optional<Point2> from;
    visitObject(scene, ref_, [&](const auto& desc) { from = pointField(desc, placeKey); });
    if (!ref_.isValid())
        refuse(QObject::tr("unknown object id %1").arg(quotedId(id_)));
    else if (from)
        from_ = *from;
    else if (!placeKey.empty())  // a connector held between two bodies, not by its anchor
        refuse(QObject::tr("%1 %2 hangs between two bodies; move them instead")
                   .arg(objectKindName(ref_.kind), id));
    else
        refuse(QObject::tr("%1 %2 moves with its bodies; move them instead")
                   .arg(objectKindName(ref_.kind), id));
    if (schema::kindInfo(ref_.kind).nodes) id_ = objectId(scene, ref_);  // a node moves its object
    // Only the position changes, so only it needs checking: a full validateScene() at every
    // mouse move of a drag would cost more than the rebuild.
    // The file-format bound too: a drag far off screen must not give a scene that saves but
    // no longer loads.
    const double limit = SceneLimits::kMaxLength;
    if (!std::isfinite(position[0]) || !std::isfinite(position[1]))
        refuse(QObject::tr("the position of %1 must be finite").arg(quotedId(id_)));
    else if (!(std::abs(position[0]) <= limit && std::abs(position[1]) <= limit))
        refuse(QObject::tr("the position of %1 must lie within ±%2 m")
                   .arg(quotedId(id_))
                   .arg(limit, 0, 'g'));
}

void MoveObjectCommand::place(SceneDesc& scene, const Point2& position) const {
    const std::string_view placeKey = placeKeyOf(ref_.kind);
    visitObject(scene, ref_, [&](auto& desc) { setPointField(desc, placeKey, position); });
}

void MoveObjectCommand::apply(SceneDesc& scene) const {
    place(scene, to_);
}
void MoveObjectCommand::revert(SceneDesc& scene) const {
    place(scene, from_);
}

bool MoveObjectCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = static_cast<const MoveObjectCommand*>(other);  // same id(): same type
    if (next->id_ != id_ || !sameInteraction(*next) || !next->isValid()) return false;
    to_ = next->to_;
    setObsolete(to_ == from_);  // dragged back to where it was: no step at all
    return true;
}

// ---- SetPropertyCommand ----------------------------------------------------------------------

SetPropertyCommand::SetPropertyCommand(Document& document, const QString& id, const QString& key,
                                       double value)
    : DocumentCommand(document, {}),
      objectId_(id),
      key_(key),
      ref_(findObject(setup(), id.toStdString())) {
    if (!ref_.isValid()) {
        refuse(QObject::tr("unknown object id %1").arg(quotedId(id.toStdString())));
        return;
    }
    objectId_ = QString::fromStdString(objectId(setup(), ref_));  // a cloth node names its cloth
    before_ = objectDesc(setup(), ref_);
    SceneDesc trial = setup();
    if (!setPropertyValue(trial, objectId_, key, value)) {
        refuse(QObject::tr("%1 %2 has no property \"%3\"")
                   .arg(objectKindName(ref_.kind), objectId_, key));
        return;
    }
    after_ = objectDesc(trial, ref_);
    moves_ = propertyMovesObject(setup(), objectId_, key);
    const QString label = [&] {
        for (const PropertyRow& row : propertiesOf(setup(), objectId_))
            if (row.key == key) return row.label.toLower();
        return key;
    }();
    setText(QObject::tr("Set %1 of %2").arg(label, objectId_));
    validate();
}

void SetPropertyCommand::apply(SceneDesc& scene) const {
    setObjectDesc(scene, ref_, after_);
}
void SetPropertyCommand::revert(SceneDesc& scene) const {
    setObjectDesc(scene, ref_, before_);
}

QStringList SetPropertyCommand::movedIds() const {
    return moves_ ? QStringList{objectId_} : QStringList{};
}

bool SetPropertyCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = static_cast<const SetPropertyCommand*>(other);
    if (next->objectId_ != objectId_ || next->key_ != key_ || !sameInteraction(*next) ||
        !next->isValid())
        return false;
    after_ = next->after_;
    return true;
}

// ---- SetPinnedCommand ------------------------------------------------------------------------

SetPinnedCommand::SetPinnedCommand(Document& document, const QString& id, bool pinned)
    : DocumentCommand(document, {}), ref_(findObject(setup(), id.toStdString())), pinned_(pinned) {
    if (const std::optional<bool> before = pinOf(setup(), ref_)) {
        before_ = *before;
        if (schema::kindInfo(ref_.kind).pinKey == schema::key::isStatic)
            setText(pinned ? QObject::tr("Make %1 static").arg(id)
                           : QObject::tr("Make %1 dynamic").arg(id));
        else
            setText(pinned ? QObject::tr("Pin %1").arg(id) : QObject::tr("Unpin %1").arg(id));
    } else {
        refuse(ref_.isValid()
                   ? QObject::tr("only particles and rigid bodies can be pinned")
                   : QObject::tr("unknown object id %1").arg(quotedId(id.toStdString())));
    }
}

void SetPinnedCommand::set(SceneDesc& scene, bool pinned) const {
    visitObject(scene, ref_, [&](auto& desc) {
        if (bool* flag = boolField(desc, schema::kindInfo(ref_.kind).pinKey)) *flag = pinned;
    });
}

void SetPinnedCommand::apply(SceneDesc& scene) const {
    set(scene, pinned_);
}
void SetPinnedCommand::revert(SceneDesc& scene) const {
    set(scene, before_);
}

// ---- SetSimulationCommand --------------------------------------------------------------------

SetSimulationCommand::SetSimulationCommand(Document& document, const SimulationDesc& simulation)
    : DocumentCommand(document, {}),
      before_(setup().simulation),
      after_(simulation),
      field_(changedField(before_, after_)) {
    setText(field_.isEmpty() ? QObject::tr("Change simulation settings")
                             : QObject::tr("Change %1").arg(field_));
    validate();
}

void SetSimulationCommand::commit(const SetupEdit& edit) {
    document().commitSimulationEdit(edit);
}

bool SetSimulationCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = static_cast<const SetSimulationCommand*>(other);
    if (field_.isEmpty() || next->field_ != field_ || !sameInteraction(*next) || !next->isValid())
        return false;
    after_ = next->after_;
    setObsolete(sameSimulation(before_, after_));
    return true;
}

// ---- SetEffectCommand ------------------------------------------------------------------------

SetEffectCommand::SetEffectCommand(Document& document, const EffectsDesc& effects,
                                   const QString& text, const QString& mergeKey)
    : DocumentCommand(document, text),
      before_(setup().effects),
      after_(effects),
      mergeKey_(mergeKey) {
    validate();
}

bool SetEffectCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = static_cast<const SetEffectCommand*>(other);
    if (mergeKey_.isEmpty() || next->mergeKey_ != mergeKey_ || !sameInteraction(*next) ||
        !next->isValid())
        return false;
    after_ = next->after_;
    return true;
}

}  // namespace phasebox
