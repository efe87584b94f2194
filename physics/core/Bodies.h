#pragma once
// The object records: what a scene's particles, rigid bodies, planes, springs and cloths are once
// built. Cold data (ids, materials, setup values) lives here; the hot state of a dynamic
// object is in the world's flat vectors (q, u) at the record's `dof`.
//
// For a dynamic object the state is authoritative and the record's position/velocity are only
// its setup values; for a pinned particle, a static rigid body or a body asleep the record's fields
// are the truth.

#include "physics/core/Types.h"

#include <string>
#include <vector>

namespace phasebox {

struct Particle {
    std::string id;
    Vec2 position{0.0, 0.0};  // setup value; live value in the state unless pinned
    Vec2 velocity{0.0, 0.0};
    double mass = 1.0;
    double radius = 0.05;
    bool pinned = false;
    double restitution = 0.5;
    double friction = 0.2;
    double charge = 0.0;
    int cloth = -1;  // index of the cloth this node belongs to, or −1
    int dof = -1;    // first state index, −1 when pinned or asleep
    // Its island sleeps (simulation.sleep): out of the state, the record holds its state.
    bool asleep = false;
};

// A rigid body: x, y and an angle, whatever its shape: a rectangle (the scene's `boxes`), a disk
// (`disks`) or a convex polygon (`polygons`) share this one record.
enum class RigidShape : unsigned char { Rectangle, Disk, Polygon };

struct RigidBody {
    std::string id;
    RigidShape shape = RigidShape::Rectangle;
    double radius = 0.0;  // a disk's; its size is then its bounding square, 2r × 2r
    // A polygon's corners counter-clockwise about its centroid, and its faces' outward normals
    // (face i from corner i to i + 1); its size is then its bounding square about the centroid.
    std::vector<Vec2> vertices, normals;
    double inradius = 0.0;    // a polygon's: the least distance from its centroid to a face
    Vec2 position{0.0, 0.0};  // setup value; live value in the state unless static
    double angle = 0.0;
    Vec2 velocity{0.0, 0.0};
    double angularVelocity = 0.0;
    Vec2 size{1.0, 1.0};
    double mass = 1.0;
    double inertia = 1.0 / 6.0;
    bool isStatic = false;
    double friction = 0.6;
    double restitution = 0.0;
    int dof = -1;  // first state index, −1 when static or asleep
    // Its island sleeps (simulation.sleep): out of the state, the record holds its state.
    bool asleep = false;
};

struct Plane {
    std::string id;
    Vec2 point{0.0, 0.0};
    Vec2 normal{0.0, 1.0};  // unit; solid on the side opposite the normal
    double friction = 0.5;
    double restitution = 0.5;
};

// One end of a spring, by object index (resolved to a BodyPoint when the layout is built).
struct SpringEnd {
    enum class Kind { Particle, Rigid, Anchor };
    Kind kind = Kind::Anchor;
    int index = -1;        // particle or rigid body index
    Vec2 point{0.0, 0.0};  // rigid: attachment in the body's frame; anchor: world point
};

struct Spring {
    std::string id;
    SpringEnd a, b;
    double stiffness = 0.0;
    double damping = 0.0;
    double restLength = 0.0;
    int cloth = -1;
};

struct Cloth {
    std::string id;
    int nx = 0, ny = 0;
    int firstParticle = 0;  // node (i, j) is particle firstParticle + j·nx + i
    int firstSpring = 0;
    int springCount = 0;
};

// One body a joint holds: a particle (or cloth node), a rigid body, or the fixed world; the
// point is in the body's own frame (a particle's is unused), or a world point for the world.
struct JointBody {
    enum class Kind : unsigned char { Particle, Rigid, World };
    Kind kind = Kind::World;
    int index = -1;        // particle or rigid body index
    Vec2 point{0.0, 0.0};  // in the body's frame; for the world, where it is
};

// A joint (CONTRACT §6). Equality joints (hinge, rod, weld, pulley, track, and a rope while it
// is taut) enter every derivative evaluation as constraint forces; a hinge's limits and motor
// act after the step (JointSolver).
struct Joint {
    enum class Type : unsigned char { Hinge, Rod, Rope, Weld, Pulley, Track };
    std::string id;
    Type type = Type::Hinge;
    JointBody a, b;
    double length = 0.0;  // rod, rope; pulley: the constant |ga − pa| + ratio·|gb − pb|
    double referenceAngle = 0.0;  // hinge, weld: θb − θa at load
    Vec2 offset{0.0, 0.0};        // hinge, weld: pa − pb kept (nonzero only between particles)
    bool hasLimits = false;
    double lower = 0.0, upper = 0.0;  // hinge: bounds of θb − θa − referenceAngle
    bool hasMotor = false;
    double motorSpeed = 0.0, maxMotorTorque = 0.0;
    Vec2 groundA{0.0, 0.0}, groundB{0.0, 0.0};  // pulley
    double ratio = 1.0;
    // track: a circle (centre, radius) or a line (point, unit normal)
    bool circle = true;
    Vec2 center{0.0, 0.0};
    double radius = 0.0;
    Vec2 linePoint{0.0, 0.0}, lineNormal{0.0, 1.0};
};

// Every object of a world, by kind, in the order added (the scene file's order).
struct Bodies {
    std::vector<Particle> particles;
    std::vector<RigidBody> rigidBodies;
    std::vector<Plane> planes;
    std::vector<Spring> springs;
    std::vector<Cloth> cloths;
    std::vector<Joint> joints;
};

}  // namespace phasebox
