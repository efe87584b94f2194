#pragma once
// What the Properties panel may edit on an object of any kind (the kinds and the objects of a
// setup by id are physics/scene/ObjectKinds.h's).
//
// The schema's table of each kind (key, label, unit, editor range, decimals) drives the property
// editor and the SetPropertyCommand alike, so the two cannot disagree about what a key means;
// the ranges only guide the editor, validateScene() stays the judge of what a scene may hold.

#include "physics/scene/ObjectKinds.h"

#include <QString>

#include <optional>
#include <string>
#include <vector>

namespace phasebox {

// The context the kinds' names (schema::KindInfo::name) are translated in.
inline constexpr char kObjectKindTextContext[] = "ObjectKind";

// The kind's name (schema::KindInfo::name: "particle", "box", …) in the app's language;
// "object" for None.
QString objectKindName(ObjectKind kind);

// prefix0, prefix1, … : the first one no object (or cloth node) of the scene uses.
std::string uniqueObjectId(const SceneDesc& scene, const std::string& prefix);
// The prefix of the ids the editor gives new objects of this kind (schema::KindInfo::idPrefix).
std::string defaultIdPrefix(ObjectKind kind);

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
// The property that pins an object in place (schema::KindInfo::pinKey): a particle's pinned, a
// rigid body's static flag; empty when the kind cannot be pinned.
QString pinPropertyKey(ObjectKind kind);
// True for the properties that place or launch an object (position, velocity, angle, a
// cloth's shape): after editing one, the object starts from its setup values again instead of
// continuing its live motion.
bool propertyMovesObject(const SceneDesc& scene, const QString& id, const QString& key);

}  // namespace phasebox
