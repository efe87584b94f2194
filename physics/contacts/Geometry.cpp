#include "physics/contacts/Geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace phasebox {

namespace {

// Shorter vectors are not normalised: their squared length would fall below the smallest
// normal double (≈ 1e-308) and lose precision, so the quotient would not be a unit vector.
constexpr double kMinLength = 1e-150;

// Box2D's tolerance for keeping A's face as the reference: 0.1 of its linear slop (5 mm, the
// ContactSolver's default too). Face-to-face contact makes both boxes' separations equal up to
// round-off and solver jitter; without a bias the reference face (and with it every feature id)
// would flip between steps and the warm-started impulses would be lost. Capped at a
// hundredth of the smaller box so that it cannot choose a wrong face on very small boxes.
constexpr double kReferenceFaceBias = 0.1 * 0.005;

// Box corners and faces are numbered as in Box2D's b2MakeBox: corner i at (±hx, ±hy)
// counter-clockwise from (−hx, −hy), face i from corner i to corner i + 1, outward normal below.
constexpr double kCornerSign[4][2] = {{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}};
constexpr double kFaceNormal[4][2] = {{0.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}};

Vec2 localCorner(const Vec2& halfExtents, int i) {
    return {kCornerSign[i][0] * halfExtents.x(), kCornerSign[i][1] * halfExtents.y()};
}

// A convex shape's corners and outward face normals (a box's four, a polygon's up to 16),
// counter-clockwise, relative to an origin near the pair (so that large coordinates cancel
// before anything is multiplied). Face i runs from corner i to corner i + 1. A box's count is
// fixed, so that its pair tests unroll.
struct PlacedShape {
    int count = 4;
    Vec2 corners[kMaxPolygonVertices];
    Vec2 normals[kMaxPolygonVertices];
    int next(int i) const { return i + 1 == count ? 0 : i + 1; }
};

struct PlacedBox {
    static constexpr int count = 4;
    Vec2 corners[4];
    Vec2 normals[4];
    static int next(int i) { return (i + 1) & 3; }
};

PlacedBox placeBox(const OrientedBox& box, const Vec2& origin) {
    const Mat2& r = box.rotation;
    const Vec2 center = box.center - origin;
    PlacedBox placed;
    for (int i = 0; i < 4; ++i) {
        placed.corners[i] = center + r * localCorner(box.halfExtents, i);
        placed.normals[i] = r * Vec2(kFaceNormal[i][0], kFaceNormal[i][1]);
    }
    return placed;
}

PlacedShape placePolygon(const OrientedPolygon& polygon, const Vec2& origin) {
    const Mat2& r = polygon.rotation;
    const Vec2 center = polygon.center - origin;
    PlacedShape placed;
    placed.count = polygon.count;
    for (int i = 0; i < polygon.count; ++i) {
        placed.corners[i] = center + r * polygon.vertices[i];
        placed.normals[i] = r * polygon.normals[i];
    }
    return placed;
}

// The face of `box` along whose normal `other` lies farthest out, and that separation (the
// depth of `other`'s deepest corner below the face's plane; negative when overlapping).
template <class Box, class Other>
double maxSeparation(const Box& box, const Other& other, int& bestFace) {
    double best = -std::numeric_limits<double>::infinity();
    bestFace = 0;
    for (int i = 0; i < box.count; ++i) {
        double deepest = std::numeric_limits<double>::infinity();
        for (int k = 0; k < other.count; ++k) {
            deepest = std::min(deepest, box.normals[i].dot(other.corners[k] - box.corners[i]));
        }
        if (deepest > best) {
            best = deepest;
            bestFace = i;
        }
    }
    return best;
}

// The same against a box: its deepest corner along a face's normal n lies below its centre by
// the projections of its half extents, |n·e_x| + |n·e_y|, one term per face instead of a look at
// each of the four corners.
template <class Shape>
double maxSeparation(const Shape& shape, const PlacedBox& box, int& bestFace) {
    const Vec2 center = 0.5 * (box.corners[0] + box.corners[2]);
    const Vec2 ex = 0.5 * (box.corners[1] - box.corners[0]);
    const Vec2 ey = 0.5 * (box.corners[3] - box.corners[0]);
    double best = -std::numeric_limits<double>::infinity();
    bestFace = 0;
    for (int i = 0; i < shape.count; ++i) {
        const Vec2& n = shape.normals[i];
        const double deepest =
            n.dot(center - shape.corners[i]) - std::abs(n.dot(ex)) - std::abs(n.dot(ey));
        if (deepest > best) {
            best = deepest;
            bestFace = i;
        }
    }
    return best;
}

// Keeps the part of segment v on the side dir·x ≤ offset. An end beyond the plane is moved onto
// it rather than dropped, so that v[0] and v[1] keep naming the same ends of the incident edge
// (which is what makes the feature ids stable when a point slides past a side plane).
bool clipSegment(Vec2 (&v)[2], const Vec2& dir, double offset) {
    const double d0 = dir.dot(v[0]) - offset;
    const double d1 = dir.dot(v[1]) - offset;
    if (d0 > 0.0 && d1 > 0.0) return false;
    if (d0 > 0.0) {
        v[0] += (d0 / (d0 - d1)) * (v[1] - v[0]);
    } else if (d1 > 0.0) {
        v[1] += (d1 / (d1 - d0)) * (v[0] - v[1]);
    }
    return true;
}

// Feature id of a point between two boxes or polygons, like Box2D's b2ContactFeature packed
// into ten bits: bit 9 whether B holds the reference face, bits 5–8 the reference face, bits 1–4
// the incident face (up to 16 faces each), bit 0 which end of the incident edge. None of it depends
// on the point's position, so a resting contact keeps its ids while it jitters.
std::uint32_t featureId(bool referenceIsB, int referenceFace, int incidentFace, int end) {
    return (referenceIsB ? 1u << 9 : 0u) | static_cast<std::uint32_t>(referenceFace) << 5 |
           static_cast<std::uint32_t>(incidentFace) << 1 | static_cast<std::uint32_t>(end);
}

void addPoint(Manifold& m, const Vec2& position, double separation, std::uint32_t id) {
    ManifoldPoint& p = m.points[m.pointCount++];
    p.position = position;
    p.separation = separation;
    p.id = id;
}

}  // namespace

