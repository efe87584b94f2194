// A polygon's area, centroid, mass and moment of inertia, from one sweep over the triangle fan
// of its vertices, and the move of a polygon's frame to its centroid (the springs and joints
// attached to it follow).
#include "physics/scene/SceneDesc.h"

#include <algorithm>
#include <cmath>

namespace phasebox {

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

}  // namespace phasebox
