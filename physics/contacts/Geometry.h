#pragma once
// Collision shapes and contact manifolds: plain geometry, no bodies, no state layout.
//
// Conventions (shared by every narrow-phase function):
// - A manifold's normal is a unit vector pointing from shape A to shape B.
// - A point's separation is the signed distance between the two surfaces along the normal at
//   that point: negative when they overlap. Points are reported when separation < margin
//   (speculative contacts: margin > 0 finds contacts that are about to happen).
// - A point's position is midway between the two surfaces.
// - A point's id names the features that made it (e.g. reference face and incident vertex),
//   so that the same contact keeps its id from step to step and its impulse can warm-start.

#include "physics/core/Types.h"

#include <cstdint>

namespace phasebox {

struct Disk {
    Vec2 center;
    double radius;
};

// A box at an angle; its rotation is computed once here, not once per pair it is tested in.
struct OrientedBox {
    OrientedBox() = default;
    OrientedBox(const Vec2& center_, double angle_, const Vec2& halfExtents_)
        : center(center_),
          angle(angle_),
          halfExtents(halfExtents_),
          rotation(phasebox::rotation(angle_)) {}
    Vec2 center = Vec2::Zero();
    double angle = 0.0;
    Vec2 halfExtents = Vec2::Zero();
    Mat2 rotation = Mat2::Identity();
};

// The most vertices a convex polygon may have (CONTRACT §6).
inline constexpr int kMaxPolygonVertices = 16;

// A convex polygon at an angle: its vertices counter-clockwise about its centroid and the
// outward normals of its faces (face i from vertex i to vertex i + 1), both in its own frame,
// held by the caller; inradius bounds the reference-face bias as a box's half extent does.
struct OrientedPolygon {
    Vec2 center = Vec2::Zero();
    Mat2 rotation = Mat2::Identity();
    int count = 0;
    const Vec2* vertices = nullptr;
    const Vec2* normals = nullptr;
    double inradius = 0.0;
};

// A static half-plane: solid on the side opposite the unit normal.
struct HalfPlane {
    Vec2 point;
    Vec2 normal;
};

struct Aabb {
    Vec2 lower;
    Vec2 upper;
    bool overlaps(const Aabb& o) const {
        return lower.x() <= o.upper.x() && o.lower.x() <= upper.x() && lower.y() <= o.upper.y() &&
               o.lower.y() <= upper.y();
    }
    bool contains(const Aabb& o) const {
        return lower.x() <= o.lower.x() && lower.y() <= o.lower.y() && o.upper.x() <= upper.x() &&
               o.upper.y() <= upper.y();
    }
};

struct ManifoldPoint {
    Vec2 position = Vec2::Zero();
    double separation = 0.0;
    std::uint32_t id = 0;
};

struct Manifold {
    Vec2 normal = Vec2::Zero();  // from A to B
    int pointCount = 0;
    ManifoldPoint points[2];
};

Aabb boundingBox(const Disk& disk);
Aabb boundingBox(const OrientedBox& box);

// A unit direction for a pair of shapes whose centres coincide, where geometry gives none:
// spread over the circle by a hash of the pair's indices, so that a pile of bodies started at
// one point is pushed apart in every direction (one shared fallback would line them all up
// along it) and the same pair gets the same normal in every run and every step.
Vec2 coincidentNormal(std::uint32_t a, std::uint32_t b);
// Whether two centres are too close for their difference to give a direction.
bool coincident(const Vec2& a, const Vec2& b);

// Each returns true and fills the manifold when at least one point has separation < margin.
// Disks whose centres coincide use whenCoincident as the normal.
bool collideDisks(const Disk& a, const Disk& b, double margin, Manifold& m,
                  const Vec2& whenCoincident = Vec2(0.0, 1.0));
bool collidePlaneDisk(const HalfPlane& a, const Disk& b, double margin, Manifold& m);
bool collideBoxDisk(const OrientedBox& a, const Disk& b, double margin, Manifold& m);
bool collidePlaneBox(const HalfPlane& a, const OrientedBox& b, double margin, Manifold& m);
// Separating axes over the four face normals, then the incident face clipped against the
// reference face's side planes: up to two points.
// Boxes whose centres coincide give SAT a tie on every face; whenCoincident then picks A's face
// whose normal lies nearest it (a pile started at one point spreads instead of stacking).
bool collideBoxes(const OrientedBox& a, const OrientedBox& b, double margin, Manifold& m,
                  const Vec2& whenCoincident = Vec2(0.0, 1.0));
// The same for convex polygons, and a polygon against a box (the box's faces are four more).
bool collidePolygons(const OrientedPolygon& a, const OrientedPolygon& b, double margin, Manifold& m,
                     const Vec2& whenCoincident = Vec2(0.0, 1.0));
bool collidePolygonBox(const OrientedPolygon& a, const OrientedBox& b, double margin, Manifold& m,
                       const Vec2& whenCoincident = Vec2(0.0, 1.0));
bool collidePolygonDisk(const OrientedPolygon& a, const Disk& b, double margin, Manifold& m);
bool collidePlanePolygon(const HalfPlane& a, const OrientedPolygon& b, double margin, Manifold& m);
Aabb boundingBox(const OrientedPolygon& polygon);

}  // namespace phasebox