Aabb boundingBox(const Disk& disk) {
    const Vec2 r(disk.radius, disk.radius);
    return {disk.center - r, disk.center + r};
}

Aabb boundingBox(const OrientedBox& box) {
    const double c = std::abs(box.rotation(0, 0)), s = std::abs(box.rotation(1, 0));
    const Vec2 extent(c * box.halfExtents.x() + s * box.halfExtents.y(),
                      s * box.halfExtents.x() + c * box.halfExtents.y());
    return {box.center - extent, box.center + extent};
}

Vec2 coincidentNormal(std::uint32_t a, std::uint32_t b) {
    // SplitMix64's finaliser on the packed pair: nearby indices land far apart on the circle.
    std::uint64_t z = (static_cast<std::uint64_t>(a) << 32 | b) + 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    const double angle = 2.0 * std::numbers::pi * (static_cast<double>(z >> 11) * 0x1.0p-53);
    return {std::cos(angle), std::sin(angle)};
}

bool coincident(const Vec2& a, const Vec2& b) {
    // The square root only near the threshold: far from it the squared length decides alike.
    const double squared = (b - a).squaredNorm();
    if (squared > 4.0 * kMinLength * kMinLength) return false;
    if (squared < 0.25 * kMinLength * kMinLength) return true;
    return !(std::sqrt(squared) > kMinLength);
}

bool collideDisks(const Disk& a, const Disk& b, double margin, Manifold& m,
                  const Vec2& whenCoincident) {
    m.pointCount = 0;
    const Vec2 d = b.center - a.center;
    const double distance = d.norm();
    // Coincident centres give no direction: the caller's (the pair's) fallback.
    const Vec2 normal = distance > kMinLength ? Vec2(d / distance) : whenCoincident;
    const double separation = distance - a.radius - b.radius;
    if (!(separation < margin)) return false;
    m.normal = normal;
    // Midway between a's surface point (a.r along n) and b's (distance − b.r along n).
    addPoint(m, a.center + (0.5 * (a.radius + distance - b.radius)) * normal, separation, 0);
    return true;
}

bool collidePlaneDisk(const HalfPlane& a, const Disk& b, double margin, Manifold& m) {
    m.pointCount = 0;
    const double height = a.normal.dot(b.center - a.point);
    const double separation = height - b.radius;
    if (!(separation < margin)) return false;
    m.normal = a.normal;
    addPoint(m, b.center - (0.5 * (height + b.radius)) * a.normal, separation, 0);
    return true;
}

bool collideBoxDisk(const OrientedBox& a, const Disk& b, double margin, Manifold& m) {
    m.pointCount = 0;
    const Mat2& r = a.rotation;
    const Vec2& h = a.halfExtents;
    const Vec2 c = r.transpose() * (b.center - a.center);  // disk centre in the box's frame
    Vec2 surface = c.cwiseMax(-h).cwiseMin(h);             // closest point of the box
    const Vec2 outside = c - surface;
    const double distance = outside.norm();
    Vec2 normal;
    if (distance > kMinLength) {
        normal = outside / distance;
    } else {
        // The centre is inside (or on the boundary): the closest point gives no direction, so
        // leave through the face that is nearest, the axis of least penetration.
        const double depthX = h.x() - std::abs(c.x()), depthY = h.y() - std::abs(c.y());
        if (depthX < depthY) {
            normal = {c.x() >= 0.0 ? 1.0 : -1.0, 0.0};
            surface = {normal.x() * h.x(), c.y()};
        } else {
            normal = {0.0, c.y() >= 0.0 ? 1.0 : -1.0};
            surface = {c.x(), normal.y() * h.y()};
        }
    }
    const double separation = normal.dot(c - surface) - b.radius;
    if (!(separation < margin)) return false;
    m.normal = r * normal;
    const Vec2 midway = 0.5 * (surface + c - b.radius * normal);
    addPoint(m, a.center + r * midway, separation, 0);
    return true;
}

