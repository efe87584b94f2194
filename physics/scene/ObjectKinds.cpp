// The object kinds' entries and the generic walks over them (ObjectKinds.h).
#include "physics/scene/ObjectKinds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace phasebox {

namespace schema {

const KindInfo& kindInfo(ObjectKind kind) {
    // In ObjectKind's order, None first.
    static const std::array<KindInfo, kObjectKindCount + 1> kinds = {{
        {.name = "object", .idPrefix = "object"},
        {.name = "particle",
         .idPrefix = "p",
         .body = true,
         .placeKey = key::position,
         .pinKey = key::pinned},
        {.name = "box",
         .idPrefix = "b",
         .body = true,
         .rotates = true,
         .placeKey = key::position,
         .pinKey = key::isStatic},
        {.name = "disk",
         .idPrefix = "d",
         .body = true,
         .rotates = true,
         .placeKey = key::position,
         .pinKey = key::isStatic},
        {.name = "polygon",
         .idPrefix = "poly",
         .body = true,
         .rotates = true,
         .placeKey = key::position,
         .pinKey = key::isStatic},
        {.name = "plane", .idPrefix = "plane", .placeKey = key::point},
        {.name = "spring", .idPrefix = "s", .anchorPlaces = true, .endsLengthKey = key::restLength},
        {.name = "cloth",
         .idPrefix = "cloth",
         .body = true,
         .nodes = true,
         .placeKey = key::origin},
        {.name = "joint", .idPrefix = "j", .endsLengthKey = key::length},
    }};
    const auto index = static_cast<std::size_t>(kind);
    return kinds[index < kinds.size() ? index : 0];
}

}  // namespace schema

namespace {

// Whether objects of type D must name themselves (a cloth: its nodes are named after it), rather
// than take a default id by position.
template <typename D>
bool idRequired() {
    for (const schema::Field<D>& f : schema::table<D>().fields)
        if (f.key == schema::key::id) return f.need == schema::Need::Required;
    return false;
}

template <typename D>
std::string idOf(const D& d, std::size_t index) {
    if (!d.id.empty() || idRequired<D>()) return d.id;
    return std::string(schema::kindInfo(kindOf<D>()).idPrefix) + std::to_string(index);
}

// Whether id names a node of the object with id `owner`: owner[…].
bool isNodeOf(const std::string& id, const std::string& owner) {
    return id.size() > owner.size() + 2 && id.compare(0, owner.size(), owner) == 0 &&
           id[owner.size()] == '[' && id.back() == ']';
}

// Calls fn(type, kind) for the kinds without nodes, then for those with nodes.
template <typename Fn>
void forEachKindNodesLast(Fn&& fn) {
    for (const bool nodes : {false, true})
        forEachKind([&](auto type, ObjectKind kind) {
            if (schema::kindInfo(kind).nodes == nodes) fn(type, kind);
        });
}

template <typename D>
std::optional<Point2> pointOn(const D& d, const std::string& id, const Point2& local) {
    if constexpr (std::is_base_of_v<RigidDesc, D>) {
        const double c = std::cos(d.angle), s = std::sin(d.angle);
        return Point2{d.position[0] + c * local[0] - s * local[1],
                      d.position[1] + s * local[0] + c * local[1]};
    } else if constexpr (std::is_same_v<D, ParticleDesc>) {
        return d.position;
    } else if constexpr (std::is_same_v<D, ClothDesc>) {
        int i = -1, j = -1;
        if (std::sscanf(id.c_str() + d.id.size(), "[%d,%d]", &i, &j) != 2) return std::nullopt;
        const double dx = d.size[0] / std::max(d.resolution[0] - 1, 1);
        const double dy = d.size[1] / std::max(d.resolution[1] - 1, 1);
        return Point2{d.origin[0] + i * dx, d.origin[1] - j * dy};
    } else {
        return std::nullopt;  // not a body
    }
}

void shift(Point2& p, const Point2& by) {
    p[0] += by[0];
    p[1] += by[1];
}

}  // namespace

