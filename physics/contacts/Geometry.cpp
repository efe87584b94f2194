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

int nextFace(int i) {
    return (i + 1) & 3;
}

// A box's corners and outward face normals, relative to an origin near the pair (so that large
// coordinates cancel before anything is multiplied).
struct PlacedBox {
    Vec2 corners[4];
    Vec2 normals[4];
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

// The face of `box` along whose normal `other` lies farthest out, and that separation (the
// depth of `other`'s deepest corner below the face's plane; negative when overlapping).
double maxSeparation(const PlacedBox& box, const PlacedBox& other, int& bestFace) {
    double best = -std::numeric_limits<double>::infinity();
    bestFace = 0;
    for (int i = 0; i < 4; ++i) {
        double deepest = std::numeric_limits<double>::infinity();
        for (const Vec2& corner : other.corners) {
            deepest = std::min(deepest, box.normals[i].dot(corner - box.corners[i]));
        }
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

// Feature id of a box–box point, like Box2D's b2ContactFeature packed into six bits:
// bit 5 whether B holds the reference face, bits 3–4 the reference face, bits 1–2 the incident
// face, bit 0 which end of the incident edge. None of it depends on the point's position, so
// a resting contact keeps its ids while it jitters.
std::uint32_t boxFeatureId(bool referenceIsB, int referenceFace, int incidentFace, int end) {
    return (referenceIsB ? 1u << 5 : 0u) | static_cast<std::uint32_t>(referenceFace) << 3 |
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
    return !((b - a).norm() > kMinLength);
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

bool collidePlaneBox(const HalfPlane& a, const OrientedBox& b, double margin, Manifold& m) {
    m.pointCount = 0;
    const Mat2& r = b.rotation;
    const double centerHeight = a.normal.dot(b.center - a.point);
    double height[4];
    Vec2 offset[4];  // corner − centre
    int deepest = -1, second = -1;
    for (int i = 0; i < 4; ++i) {
        offset[i] = r * localCorner(b.halfExtents, i);
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
    // Two points are enough: the two deepest corners of a rectangle always share an edge, and
    // a third corner within the margin adds nothing the solver needs.
    m.normal = a.normal;
    for (const int i : {deepest, second}) {
        if (i < 0) break;
        const Vec2 midway = b.center + offset[i] - (0.5 * height[i]) * a.normal;
        addPoint(m, midway, height[i], static_cast<std::uint32_t>(i));
    }
    return true;
}

bool collideBoxes(const OrientedBox& a, const OrientedBox& b, double margin, Manifold& m,
                  const Vec2& whenCoincident) {
    m.pointCount = 0;
    const Vec2 origin = a.center;
    const PlacedBox boxA = placeBox(a, origin);
    const PlacedBox boxB = placeBox(b, origin);

    int faceA = 0, faceB = 0;
    const double separationA = maxSeparation(boxA, boxB, faceA);
    if (!(separationA < margin)) return false;  // no clipped point can be closer than this
    const double separationB = maxSeparation(boxB, boxA, faceB);
    if (!(separationB < margin)) return false;

    const double smallest =
        std::min({a.halfExtents.x(), a.halfExtents.y(), b.halfExtents.x(), b.halfExtents.y()});
    const double bias = std::min(kReferenceFaceBias, 0.01 * smallest);
    bool referenceIsB = separationB > separationA + bias;
    if (coincident(a.center, b.center)) {
        referenceIsB = false;
        double nearest = -std::numeric_limits<double>::infinity();
        for (int i = 0; i < 4; ++i)
            if (boxA.normals[i].dot(whenCoincident) > nearest) {
                nearest = boxA.normals[i].dot(whenCoincident);
                faceA = i;
            }
    }
    const PlacedBox& reference = referenceIsB ? boxB : boxA;
    const PlacedBox& incident = referenceIsB ? boxA : boxB;
    const int referenceFace = referenceIsB ? faceB : faceA;
    const Vec2& normal = reference.normals[referenceFace];

    // The incident face is the one most anti-parallel to the reference normal: its edge is the
    // part of the other box that faces the reference face.
    int incidentFace = 0;
    double mostOpposed = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 4; ++i) {
        const double d = normal.dot(incident.normals[i]);
        if (d < mostOpposed) {
            mostOpposed = d;
            incidentFace = i;
        }
    }

    // Sutherland–Hodgman against the reference face's two side planes: what remains of the
    // incident edge lies over the reference face.
    Vec2 v[2] = {incident.corners[incidentFace], incident.corners[nextFace(incidentFace)]};
    const Vec2& start = reference.corners[referenceFace];
    const Vec2& end = reference.corners[nextFace(referenceFace)];
    const Vec2 tangent = perp(normal);  // from start to end (faces run counter-clockwise)
    if (!clipSegment(v, -tangent, -tangent.dot(start))) return false;
    if (!clipSegment(v, tangent, tangent.dot(end))) return false;

    m.normal = referenceIsB ? Vec2(-normal) : normal;
    for (int k = 0; k < 2; ++k) {
        const double separation = normal.dot(v[k] - start);
        if (!(separation < margin)) continue;
        // v[k] is on the incident surface; the reference surface is `separation` behind it.
        addPoint(m, origin + v[k] - (0.5 * separation) * normal, separation,
                 boxFeatureId(referenceIsB, referenceFace, incidentFace, k));
    }
    return m.pointCount > 0;
}

}  // namespace phasebox
