// What a scene description works out of itself: the default ids of its objects (p0, b1, ...)
// and of a cloth's nodes, a disk's and a polygon's mass, a polygon's area, centroid and moment
// of inertia, the move of a polygon's frame to its centroid, which cloth nodes are pinned, and
// the work a step of the scene costs. validateScene() is in SceneValidation.cpp.
#include "physics/scene/SceneDesc.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace phasebox {

namespace {
std::string defaultOr(const std::string& id, const char* prefix, std::size_t index) {
    return id.empty() ? prefix + std::to_string(index) : id;
}
}  // namespace

std::string particleId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.particles[i].id, "p", i);
}
std::string boxId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.boxes[i].id, "b", i);
}
std::string diskId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.disks[i].id, "d", i);
}
double DiskDesc::resolvedMass() const {
    return mass ? *mass : density * std::numbers::pi * radius * radius;
}
std::string polygonId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.polygons[i].id, "poly", i);
}

namespace {
// The polygon's signed area and first moments (Σ over the triangle fan from the origin).
struct PolygonMoments {
    double area = 0.0;          // signed: > 0 counter-clockwise
    double mx = 0.0, my = 0.0;  // ∫x dA, ∫y dA
    double ixx = 0.0;           // ∫(x² + y²) dA about the origin
};
PolygonMoments momentsOf(const std::vector<Point2>& v) {
    PolygonMoments m;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const Point2& a = v[i];
        const Point2& b = v[(i + 1) % v.size()];
        const double cross = a[0] * b[1] - b[0] * a[1];
        m.area += 0.5 * cross;
        m.mx += cross * (a[0] + b[0]) / 6.0;
        m.my += cross * (a[1] + b[1]) / 6.0;
        m.ixx +=
            cross *
            (a[0] * a[0] + a[0] * b[0] + b[0] * b[0] + a[1] * a[1] + a[1] * b[1] + b[1] * b[1]) /
            12.0;
    }
    return m;
}
}  // namespace

double PolygonDesc::area() const {
    return std::abs(momentsOf(vertices).area);
}
Point2 PolygonDesc::centroid() const {
    const PolygonMoments m = momentsOf(vertices);
    return m.area != 0.0 ? Point2{m.mx / m.area, m.my / m.area} : Point2{0.0, 0.0};
}
double PolygonDesc::resolvedMass() const {
    return mass ? *mass : density * area();
}
double PolygonDesc::momentOfInertia() const {
    const PolygonMoments m = momentsOf(vertices);
    if (m.area == 0.0) return 0.0;
    // ∫r² dA about the origin, moved to the centroid (parallel axes), per unit area times mass.
    const double cx = m.mx / m.area, cy = m.my / m.area;
    const double perArea = m.ixx / m.area - (cx * cx + cy * cy);
    return resolvedMass() * perArea;
}

void recentrePolygons(SceneDesc& scene) {
    for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
        PolygonDesc& p = scene.polygons[i];
        const Point2 c = p.centroid();
        double size = 0.0;
        for (const Point2& v : p.vertices) size = std::max({size, std::abs(v[0]), std::abs(v[1])});
        if (!(std::hypot(c[0], c[1]) > 1e-12 * size)) continue;
        const std::string id = polygonId(scene, i);
        for (Point2& v : p.vertices) v = {v[0] - c[0], v[1] - c[1]};
        const double cosA = std::cos(p.angle), sinA = std::sin(p.angle);
        const Point2 rc{cosA * c[0] - sinA * c[1], sinA * c[0] + cosA * c[1]};
        p.position = {p.position[0] + rc[0], p.position[1] + rc[1]};
        p.velocity = {p.velocity[0] - p.angularVelocity * rc[1],
                      p.velocity[1] + p.angularVelocity * rc[0]};
        const auto shift = [&](Point2& q) { q = {q[0] - c[0], q[1] - c[1]}; };
        for (SpringDesc& s : scene.springs) {
            if (s.a == id) shift(s.aPoint);
            if (s.b && *s.b == id) shift(s.bPoint);
        }
        for (JointDesc& j : scene.joints) {
            if (j.a == id) shift(j.aPoint);
            if (j.b && *j.b == id) shift(j.bPoint);
        }
    }
}

std::string planeId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.planes[i].id, "plane", i);
}
std::string springId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.springs[i].id, "s", i);
}
long long stepWorkUnits(const SceneDesc& scene) {
    const auto count = [](const auto& objects) { return static_cast<long long>(objects.size()); };
    long long units = count(scene.particles) + count(scene.springs) +
                      SceneLimits::kCostlyWorkUnits * (count(scene.boxes) + count(scene.disks) +
                                                       count(scene.polygons) + count(scene.joints));
    for (const ClothDesc& cloth : scene.cloths) {
        const long long nx = std::max(0, cloth.resolution[0]),
                        ny = std::max(0, cloth.resolution[1]);
        // Its nodes and at most its structural, shear and bend springs.
        units += nx * ny + nx * std::max(0LL, ny - 1) + ny * std::max(0LL, nx - 1) +
                 2 * std::max(0LL, nx - 1) * std::max(0LL, ny - 1) + nx * std::max(0LL, ny - 2) +
                 ny * std::max(0LL, nx - 2);
    }
    return units;
}

std::string substepWorkProblem(const SceneDesc& scene, long long substeps) {
    const long long units = std::max(1LL, stepWorkUnits(scene));
    if (substeps <= SceneLimits::kMaxSubstepWork / units) return {};
    return std::to_string(substeps) + " sub-steps of a scene of " + std::to_string(units) +
           " work units (a particle, cloth node or spring 1, a rigid body or joint " +
           std::to_string(SceneLimits::kCostlyWorkUnits) + ") is " +
           "too much work a step: sub-steps times units may be at most " +
           std::to_string(SceneLimits::kMaxSubstepWork) + ", so at most " +
           std::to_string(SceneLimits::kMaxSubstepWork / units) + " sub-steps for this scene";
}

std::string jointId(const SceneDesc& s, std::size_t i) {
    return defaultOr(s.joints[i].id, "j", i);
}
std::string clothNodeId(const std::string& clothId, int i, int j) {
    return clothId + "[" + std::to_string(i) + "," + std::to_string(j) + "]";
}

bool clothNodePinned(const ClothDesc& cloth, int i, int j) {
    if (const auto* mode = std::get_if<std::string>(&cloth.pinned)) {
        if (*mode == "top") return j == 0;
        if (*mode == "top_corners") return j == 0 && (i == 0 || i == cloth.resolution[0] - 1);
        if (*mode == "left") return i == 0;
        return false;
    }
    const auto& nodes = std::get<std::vector<std::array<int, 2>>>(cloth.pinned);
    return std::find(nodes.begin(), nodes.end(), std::array<int, 2>{i, j}) != nodes.end();
}

}  // namespace phasebox