namespace {
// A convex shape's corners (offsets from its centre, turned) against a plane: the two deepest
// within the margin. Two points are enough: the two deepest corners of a convex polygon on a
// plane share an edge, and a third corner within the margin adds nothing the solver needs.
bool collidePlaneCorners(const HalfPlane& a, const Vec2& center, const Vec2* offset, int count,
                         double margin, Manifold& m) {
    m.pointCount = 0;
    const double centerHeight = a.normal.dot(center - a.point);
    double height[kMaxPolygonVertices];
    int deepest = -1, second = -1;
    for (int i = 0; i < count; ++i) {
        height[i] = centerHeight + a.normal.dot(offset[i]);
        if (!(height[i] < margin)) continue;
        if (deepest < 0 || height[i] < height[deepest]) {
            second = deepest;
            deepest = i;
        } else if (second < 0 || height[i] < height[second]) {
            second = i;
        }
    }
    if (deepest < 0) return false;
    m.normal = a.normal;
    for (const int i : {deepest, second}) {
        if (i < 0) break;
        const Vec2 midway = center + offset[i] - (0.5 * height[i]) * a.normal;
        addPoint(m, midway, height[i], static_cast<std::uint32_t>(i));
    }
    return true;
}
}  // namespace

bool collidePlaneBox(const HalfPlane& a, const OrientedBox& b, double margin, Manifold& m) {
    Vec2 offset[4];  // corner − centre
    for (int i = 0; i < 4; ++i) offset[i] = b.rotation * localCorner(b.halfExtents, i);
    return collidePlaneCorners(a, b.center, offset, 4, margin, m);
}

namespace {
// The incident face of the other shape clipped against the reference face's side planes: up to
// two points.
template <class Reference, class Incident>
bool clipIncident(const Reference& reference, const Incident& incident, int referenceFace,
                  bool referenceIsB, const Vec2& origin, double margin, Manifold& m) {
    const Vec2& normal = reference.normals[referenceFace];

    // The incident face is the one most anti-parallel to the reference normal: its edge is the
    // part of the other shape that faces the reference face.
    int incidentFace = 0;
    double mostOpposed = std::numeric_limits<double>::infinity();
    for (int i = 0; i < incident.count; ++i) {
        const double d = normal.dot(incident.normals[i]);
        if (d < mostOpposed) {
            mostOpposed = d;
            incidentFace = i;
        }
    }

    // Sutherland–Hodgman against the reference face's two side planes: what remains of the
    // incident edge lies over the reference face.
    Vec2 v[2] = {incident.corners[incidentFace], incident.corners[incident.next(incidentFace)]};
    const Vec2& start = reference.corners[referenceFace];
    const Vec2& end = reference.corners[reference.next(referenceFace)];
    const Vec2 tangent = perp(normal);  // from start to end (faces run counter-clockwise)
    if (!clipSegment(v, -tangent, -tangent.dot(start))) return false;
    if (!clipSegment(v, tangent, tangent.dot(end))) return false;

    m.normal = referenceIsB ? Vec2(-normal) : normal;
    for (int k = 0; k < 2; ++k) {
        const double separation = normal.dot(v[k] - start);
        if (!(separation < margin)) continue;
        // v[k] is on the incident surface; the reference surface is `separation` behind it.
        addPoint(m, origin + v[k] - (0.5 * separation) * normal, separation,
                 featureId(referenceIsB, referenceFace, incidentFace, k));
    }
    return m.pointCount > 0;
}

// Separating axes over both shapes' face normals, then the incident face clipped against the
// reference face's side planes: up to two points. smallest: the smaller shape's least half
// extent (a polygon's inradius), which bounds the reference-face bias.
template <class ShapeA, class ShapeB>
bool collidePlaced(const ShapeA& boxA, const ShapeB& boxB, const Vec2& origin, double smallest,
                   bool centresCoincide, const Vec2& whenCoincident, double margin, Manifold& m) {
    m.pointCount = 0;
    int faceA = 0, faceB = 0;
    const double separationA = maxSeparation(boxA, boxB, faceA);
    if (!(separationA < margin)) return false;  // no clipped point can be closer than this
    const double separationB = maxSeparation(boxB, boxA, faceB);
    if (!(separationB < margin)) return false;

    const double bias = std::min(kReferenceFaceBias, 0.01 * smallest);
    bool referenceIsB = separationB > separationA + bias;
    if (centresCoincide) {
        referenceIsB = false;
        double nearest = -std::numeric_limits<double>::infinity();
        for (int i = 0; i < boxA.count; ++i)
            if (boxA.normals[i].dot(whenCoincident) > nearest) {
                nearest = boxA.normals[i].dot(whenCoincident);
                faceA = i;
            }
    }
    return referenceIsB ? clipIncident(boxB, boxA, faceB, true, origin, margin, m)
                        : clipIncident(boxA, boxB, faceA, false, origin, margin, m);
}

}  // namespace