ObjectKind objectKind(const ObjectDesc& object) {
    return static_cast<ObjectKind>(object.index() + 1);
}

std::size_t objectCount(const SceneDesc& scene, ObjectKind kind) {
    std::size_t count = 0;
    visitKind(kind, [&]<typename D>(std::type_identity<D>) { count = arrayOf<D>(scene).size(); });
    return count;
}

std::string objectId(const SceneDesc& scene, ObjectRef ref) {
    std::string id;
    visitKind(ref.kind, [&]<typename D>(std::type_identity<D>) {
        id = idOf(arrayOf<D>(scene)[ref.index], ref.index);
    });
    return id;
}

ObjectRef findObject(const SceneDesc& scene, const std::string& id) {
    if (id.empty()) return {};
    ObjectRef found;
    forEachKindNodesLast([&]<typename D>(std::type_identity<D>, ObjectKind kind) {
        const std::vector<D>& array = arrayOf<D>(scene);
        for (std::size_t i = 0; i < array.size() && !found.isValid(); ++i) {
            const std::string own = idOf(array[i], i);
            if (own == id || (schema::kindInfo(kind).nodes && isNodeOf(id, own))) found = {kind, i};
        }
    });
    return found;
}

std::vector<std::string> objectIds(const SceneDesc& scene) {
    std::vector<std::string> ids;
    forEachKindNodesLast([&]<typename D>(std::type_identity<D>, ObjectKind) {
        const std::vector<D>& array = arrayOf<D>(scene);
        for (std::size_t i = 0; i < array.size(); ++i) ids.push_back(idOf(array[i], i));
    });
    return ids;
}

void assignDefaultIds(SceneDesc& scene) {
    forEachKind([&]<typename D>(std::type_identity<D>, ObjectKind) {
        std::vector<D>& array = arrayOf<D>(scene);
        for (std::size_t i = 0; i < array.size(); ++i) array[i].id = idOf(array[i], i);
    });
}

ObjectDesc objectDesc(const SceneDesc& scene, ObjectRef ref) {
    ObjectDesc out;
    visitObject(scene, ref, [&](const auto& desc) { out = desc; });
    return out;
}

void setObjectDesc(SceneDesc& scene, ObjectRef ref, const ObjectDesc& object) {
    if (objectKind(object) != ref.kind) return;
    std::visit([&](const auto& desc) { arrayOf(scene, desc)[ref.index] = desc; }, object);
}

std::vector<std::string> nodeIds(const SceneDesc& scene, ObjectRef ref) {
    std::vector<std::string> ids;
    visitObject(scene, ref, [&]<typename D>(const D& d) {
        if constexpr (std::is_same_v<D, ClothDesc>)
            for (int j = 0; j < d.resolution[1]; ++j)
                for (int i = 0; i < d.resolution[0]; ++i) ids.push_back(clothNodeId(d.id, i, j));
    });
    return ids;
}

std::optional<Point2> setupPoint(const SceneDesc& scene, const std::string& id,
                                 const Point2& local) {
    std::optional<Point2> point;
    visitObject(scene, findObject(scene, id),
                [&](const auto& desc) { point = pointOn(desc, id, local); });
    return point;
}

void translateObject(ObjectDesc& object, const Point2& offset) {
    std::visit(
        [&]<typename D>(D& d) {
            if constexpr (schema::Connector<D>) {
                if (d.anchor) shift(*d.anchor, offset);
                if constexpr (std::is_same_v<D, JointDesc>) {
                    // The world points a joint holds.
                    shift(d.groundA, offset);
                    shift(d.groundB, offset);
                    if (d.circle) shift(d.circle->center, offset);
                    if (d.line) shift(d.line->point, offset);
                }
            } else {
                const std::string_view place = schema::kindInfo(kindOf<D>()).placeKey;
                if (const std::optional<Point2> at = pointField(d, place))
                    setPointField(d, place, {(*at)[0] + offset[0], (*at)[1] + offset[1]});
            }
        },
        object);
}

}  // namespace phasebox
