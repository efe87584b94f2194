#pragma once
// The object kinds of a scene, listed once. Beside each kind's table of fields (SceneSchema.h)
// stands what an editor needs to know of the kind as a whole: its name for people, the prefix
// of its default ids, whether springs and joints hold on to it, which field places it and which
// pins it. Code that handles objects of every kind (the app's document, its commands, the
// property editor, the canvas tools) visits the kinds through this header and names none of
// them, so a new kind is its Desc struct and table, its entry here, its physics and its drawing.

#include "physics/scene/SceneSchema.h"

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace phasebox {

// The kinds in the file's order (schema::forEachObjectKind), after None.
enum class ObjectKind { None, Particle, Box, Disk, Polygon, Plane, Spring, Cloth, Joint };

// One object's description, whatever its kind, in ObjectKind's order: what add and delete
// commands carry.
using ObjectDesc = std::variant<ParticleDesc, BoxDesc, DiskDesc, PolygonDesc, PlaneDesc, SpringDesc,
                                ClothDesc, JointDesc>;
inline constexpr std::size_t kObjectKindCount = std::variant_size_v<ObjectDesc>;

// Where an object sits in a SceneDesc: its array and its index there.
struct ObjectRef {
    ObjectKind kind = ObjectKind::None;
    std::size_t index = 0;
    bool isValid() const { return kind != ObjectKind::None; }
    friend bool operator==(const ObjectRef&, const ObjectRef&) = default;
};

namespace schema {

// What an editor knows of a kind beyond its fields.
struct KindInfo {
    std::string_view name{};      // for people, in English: "particle"
    std::string_view idPrefix{};  // default ids p0, p1, … by position; new objects' ids too
    // Springs and joints hold on to it (a particle, a rigid body, a cloth's nodes): deleting it
    // takes them along, and copying it lets them come too.
    bool body = false;
    bool rotates = false;  // it has an angle of its own (a rigid body)
    bool nodes = false;    // its nodes are named ID[i,j] and are bodies of their own (a cloth)
    // The point field that places it (a move sets it); empty when it has none of its own.
    std::string_view placeKey{};
    // A connector held by a fixed anchor moves with it when it has one.
    bool anchorPlaces = false;
    // The flag that holds it in place (pinned, static); empty when it cannot be held.
    std::string_view pinKey{};
    // A length that, left out, is the initial distance between its ends.
    std::string_view endsLengthKey{};
};

const KindInfo& kindInfo(ObjectKind kind);

// Whether objects of type D hang between two ends (a, and b or a fixed anchor).
template <typename D>
concept Connector = requires(const D& d) {
    d.a;
    d.b;
    d.aPoint;
    d.bPoint;
    d.anchor;
};

}  // namespace schema

// The kind of an object of type D.
template <typename D, std::size_t I = 0>
constexpr ObjectKind kindOf() {
    if constexpr (std::is_same_v<std::variant_alternative_t<I, ObjectDesc>, D>)
        return static_cast<ObjectKind>(I + 1);
    else
        return kindOf<D, I + 1>();
}

ObjectKind objectKind(const ObjectDesc& object);

// fn(std::type_identity<D>{}) for the kind's type D; nothing for None.
template <typename Fn>
void visitKind(ObjectKind kind, Fn&& fn) {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((static_cast<std::size_t>(kind) == I + 1
              ? (fn(std::type_identity<std::variant_alternative_t<I, ObjectDesc>>{}), 0)
              : 0),
         ...);
    }
    (std::make_index_sequence<kObjectKindCount>{});
}

// fn(std::type_identity<D>{}, kind) for every kind, in ObjectKind's order.
template <typename Fn>
void forEachKind(Fn&& fn) {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (fn(std::type_identity<std::variant_alternative_t<I, ObjectDesc>>{},
            static_cast<ObjectKind>(I + 1)),
         ...);
    }
    (std::make_index_sequence<kObjectKindCount>{});
}

// The scene array the objects of type D live in.
template <typename D>
std::vector<D>& arrayOf(SceneDesc& scene, const D& = {}) {
    std::vector<D>* array = nullptr;
    schema::forEachObjectKind([&](const auto&, auto member) {
        if constexpr (std::is_same_v<decltype(member), std::vector<D> SceneDesc::*>)
            array = &(scene.*member);
    });
    return *array;
}
template <typename D>
const std::vector<D>& arrayOf(const SceneDesc& scene, const D& d = {}) {
    return arrayOf(const_cast<SceneDesc&>(scene), d);
}