bool collideBoxes(const OrientedBox& a, const OrientedBox& b, double margin, Manifold& m,
                  const Vec2& whenCoincident) {
    const Vec2 origin = a.center;
    const double smallest =
        std::min({a.halfExtents.x(), a.halfExtents.y(), b.halfExtents.x(), b.halfExtents.y()});
    return collidePlaced(placeBox(a, origin), placeBox(b, origin), origin, smallest,
                         coincident(a.center, b.center), whenCoincident, margin, m);
}

bool collidePolygons(const OrientedPolygon& a, const OrientedPolygon& b, double margin, Manifold& m,
                     const Vec2& whenCoincident) {
    const Vec2 origin = a.center;
    return collidePlaced(placePolygon(a, origin), placePolygon(b, origin), origin,
                         std::min(a.inradius, b.inradius), coincident(a.center, b.center),
                         whenCoincident, margin, m);
}

bool collidePolygonBox(const OrientedPolygon& a, const OrientedBox& b, double margin, Manifold& m,
                       const Vec2& whenCoincident) {
    const Vec2 origin = a.center;
    const double smallest = std::min({a.inradius, b.halfExtents.x(), b.halfExtents.y()});
    return collidePlaced(placePolygon(a, origin), placeBox(b, origin), origin, smallest,
                         coincident(a.center, b.center), whenCoincident, margin, m);
}

bool collidePolygonDisk(const OrientedPolygon& a, const Disk& b, double margin, Manifold& m) {
    // Box2D's b2CollidePolygonAndCircle: the face the centre lies farthest out of, then the
    // centre's region of it (a vertex beyond either end, else the face).
    m.pointCount = 0;
    const Mat2& r = a.rotation;
    const Vec2 c = r.transpose() * (b.center - a.center);  // the centre in the polygon's frame
    int face = 0;
    double separation = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < a.count; ++i) {
        const double s = a.normals[i].dot(c - a.vertices[i]);
        if (s > separation) {
            separation = s;
            face = i;
        }
    }
    if (!(separation - b.radius < margin)) return false;
    const Vec2& v1 = a.vertices[face];
    const Vec2& v2 = a.vertices[face + 1 == a.count ? 0 : face + 1];
    Vec2 normal, surface;
    if (separation <= 0.0) {  // the centre is inside: out through the nearest face
        normal = a.normals[face];
        surface = c - separation * normal;
    } else if ((c - v1).dot(v2 - v1) <= 0.0 || (c - v2).dot(v1 - v2) <= 0.0) {
        surface = (c - v1).dot(v2 - v1) <= 0.0 ? v1 : v2;
        const Vec2 outside = c - surface;
        const double distance = outside.norm();
        if (!(distance - b.radius < margin)) return false;
        normal = distance > kMinLength ? Vec2(outside / distance) : a.normals[face];
        separation = distance;
    } else {
        normal = a.normals[face];
        surface = c - separation * normal;
    }
    const double gap = separation - b.radius;
    if (!(gap < margin)) return false;
    m.normal = r * normal;
    const Vec2 midway = 0.5 * (surface + c - b.radius * normal);
    addPoint(m, a.center + r * midway, gap, 0);
    return true;
}

bool collidePlanePolygon(const HalfPlane& a, const OrientedPolygon& b, double margin, Manifold& m) {
    Vec2 offset[kMaxPolygonVertices];
    for (int i = 0; i < b.count; ++i) offset[i] = b.rotation * b.vertices[i];
    return collidePlaneCorners(a, b.center, offset, b.count, margin, m);
}

Aabb boundingBox(const OrientedPolygon& polygon) {
    Vec2 lower = Vec2::Constant(std::numeric_limits<double>::infinity()), upper = -lower;
    for (int i = 0; i < polygon.count; ++i) {
        const Vec2 p = polygon.center + polygon.rotation * polygon.vertices[i];
        lower = lower.cwiseMin(p);
        upper = upper.cwiseMax(p);
    }
    return {lower, upper};
}

}  // namespace phasebox
