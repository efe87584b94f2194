#include "app/document/PropertyTable.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <span>
#include <unordered_set>

namespace phasebox {

namespace {

// The editor's range of coordinates and speeds: far past any classroom scene.
constexpr double kFar = 1e6;
constexpr double kLarge = 1e9;

// One row of a kind's table. get/set are captureless lambdas; applies (optional) hides a row
// that makes no sense for this object (a spring's anchor when it has a second body).
template <typename Desc>
struct PropertySpec {
    const char* key;
    const char* label;
    const char* unit;
    double minimum, maximum;
    int decimals;
    bool isBool;
    bool movesObject;
    double (*get)(const Desc&);
    void (*set)(Desc&, double);
    bool (*applies)(const Desc&) = nullptr;
};

// Accessors for a plain numeric, a boolean and an integer member.
#define PB_NUMBER(m) \
    [](const auto& d) { return static_cast<double>(d.m); }, [](auto& d, double v) { d.m = v; }
#define PB_BOOL(m) \
    [](const auto& d) { return d.m ? 1.0 : 0.0; }, [](auto& d, double v) { d.m = v != 0.0; }
#define PB_INT(m)                                           \
    [](const auto& d) { return static_cast<double>(d.m); }, \
        [](auto& d, double v) { d.m = static_cast<int>(std::lround(v)); }

const PropertySpec<ParticleDesc> kParticleTable[] = {
    {"position.x", "Position x", "m", -kFar, kFar, 3, false, true, PB_NUMBER(position[0])},
    {"position.y", "Position y", "m", -kFar, kFar, 3, false, true, PB_NUMBER(position[1])},
    {"velocity.x", "Velocity x", "m/s", -kFar, kFar, 3, false, true, PB_NUMBER(velocity[0])},
    {"velocity.y", "Velocity y", "m/s", -kFar, kFar, 3, false, true, PB_NUMBER(velocity[1])},
    {"mass", "Mass", "kg", 0.001, kLarge, 3, false, false, PB_NUMBER(mass)},
    {"radius", "Radius", "m", 0.0, kFar, 3, false, false, PB_NUMBER(radius)},
    {"pinned", "Pinned", "", 0.0, 1.0, 0, true, false, PB_BOOL(pinned)},
    {"restitution", "Restitution", "", 0.0, 1.0, 2, false, false, PB_NUMBER(restitution)},
    {"friction", "Friction", "", 0.0, 10.0, 2, false, false, PB_NUMBER(friction)},
    {"charge", "Charge", "C", -kLarge, kLarge, 3, false, false, PB_NUMBER(charge)},
};

const PropertySpec<BoxDesc> kBoxTable[] = {
    {"position.x", "Position x", "m", -kFar, kFar, 3, false, true, PB_NUMBER(position[0])},
    {"position.y", "Position y", "m", -kFar, kFar, 3, false, true, PB_NUMBER(position[1])},
    {"size.w", "Width", "m", 0.001, kFar, 3, false, false, PB_NUMBER(size[0])},
    {"size.h", "Height", "m", 0.001, kFar, 3, false, false, PB_NUMBER(size[1])},
    {"angle", "Angle", "rad", -kFar, kFar, 3, false, true, PB_NUMBER(angle)},
    {"velocity.x", "Velocity x", "m/s", -kFar, kFar, 3, false, true, PB_NUMBER(velocity[0])},
    {"velocity.y", "Velocity y", "m/s", -kFar, kFar, 3, false, true, PB_NUMBER(velocity[1])},
    {"angular_velocity", "Angular velocity \u03c9", "rad/s", -kFar, kFar, 3, false, true,
     PB_NUMBER(angularVelocity)},
    // A box's mass may come from its density; editing it makes the mass explicit.
    {"mass", "Mass", "kg", 0.001, kLarge, 3, false, false,
     [](const BoxDesc& d) { return d.resolvedMass(); }, [](BoxDesc& d, double v) { d.mass = v; }},
    {"static", "Static", "", 0.0, 1.0, 0, true, false, PB_BOOL(isStatic)},
    {"friction", "Friction", "", 0.0, 10.0, 2, false, false, PB_NUMBER(friction)},
    {"restitution", "Restitution", "", 0.0, 1.0, 2, false, false, PB_NUMBER(restitution)},
};

// A plane's normal is edited as the tilt of the surface: 0 = a floor (normal up), π/2 = a wall
// facing −x. Two spin boxes for the normal's components would let it become zero.
const PropertySpec<PlaneDesc> kPlaneTable[] = {
    {"point.x", "Point x", "m", -kFar, kFar, 3, false, false, PB_NUMBER(point[0])},
    {"point.y", "Point y", "m", -kFar, kFar, 3, false, false, PB_NUMBER(point[1])},
    {"angle", "Tilt", "rad", -std::numbers::pi, std::numbers::pi, 3, false, false,
     [](const PlaneDesc& d) { return std::atan2(-d.normal[0], d.normal[1]); },
     [](PlaneDesc& d, double v) {
         d.normal = {-std::sin(v), std::cos(v)};
     }},
    {"friction", "Friction", "", 0.0, 10.0, 2, false, false, PB_NUMBER(friction)},
    {"restitution", "Restitution", "", 0.0, 1.0, 2, false, false, PB_NUMBER(restitution)},
};

bool hasAnchor(const SpringDesc& d) {
    return d.anchor.has_value();
}
const PropertySpec<SpringDesc> kSpringTable[] = {
    {"stiffness", "Stiffness k", "N/m", 0.001, kLarge, 3, false, false, PB_NUMBER(stiffness)},
    {"damping", "Damping c", "N\u00b7s/m", 0.0, kLarge, 3, false, false, PB_NUMBER(damping)},
    // Shown as the initial distance while the scene gives none (propertiesOf fills it in).
    {"rest_length", "Rest length", "m", 0.0, kFar, 3, false, false,
     [](const SpringDesc& d) { return d.restLength.value_or(0.0); },
     [](SpringDesc& d, double v) { d.restLength = v; }},
    {"anchor.x", "Anchor x", "m", -kFar, kFar, 3, false, false,
     [](const SpringDesc& d) { return d.anchor ? (*d.anchor)[0] : 0.0; },
     [](SpringDesc& d, double v) {
         if (d.anchor) (*d.anchor)[0] = v;
     },
     hasAnchor},
    {"anchor.y", "Anchor y", "m", -kFar, kFar, 3, false, false,
     [](const SpringDesc& d) { return d.anchor ? (*d.anchor)[1] : 0.0; },
     [](SpringDesc& d, double v) {
         if (d.anchor) (*d.anchor)[1] = v;
     },
     hasAnchor},
};

const PropertySpec<ClothDesc> kClothTable[] = {
    {"origin.x", "Origin x", "m", -kFar, kFar, 3, false, true, PB_NUMBER(origin[0])},
    {"origin.y", "Origin y", "m", -kFar, kFar, 3, false, true, PB_NUMBER(origin[1])},
    {"size.w", "Width", "m", 0.001, kFar, 3, false, true, PB_NUMBER(size[0])},
    {"size.h", "Height", "m", 0.001, kFar, 3, false, true, PB_NUMBER(size[1])},
    {"resolution.x", "Columns", "", 2.0, 200.0, 0, false, true, PB_INT(resolution[0])},
    {"resolution.y", "Rows", "", 2.0, 200.0, 0, false, true, PB_INT(resolution[1])},
    {"mass", "Mass (total)", "kg", 0.001, kLarge, 3, false, false, PB_NUMBER(mass)},
    {"stiffness.structural", "Structural stiffness", "N/m", 0.0, kLarge, 2, false, false,
     PB_NUMBER(stiffness.structural)},
    {"stiffness.shear", "Shear stiffness", "N/m", 0.0, kLarge, 2, false, false,
     PB_NUMBER(stiffness.shear)},
    {"stiffness.bend", "Bend stiffness", "N/m", 0.0, kLarge, 2, false, false,
     PB_NUMBER(stiffness.bend)},
    {"damping", "Damping", "N\u00b7s/m", 0.0, kLarge, 3, false, false, PB_NUMBER(damping)},
    {"radius", "Node radius", "m", 0.0, kFar, 3, false, false, PB_NUMBER(radius)},
};

#undef PB_NUMBER
#undef PB_BOOL
#undef PB_INT

// The scene's array for a kind, by the desc type.
std::vector<ParticleDesc>& array(SceneDesc& s, const ParticleDesc*) {
    return s.particles;
}
std::vector<BoxDesc>& array(SceneDesc& s, const BoxDesc*) {
    return s.boxes;
}
std::vector<PlaneDesc>& array(SceneDesc& s, const PlaneDesc*) {
    return s.planes;
}
std::vector<SpringDesc>& array(SceneDesc& s, const SpringDesc*) {
    return s.springs;
}
std::vector<ClothDesc>& array(SceneDesc& s, const ClothDesc*) {
    return s.cloths;
}

// Calls fn(table, desc) for the object at ref.
template <typename Scene, typename Fn>
bool visitObject(Scene& scene, ObjectRef ref, Fn&& fn) {
    switch (ref.kind) {
        case ObjectKind::Particle:
            fn(std::span(kParticleTable), scene.particles[ref.index]);
            return true;
        case ObjectKind::Box:
            fn(std::span(kBoxTable), scene.boxes[ref.index]);
            return true;
        case ObjectKind::Plane:
            fn(std::span(kPlaneTable), scene.planes[ref.index]);
            return true;
        case ObjectKind::Spring:
            fn(std::span(kSpringTable), scene.springs[ref.index]);
            return true;
        case ObjectKind::Cloth:
            fn(std::span(kClothTable), scene.cloths[ref.index]);
            return true;
        case ObjectKind::None:
            break;
    }
    return false;
}

template <typename Table>
typename Table::element_type* findSpec(Table table, const QString& key) {
    for (auto& spec : table)
        if (key == QLatin1String(spec.key)) return &spec;
    return nullptr;
}

// Setup position of a point fixed to a body (particle, box, cloth node); nullopt if unknown.
std::optional<Point2> bodyPoint(const SceneDesc& scene, const std::string& id,
                                const Point2& local) {
    const ObjectRef ref = findObject(scene, id);
    if (ref.kind == ObjectKind::Particle) return scene.particles[ref.index].position;
    if (ref.kind == ObjectKind::Box) {
        const BoxDesc& b = scene.boxes[ref.index];
        const double c = std::cos(b.angle), s = std::sin(b.angle);
        return Point2{b.position[0] + c * local[0] - s * local[1],
                      b.position[1] + s * local[0] + c * local[1]};
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
    for (std::size_t i = 0; i < scene.planes.size(); ++i)
        if (planeId(scene, i) == id) return {ObjectKind::Plane, i};
    for (std::size_t i = 0; i < scene.springs.size(); ++i)
        if (springId(scene, i) == id) return {ObjectKind::Spring, i};
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
        case ObjectKind::Plane:
            return planeId(scene, ref.index);
        case ObjectKind::Spring:
            return springId(scene, ref.index);
        case ObjectKind::Cloth:
            return scene.cloths[ref.index].id;
        case ObjectKind::None:
            break;
    }
    return {};
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
        case ObjectKind::Plane:
            return scene.planes[ref.index];
        case ObjectKind::Spring:
            return scene.springs[ref.index];
        case ObjectKind::Cloth:
            return scene.cloths[ref.index];
        case ObjectKind::None:
            break;
    }
    return {};
}

void setObjectDesc(SceneDesc& scene, ObjectRef ref, const ObjectDesc& object) {
    if (objectKind(object) != ref.kind) return;
    std::visit([&](const auto& desc) { array(scene, &desc)[ref.index] = desc; }, object);
}

QString objectKindName(ObjectKind kind) {
    switch (kind) {
        case ObjectKind::Particle:
            return QStringLiteral("particle");
        case ObjectKind::Box:
            return QStringLiteral("box");
        case ObjectKind::Plane:
            return QStringLiteral("plane");
        case ObjectKind::Spring:
            return QStringLiteral("spring");
        case ObjectKind::Cloth:
            return QStringLiteral("cloth");
        case ObjectKind::None:
            break;
    }
    return QStringLiteral("object");
}

std::vector<std::string> objectIds(const SceneDesc& scene) {
    std::vector<std::string> ids;
    for (std::size_t i = 0; i < scene.particles.size(); ++i) ids.push_back(particleId(scene, i));
    for (std::size_t i = 0; i < scene.boxes.size(); ++i) ids.push_back(boxId(scene, i));
    for (std::size_t i = 0; i < scene.planes.size(); ++i) ids.push_back(planeId(scene, i));
    for (std::size_t i = 0; i < scene.springs.size(); ++i) ids.push_back(springId(scene, i));
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

void assignDefaultIds(SceneDesc& scene) {
    for (std::size_t i = 0; i < scene.particles.size(); ++i)
        scene.particles[i].id = particleId(scene, i);
    for (std::size_t i = 0; i < scene.boxes.size(); ++i) scene.boxes[i].id = boxId(scene, i);
    for (std::size_t i = 0; i < scene.planes.size(); ++i) scene.planes[i].id = planeId(scene, i);
    for (std::size_t i = 0; i < scene.springs.size(); ++i) scene.springs[i].id = springId(scene, i);
}

std::optional<double> initialSpringLength(const SceneDesc& scene, const SpringDesc& spring) {
    const std::optional<Point2> a = bodyPoint(scene, spring.a, spring.aPoint);
    const std::optional<Point2> b =
        spring.b ? bodyPoint(scene, *spring.b, spring.bPoint) : spring.anchor;
    if (!a || !b) return std::nullopt;
    return std::hypot((*a)[0] - (*b)[0], (*a)[1] - (*b)[1]);
}

std::vector<PropertyRow> propertiesOf(const SceneDesc& scene, const QString& id) {
    std::vector<PropertyRow> rows;
    const ObjectRef ref = findObject(scene, id.toStdString());
    visitObject(scene, ref, [&](auto table, const auto& desc) {
        for (const auto& spec : table) {
            if (spec.applies && !spec.applies(desc)) continue;
            rows.push_back({QLatin1String(spec.key), QString::fromUtf8(spec.label),
                            QString::fromUtf8(spec.unit), spec.get(desc), spec.minimum,
                            spec.maximum, spec.decimals, spec.isBool});
        }
    });
    if (ref.kind == ObjectKind::Spring && !scene.springs[ref.index].restLength) {
        for (PropertyRow& row : rows)
            if (row.key == QLatin1String("rest_length"))
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
    visitObject(scene, findObject(scene, id.toStdString()), [&](auto table, auto& desc) {
        const auto* spec = findSpec(table, key);
        // "pinned" is what a box's "static" is called in the generic pin command's vocabulary.
        if (!spec && key == QLatin1String("pinned"))
            spec = findSpec(table, QStringLiteral("static"));
        if (!spec || (spec->applies && !spec->applies(desc))) return;
        spec->set(desc, value);
        found = true;
    });
    return found;
}

bool propertyMovesObject(const SceneDesc& scene, const QString& id, const QString& key) {
    bool moves = false;
    visitObject(scene, findObject(scene, id.toStdString()), [&](auto table, const auto&) {
        if (const auto* spec = findSpec(table, key)) moves = spec->movesObject;
    });
    return moves;
}

}  // namespace phasebox