// Calls fn(desc) for the object at ref (nothing when it is invalid).
template <typename Fn>
void visitObject(SceneDesc& scene, ObjectRef ref, Fn&& fn) {
    visitKind(ref.kind,
              [&]<typename D>(std::type_identity<D>) { fn(arrayOf<D>(scene)[ref.index]); });
}
template <typename Fn>
void visitObject(const SceneDesc& scene, ObjectRef ref, Fn&& fn) {
    visitKind(ref.kind, [&]<typename D>(std::type_identity<D>) {
        fn(std::as_const(arrayOf<D>(scene)[ref.index]));
    });
}

// The number of objects of the kind in the scene.
std::size_t objectCount(const SceneDesc& scene, ObjectKind kind);
// The object's id, its kind's default (p0, b1, …) when it has none of its own.
std::string objectId(const SceneDesc& scene, ObjectRef ref);
// The object with this id; a node id ID[i,j] names its cloth (a node is not an object of the
// setup). Invalid when nothing has the id.
ObjectRef findObject(const SceneDesc& scene, const std::string& id);
// Every id in the scene (defaults included), without nodes, the kinds with nodes last.
std::vector<std::string> objectIds(const SceneDesc& scene);
// Writes the default ids (p0, b0, d0, plane0, s0 by position) into objects that have none, so
// that ids stay put when an object before them is deleted.
void assignDefaultIds(SceneDesc& scene);
ObjectDesc objectDesc(const SceneDesc& scene, ObjectRef ref);
// Replaces the object at ref; the kinds must match (else nothing happens).
void setObjectDesc(SceneDesc& scene, ObjectRef ref, const ObjectDesc& object);
// The ids of the object's nodes (a cloth's ID[i,j]); empty for a kind without nodes.
std::vector<std::string> nodeIds(const SceneDesc& scene, ObjectRef ref);

// The setup position of a point fixed to the body with this id (local: in its own frame; a
// particle's is ignored), or of a node; nullopt when the id names no body.
std::optional<Point2> setupPoint(const SceneDesc& scene, const std::string& id,
                                 const Point2& local);
// The initial distance between a connector's ends in the setup; nullopt when an end does not
// resolve.
template <schema::Connector D>
std::optional<double> initialEndsDistance(const SceneDesc& scene, const D& d) {
    const std::optional<Point2> a = setupPoint(scene, d.a, d.aPoint);
    const std::optional<Point2> b = d.b ? setupPoint(scene, *d.b, d.bPoint) : d.anchor;
    if (!a || !b) return std::nullopt;
    return std::hypot((*a)[0] - (*b)[0], (*a)[1] - (*b)[1]);
}
// Moves the object by offset: every world point it holds (a connector's ends on bodies stay).
void translateObject(ObjectDesc& object, const Point2& offset);

// The point field key of d (Type::Point, held plainly or in std::optional): its value, nullopt
// when d has no such field or leaves it out.
template <typename D>
std::optional<Point2> pointField(const D& d, std::string_view key) {
    std::optional<Point2> out;
    for (const schema::Field<D>& f : schema::table<D>().fields) {
        if (f.key != key) continue;
        std::visit(
            [&]<typename V>(V D::*member) {
                if constexpr (std::is_same_v<V, Point2> || std::is_same_v<V, std::optional<Point2>>)
                    out = d.*member;
            },
            f.member);
    }
    return out;
}
// Sets it; false when d has no such field.
template <typename D>
bool setPointField(D& d, std::string_view key, const Point2& value) {
    bool set = false;
    for (const schema::Field<D>& f : schema::table<D>().fields) {
        if (f.key != key) continue;
        std::visit(
            [&]<typename V>(V D::*member) {
                if constexpr (std::is_same_v<V, Point2> ||
                              std::is_same_v<V, std::optional<Point2>>) {
                    d.*member = value;
                    set = true;
                }
            },
            f.member);
    }
    return set;
}
// The bool field key of d (a pin); nullptr when d has none.
template <typename D>
bool* boolField(D& d, std::string_view key) {
    bool* out = nullptr;
    for (const schema::Field<D>& f : schema::table<D>().fields) {
        if (f.key != key) continue;
        std::visit(
            [&]<typename V>(V D::*member) {
                if constexpr (std::is_same_v<V, bool>) out = &(d.*member);
            },
            f.member);
    }
    return out;
}

}  // namespace phasebox
