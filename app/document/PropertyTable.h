#pragma once
// The objects of a scene setup by id, and what the Properties panel may edit on each kind.
//
// One small table per kind of object (key, label, unit, range, decimals) drives the property
// editor and the SetPropertyCommand alike, so the two cannot disagree about what a key means;
// the ranges only guide the editor, validateScene() stays the judge of what a scene may hold.

#include "physics/scene/SceneDesc.h"

#include <QString>

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace phasebox {

enum class ObjectKind { None, Particle, Box, Disk, Polygon, Plane, Spring, Cloth, Joint };

// Where an object sits in a SceneDesc: its array and its index there.
struct ObjectRef {
    ObjectKind kind = ObjectKind::None;
    std::size_t index = 0;
    bool isValid() const { return kind != ObjectKind::None; }
};

// One object's description, whatever its kind: what add and delete commands carry.
using ObjectDesc = std::variant<ParticleDesc, BoxDesc, DiskDesc, PolygonDesc, PlaneDesc, SpringDesc,
                                ClothDesc, JointDesc>;

// The object with this id; a cloth node id ID[i,j] names its cloth (a node is not an object of
// the setup). Invalid when nothing has the id.
ObjectRef findObject(const SceneDesc& scene, const std::string& id);
std::string objectId(const SceneDesc& scene, ObjectRef ref);
ObjectKind objectKind(const ObjectDesc& object);
// The scene array an object of this type lives in.
std::vector<ParticleDesc>& arrayOf(SceneDesc& scene, const ParticleDesc&);
std::vector<BoxDesc>& arrayOf(SceneDesc& scene, const BoxDesc&);
std::vector<DiskDesc>& arrayOf(SceneDesc& scene, const DiskDesc&);
std::vector<PolygonDesc>& arrayOf(SceneDesc& scene, const PolygonDesc&);
std::vector<PlaneDesc>& arrayOf(SceneDesc& scene, const PlaneDesc&);
std::vector<SpringDesc>& arrayOf(SceneDesc& scene, const SpringDesc&);
std::vector<ClothDesc>& arrayOf(SceneDesc& scene, const ClothDesc&);
std::vector<JointDesc>& arrayOf(SceneDesc& scene, const JointDesc&);
ObjectDesc objectDesc(const SceneDesc& scene, ObjectRef ref);
// Replaces the object at ref; the kinds must match (else nothing happens).
void setObjectDesc(SceneDesc& scene, ObjectRef ref, const ObjectDesc& object);
// "particle", "box", "disk", "polygon", "plane", "spring", "cloth", "joint", in the app's
// language.
QString objectKindName(ObjectKind kind);

// Every id in the scene (defaults included), without cloth nodes: ids of the form ID[i,j]
// are taken exactly when a cloth with id ID exists.
std::vector<std::string> objectIds(const SceneDesc& scene);
// prefix0, prefix1, … : the first one no object (or cloth node) of the scene uses.
std::string uniqueObjectId(const SceneDesc& scene, const std::string& prefix);
// The prefix of the ids the editor gives new objects of this kind: p, b, d, poly, plane, s,
// cloth.
std::string defaultIdPrefix(ObjectKind kind);
// Writes the default ids (p0, b0, d0, plane0, s0 by position) into objects that have none, so
// that ids stay put when an object before them is deleted.
void assignDefaultIds(SceneDesc& scene);
// The initial distance between a spring's ends in the setup, its rest length when the scene
// gives none; nullopt when an end does not resolve.
std::optional<double> initialSpringLength(const SceneDesc& scene, const SpringDesc& spring);

struct PropertyRow {
    QString key;    // `mass`, `size.w`, `stiffness.shear`, …
    QString label;  // for people: "Mass"
    QString unit;   // "kg", "m", "N/m", … ; empty for plain numbers
    double value = 0.0;
    double minimum = 0.0;  // the editor's range, inclusive
    double maximum = 0.0;
    int decimals = 3;
    bool isBool = false;  // a check box: value 0 or 1
};

// The editable properties of the object with this id, in display order; empty when unknown.
std::vector<PropertyRow> propertiesOf(const SceneDesc& scene, const QString& id);
std::optional<double> propertyValue(const SceneDesc& scene, const QString& id, const QString& key);
// Writes one property (no range check: validateScene() judges). False for an unknown id or key.
bool setPropertyValue(SceneDesc& scene, const QString& id, const QString& key, double value);
// The property that pins an object in place: for a box its static flag.
QString pinPropertyKey(ObjectKind kind);
// True for the properties that place or launch an object (position, velocity, angle, a
// cloth's shape): after editing one, the object starts from its setup values again instead of
// continuing its live motion.
bool propertyMovesObject(const SceneDesc& scene, const QString& id, const QString& key);

}  // namespace phasebox
