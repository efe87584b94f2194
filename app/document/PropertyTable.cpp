#include "app/document/PropertyTable.h"

#include "physics/scene/SceneSchema.h"
#include "ui/panels/BuiltinText.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <span>
#include <unordered_set>

namespace phasebox {

namespace {

namespace key = schema::key;

QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

// A plane's normal is edited as the tilt of the surface: 0 = a floor (normal up), π/2 = a wall
// facing −x. Two spin boxes for the normal's components would let it become zero.
PropertyRow tiltRow(const PlaneDesc& d) {
    return {text(key::angle),
            QStringLiteral("Tilt"),
            QStringLiteral("rad"),
            std::atan2(-d.normal[0], d.normal[1]),
            -std::numbers::pi,
            std::numbers::pi,
            3,
            false};
}

QString pairText(const char* english) {
    return QCoreApplication::translate(ui::kSchemaTextContext, english);
}

// The names of a pair's two rows: keys "size.w", labels "Width".
struct PairNames {
    const char* suffix[2];
    QString label[2];
};
template <typename D>
PairNames pairNames(const schema::Field<D>& f) {
    const QString label = ui::schemaText(f.label);
    switch (f.type) {
        case schema::Type::Size:
            return {{".w", ".h"},
                    {pairText(QT_TRANSLATE_NOOP("Schema", "Width")),
                     pairText(QT_TRANSLATE_NOOP("Schema", "Height"))}};
        case schema::Type::Grid:
            return {{".x", ".y"},
                    {pairText(QT_TRANSLATE_NOOP("Schema", "Columns")),
                     pairText(QT_TRANSLATE_NOOP("Schema", "Rows"))}};
        case schema::Type::Interval:
            return {{".lower", ".upper"},
                    {pairText(QT_TRANSLATE_NOOP("Schema", "%1 lower")).arg(label),
                     pairText(QT_TRANSLATE_NOOP("Schema", "%1 upper")).arg(label)}};
        default:
            return {{".x", ".y"},
                    {pairText(QT_TRANSLATE_NOOP("Schema", "%1 x")).arg(label),
                     pairText(QT_TRANSLATE_NOOP("Schema", "%1 y")).arg(label)}};
    }
}

// Calls fn(row, editor, set) for each property of d the editor shows, in its table's order,
// where set(value) writes the property into d. What the editor shows of a field is in its
// schema::Editor; a pair held in std::optional (a spring's anchor) only while it is set.
template <typename D, typename Fn>
void forEachProperty(D& d, Fn&& fn, const QString& prefix = {}) {
    for (const schema::Field<D>& field : schema::table<D>().fields) {
        if (field.uses && !field.uses(d)) continue;  // a field this joint's type does not use
        const QString fieldKey = prefix + text(field.key);
        const schema::Editor& e = field.editor;
        if constexpr (std::is_same_v<D, PlaneDesc>) {
            if (field.key == key::normal) {
                fn(tiltRow(d), e, [&d](double v) { d.normal = {-std::sin(v), std::cos(v)}; });
                continue;
            }
        }
        auto row = [&](const QString& rowKey, const QString& label, double value) {
            return PropertyRow{rowKey, label, text(field.unit), value,
                               e.min,  e.max, e.decimals,       field.type == schema::Type::Bool};
        };
        std::visit(
            [&]<typename V>(V D::*member) {
                V& v = d.*member;
                if constexpr (std::is_same_v<V, ClothStiffnessDesc>) {
                    forEachProperty(v, fn, fieldKey + QLatin1Char('.'));
                } else if constexpr (std::is_same_v<V, std::optional<JointMotorDesc>> ||
                                     std::is_same_v<V, std::optional<TrackCircleDesc>> ||
                                     std::is_same_v<V, std::optional<TrackLineDesc>>) {
                    if (v) forEachProperty(*v, fn, fieldKey + QLatin1Char('.'));
                } else if (e.decimals < 0) {
                    return;
                } else if constexpr (std::is_same_v<V, double>) {
                    fn(row(fieldKey, ui::schemaText(field.label), v), e, [&v](double x) { v = x; });
                } else if constexpr (std::is_same_v<V, std::optional<double>>) {
                    fn(row(fieldKey, ui::schemaText(field.label), v.value_or(0.0)), e,
                       [&v](double x) { v = x; });
                } else if constexpr (std::is_same_v<V, bool>) {
                    fn(row(fieldKey, ui::schemaText(field.label), v ? 1.0 : 0.0), e,
                       [&v](double x) { v = x != 0.0; });
                } else if constexpr (std::is_same_v<V, Point2> ||
                                     std::is_same_v<V, std::optional<Point2>> ||
                                     std::is_same_v<V, std::array<int, 2>>) {
                    auto* pair = [&] {
                        if constexpr (std::is_same_v<V, std::optional<Point2>>)
                            return v ? &*v : nullptr;
                        else
                            return &v;
                    }();
                    if (!pair) return;
                    const PairNames names = pairNames(field);
                    for (std::size_t k = 0; k < 2; ++k)
                        fn(row(fieldKey + QLatin1String(names.suffix[k]), names.label[k],
                               static_cast<double>((*pair)[k])),
                           e, [pair, k](double x) {
                               using Element = std::remove_reference_t<decltype((*pair)[k])>;
                               if constexpr (std::is_same_v<Element, int>)
                                   (*pair)[k] = static_cast<int>(std::lround(x));
                               else
                                   (*pair)[k] = x;
                           });
                }
            },
            field.member);
    }
}

// Calls fn(desc) for the object at ref.
template <typename Fn>
void visitObject(SceneDesc& scene, ObjectRef ref, Fn&& fn) {
    switch (ref.kind) {
        case ObjectKind::Particle:
            return fn(scene.particles[ref.index]);
        case ObjectKind::Box:
            return fn(scene.boxes[ref.index]);
        case ObjectKind::Disk:
            return fn(scene.disks[ref.index]);
        case ObjectKind::Polygon:
            return fn(scene.polygons[ref.index]);
        case ObjectKind::Plane:
            return fn(scene.planes[ref.index]);
        case ObjectKind::Spring:
            return fn(scene.springs[ref.index]);
        case ObjectKind::Cloth:
            return fn(scene.cloths[ref.index]);
        case ObjectKind::Joint:
            return fn(scene.joints[ref.index]);
        case ObjectKind::None:
            break;
    }
}

// Setup position of a point fixed to a body (particle, box, cloth node); nullopt if unknown.
std::optional<Point2> bodyPoint(const SceneDesc& scene, const std::string& id,
                                const Point2& local) {
    const ObjectRef ref = findObject(scene, id);
    if (ref.kind == ObjectKind::Particle) return scene.particles[ref.index].position;
    if (ref.kind == ObjectKind::Box || ref.kind == ObjectKind::Disk ||
        ref.kind == ObjectKind::Polygon) {
        const RigidDesc& body = ref.kind == ObjectKind::Box ? scene.boxes[ref.index]
                                : ref.kind == ObjectKind::Disk
                                    ? static_cast<const RigidDesc&>(scene.disks[ref.index])
                                    : scene.polygons[ref.index];
        const Point2& at = body.position;
        const double angle = body.angle;
        const double c = std::cos(angle), s = std::sin(angle);
        return Point2{at[0] + c * local[0] - s * local[1], at[1] + s * local[0] + c * local[1]};
    }
    if (ref.kind == ObjectKind::Cloth) {
        const ClothDesc& cl = scene.cloths[ref.index];
        int i = -1, j = -1;
        if (std::sscanf(id.c_str() + cl.id.size(), "[%d,%d]", &i, &j) != 2) return std::nullopt;
        const double dx = cl.size[0] / std::max(cl.resolution[0] - 1, 1);
        const double dy = cl.size[1] / std::max(cl.resolution[1] - 1, 1);
        return Point2{cl.origin[0] + i * dx, cl.origin[1] - j * dy};
    }
    return std::nullopt;
}
}  // namespace

ObjectRef findObject(const SceneDesc& scene, const std::string& id) {
    if (id.empty()) return {};
    for (std::size_t i = 0; i < scene.particles.size(); ++i)
        if (particleId(scene, i) == id) return {ObjectKind::Particle, i};
    for (std::size_t i = 0; i < scene.boxes.size(); ++i)
        if (boxId(scene, i) == id) return {ObjectKind::Box, i};
    for (std::size_t i = 0; i < scene.disks.size(); ++i)
        if (diskId(scene, i) == id) return {ObjectKind::Disk, i};
    for (std::size_t i = 0; i < scene.polygons.size(); ++i)
        if (polygonId(scene, i) == id) return {ObjectKind::Polygon, i};
    for (std::size_t i = 0; i < scene.planes.size(); ++i)
        if (planeId(scene, i) == id) return {ObjectKind::Plane, i};
    for (std::size_t i = 0; i < scene.springs.size(); ++i)
        if (springId(scene, i) == id) return {ObjectKind::Spring, i};
    for (std::size_t i = 0; i < scene.joints.size(); ++i)
        if (jointId(scene, i) == id) return {ObjectKind::Joint, i};
    for (std::size_t i = 0; i < scene.cloths.size(); ++i) {
        const std::string& cloth = scene.cloths[i].id;
        if (id == cloth) return {ObjectKind::Cloth, i};
        // A node: ID[i,j].
        if (id.size() > cloth.size() + 2 && id.compare(0, cloth.size(), cloth) == 0 &&
            id[cloth.size()] == '[' && id.back() == ']')
            return {ObjectKind::Cloth, i};
    }
    return {};
}

std::string objectId(const SceneDesc& scene, ObjectRef ref) {
    switch (ref.kind) {
        case ObjectKind::Particle:
            return particleId(scene, ref.index);
        case ObjectKind::Box:
            return boxId(scene, ref.index);
        case ObjectKind::Disk:
            return diskId(scene, ref.index);
        case ObjectKind::Polygon:
            return polygonId(scene, ref.index);
        case ObjectKind::Plane:
            return planeId(scene, ref.index);
        case ObjectKind::Spring:
            return springId(scene, ref.index);
        case ObjectKind::Cloth:
            return scene.cloths[ref.index].id;
        case ObjectKind::Joint:
            return jointId(scene, ref.index);
        case ObjectKind::None:
            break;
    }
    return {};
}

std::vector<ParticleDesc>& arrayOf(SceneDesc& s, const ParticleDesc&) {
    return s.particles;
}
std::vector<BoxDesc>& arrayOf(SceneDesc& s, const BoxDesc&) {
    return s.boxes;
}
std::vector<DiskDesc>& arrayOf(SceneDesc& s, const DiskDesc&) {
    return s.disks;
}
std::vector<PolygonDesc>& arrayOf(SceneDesc& s, const PolygonDesc&) {
    return s.polygons;
}
std::vector<PlaneDesc>& arrayOf(SceneDesc& s, const PlaneDesc&) {
    return s.planes;
}
std::vector<SpringDesc>& arrayOf(SceneDesc& s, const SpringDesc&) {
    return s.springs;
}
std::vector<ClothDesc>& arrayOf(SceneDesc& s, const ClothDesc&) {
    return s.cloths;
}
std::vector<JointDesc>& arrayOf(SceneDesc& s, const JointDesc&) {
    return s.joints;
}

ObjectKind objectKind(const ObjectDesc& object) {
    // The variant's alternatives are in the order of ObjectKind after None.
    return static_cast<ObjectKind>(object.index() + 1);
}

ObjectDesc objectDesc(const SceneDesc& scene, ObjectRef ref) {
    switch (ref.kind) {
        case ObjectKind::Particle:
            return scene.particles[ref.index];
        case ObjectKind::Box:
            return scene.boxes[ref.index];
        case ObjectKind::Disk:
            return scene.disks[ref.index];
        case ObjectKind::Polygon:
            return scene.polygons[ref.index];
        case ObjectKind::Plane:
            return scene.planes[ref.index];
        case ObjectKind::Spring:
            return scene.springs[ref.index];
        case ObjectKind::Cloth:
            return scene.cloths[ref.index];
        case ObjectKind::Joint:
            return scene.joints[ref.index];
        case ObjectKind::None:
            break;
    }
    return {};
}

void setObjectDesc(SceneDesc& scene, ObjectRef ref, const ObjectDesc& object) {
    if (objectKind(object) != ref.kind) return;
    std::visit([&](const auto& desc) { arrayOf(scene, desc)[ref.index] = desc; }, object);
}

QString objectKindName(ObjectKind kind) {
    const char* name = "object";
    switch (kind) {
        case ObjectKind::Particle:
            name = QT_TRANSLATE_NOOP("ObjectKind", "particle");
            break;
        case ObjectKind::Box:
            name = QT_TRANSLATE_NOOP("ObjectKind", "box");
            break;
        case ObjectKind::Disk:
            name = QT_TRANSLATE_NOOP("ObjectKind", "disk");
            break;
        case ObjectKind::Polygon:
            name = QT_TRANSLATE_NOOP("ObjectKind", "polygon");
            break;
        case ObjectKind::Plane:
            name = QT_TRANSLATE_NOOP("ObjectKind", "plane");
            break;
        case ObjectKind::Spring:
            name = QT_TRANSLATE_NOOP("ObjectKind", "spring");
            break;
        case ObjectKind::Cloth:
            name = QT_TRANSLATE_NOOP("ObjectKind", "cloth");
            break;
        case ObjectKind::Joint:
            name = QT_TRANSLATE_NOOP("ObjectKind", "joint");
            break;
        case ObjectKind::None:
            name = QT_TRANSLATE_NOOP("ObjectKind", "object");
            break;
    }
    return QCoreApplication::translate("ObjectKind", name);
}

std::vector<std::string> objectIds(const SceneDesc& scene) {
    std::vector<std::string> ids;
    for (std::size_t i = 0; i < scene.particles.size(); ++i) ids.push_back(particleId(scene, i));
    for (std::size_t i = 0; i < scene.boxes.size(); ++i) ids.push_back(boxId(scene, i));
    for (std::size_t i = 0; i < scene.disks.size(); ++i) ids.push_back(diskId(scene, i));
    for (std::size_t i = 0; i < scene.polygons.size(); ++i) ids.push_back(polygonId(scene, i));
    for (std::size_t i = 0; i < scene.planes.size(); ++i) ids.push_back(planeId(scene, i));
    for (std::size_t i = 0; i < scene.springs.size(); ++i) ids.push_back(springId(scene, i));
    for (std::size_t i = 0; i < scene.joints.size(); ++i) ids.push_back(jointId(scene, i));
    for (const ClothDesc& cloth : scene.cloths) ids.push_back(cloth.id);
    return ids;
}

std::string uniqueObjectId(const SceneDesc& scene, const std::string& prefix) {
    const std::vector<std::string> list = objectIds(scene);
    const std::unordered_set<std::string> used(list.begin(), list.end());
    // Cloth node ids contain '[', which a prefix+number never does, so they cannot collide.
    for (std::size_t n = 0;; ++n) {
        std::string id = prefix + std::to_string(n);
        if (!used.count(id)) return id;
    }
}

std::string defaultIdPrefix(ObjectKind kind) {
    switch (kind) {
        case ObjectKind::Particle:
            return "p";
        case ObjectKind::Box:
            return "b";
        case ObjectKind::Disk:
            return "d";
        case ObjectKind::Polygon:
            return "poly";
        case ObjectKind::Plane:
            return "plane";
        case ObjectKind::Spring:
            return "s";
        case ObjectKind::Cloth:
            return "cloth";
        case ObjectKind::Joint:
            return "j";
        case ObjectKind::None:
            break;
    }
    return "object";
}

void assignDefaultIds(SceneDesc& scene) {
    for (std::size_t i = 0; i < scene.particles.size(); ++i)
        scene.particles[i].id = particleId(scene, i);
    for (std::size_t i = 0; i < scene.boxes.size(); ++i) scene.boxes[i].id = boxId(scene, i);
    for (std::size_t i = 0; i < scene.disks.size(); ++i) scene.disks[i].id = diskId(scene, i);
    for (std::size_t i = 0; i < scene.polygons.size(); ++i)
        scene.polygons[i].id = polygonId(scene, i);
    for (std::size_t i = 0; i < scene.planes.size(); ++i) scene.planes[i].id = planeId(scene, i);
    for (std::size_t i = 0; i < scene.springs.size(); ++i) scene.springs[i].id = springId(scene, i);
    for (std::size_t i = 0; i < scene.joints.size(); ++i) scene.joints[i].id = jointId(scene, i);
}

std::optional<double> initialSpringLength(const SceneDesc& scene, const SpringDesc& spring) {
    const std::optional<Point2> a = bodyPoint(scene, spring.a, spring.aPoint);
    const std::optional<Point2> b =
        spring.b ? bodyPoint(scene, *spring.b, spring.bPoint) : spring.anchor;
    if (!a || !b) return std::nullopt;
    return std::hypot((*a)[0] - (*b)[0], (*a)[1] - (*b)[1]);
}

std::vector<PropertyRow> propertiesOf(const SceneDesc& scene, const QString& id) {
    const ObjectRef ref = findObject(scene, id.toStdString());
    if (!ref.isValid()) return {};
    std::vector<std::pair<int, PropertyRow>> ranked;
    ObjectDesc object = objectDesc(scene, ref);
    std::visit(
        [&](auto& desc) {
            forEachProperty(desc, [&](const PropertyRow& row, const schema::Editor& e, auto&&) {
                ranked.emplace_back(e.rank, row);
            });
        },
        object);
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<PropertyRow> rows;
    for (auto& [rank, row] : ranked) rows.push_back(std::move(row));
    // A number the scene leaves out shows the value it then takes: a box's mass from its
    // density, a spring's rest length from its ends' initial distance.
    for (PropertyRow& row : rows) {
        if (ref.kind == ObjectKind::Joint && row.key == text(schema::key::length) &&
            !scene.joints[ref.index].length) {
            const JointDesc& j = scene.joints[ref.index];
            const auto a = bodyPoint(scene, j.a, j.aPoint);
            const auto b = j.b ? bodyPoint(scene, *j.b, j.bPoint) : j.anchor;
            if (a && b) row.value = std::hypot((*a)[0] - (*b)[0], (*a)[1] - (*b)[1]);
        }
        if (row.key != text(schema::key::mass) && row.key != text(schema::key::restLength))
            continue;
        if (ref.kind == ObjectKind::Box && !scene.boxes[ref.index].mass)
            row.value = scene.boxes[ref.index].resolvedMass();
        if (ref.kind == ObjectKind::Disk && !scene.disks[ref.index].mass)
            row.value = scene.disks[ref.index].resolvedMass();
        if (ref.kind == ObjectKind::Polygon && !scene.polygons[ref.index].mass)
            row.value = scene.polygons[ref.index].resolvedMass();
        if (ref.kind == ObjectKind::Spring && !scene.springs[ref.index].restLength)
            row.value = initialSpringLength(scene, scene.springs[ref.index]).value_or(0.0);
    }
    return rows;
}

std::optional<double> propertyValue(const SceneDesc& scene, const QString& id, const QString& key) {
    for (const PropertyRow& row : propertiesOf(scene, id))
        if (row.key == key) return row.value;
    return std::nullopt;
}

bool setPropertyValue(SceneDesc& scene, const QString& id, const QString& key, double value) {
    bool found = false;
    const auto set = [&](const QString& target) {
        visitObject(scene, findObject(scene, id.toStdString()), [&](auto& desc) {
            forEachProperty(desc, [&](const PropertyRow& row, const schema::Editor&, auto&& write) {
                if (found || row.key != target) return;
                write(value);
                found = true;
            });
        });
    };
    set(key);
    // The generic pin command pins a box by making it static.
    if (!found && key == text(schema::key::pinned)) set(text(schema::key::isStatic));
    return found;
}

QString pinPropertyKey(ObjectKind kind) {
    const bool rigid =
        kind == ObjectKind::Box || kind == ObjectKind::Disk || kind == ObjectKind::Polygon;
    return text(rigid ? schema::key::isStatic : schema::key::pinned);
}

bool propertyMovesObject(const SceneDesc& scene, const QString& id, const QString& key) {
    const ObjectRef ref = findObject(scene, id.toStdString());
    if (!ref.isValid()) return false;
    bool moves = false;
    ObjectDesc object = objectDesc(scene, ref);
    std::visit(
        [&](auto& desc) {
            forEachProperty(desc, [&](const PropertyRow& row, const schema::Editor& e, auto&&) {
                if (row.key == key) moves = e.movesObject;
            });
        },
        object);
    return moves;
}

}  // namespace phasebox
