#pragma once
// Plain description of a scene, mirroring scene format v1 (CONTRACT.md §1) field by field,
// with the contract's defaults. No behaviour lives here: buildWorld() turns it into a World,
// validateScene() checks it, and app/SceneIO maps it to and from JSON.

#include "physics/contacts/ContactModel.h"
#include "physics/core/WorkUnits.h"
#include "physics/scene/InstrumentsDesc.h"

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace phasebox {

using Point2 = std::array<double, 2>;

struct SimulationDesc {
    std::string integrator = "symplectic_euler";
    double dt = 1.0 / 60.0;
    int substeps = 1;
    double tolerance = 1e-6;
    int newtonIterations = 1;
    double duration = 10.0;
    // Contact solver settings (engine-defined keys). Stored as numbers so unknown engine keys
    // round-trip through files.
    std::map<std::string, double> solver;
    // How contacts respond (CONTRACT §6): the penalty model's stiffness per contact point is
    // automatic while absent (the lightest dynamic body gets ω·h = 0.5).
    ContactModel contactModel = ContactModel::Impulse;
    std::optional<double> contactStiffness;
    double contactDamping = 0.0;
    // Islands at rest sleep (CONTRACT §6): off unless the scene asks.
    bool sleep = false;
};

struct GravityDesc {
    Point2 g{0.0, -9.81};
};

struct DragDesc {
    double linear = 0.0;
    double quadratic = 0.0;
    double angular = 0.0;
};

struct AttractorDesc {
    Point2 position{0.0, 0.0};
    double mass = 0.0;
};

struct NewtonianGravityDesc {
    double G = 6.674e-11;
    std::vector<AttractorDesc> attractors;
    bool mutual = false;
    double softening = 0.0;
};

struct BuoyancyDesc {
    double fluidDensity = 1000.0;
    double surfaceY = 0.0;
    double drag = 0.0;
};

struct WindDesc {
    Point2 velocity{0.0, 0.0};
    double drag = 0.0;
};

struct FlockingDesc {
    double radius = 1.0;
    double separation = 1.0;
    double alignment = 1.0;
    double cohesion = 1.0;
    double maxSpeed = 2.0;
};

struct ParticleCollisionsDesc {
    double restitution = 1.0;
};

// Coulomb's law between charged particles runs whenever two particles carry a charge (like
// springs, it is implied by the objects); this optional entry only sets its constants.
struct CoulombDesc {
    double k = 8.9875517923e9;  // N·m²/C²
    double softening = 0.0;     // ε, as for newtonian_gravity
};

// Only the effects present here are simulated (absent = not constructed, costs nothing).
struct EffectsDesc {
    std::optional<GravityDesc> gravity;
    std::optional<DragDesc> drag;
    std::optional<NewtonianGravityDesc> newtonianGravity;
    std::optional<BuoyancyDesc> buoyancy;
    std::optional<WindDesc> wind;
    std::optional<FlockingDesc> flocking;
    std::optional<ParticleCollisionsDesc> particleCollisions;
    std::optional<CoulombDesc> coulomb;
};

struct ParticleDesc {
    std::string id;  // empty = default "p<index>"
    Point2 position{0.0, 0.0};
    Point2 velocity{0.0, 0.0};
    double mass = 1.0;
    double radius = 0.05;
    bool pinned = false;
    double restitution = 0.5;
    double friction = 0.2;
    double charge = 0.0;
};

// What every rigid kind's description holds (boxes, disks): its state at load and its
// material. Exactly one of mass and density is used: mass when set, else density times the
// shape's area.
struct RigidDesc {
    std::string id;  // empty = the kind's default (b0…, d0…)
    Point2 position{0.0, 0.0};
    double angle = 0.0;
    Point2 velocity{0.0, 0.0};
    double angularVelocity = 0.0;
    std::optional<double> mass;
    double density = 1.0;
    bool isStatic = false;
    double friction = 0.6;
    double restitution = 0.0;
};

struct BoxDesc : RigidDesc {
    Point2 size{1.0, 1.0};

    double resolvedMass() const { return mass ? *mass : density * size[0] * size[1]; }
    double momentOfInertia() const {
        return resolvedMass() * (size[0] * size[0] + size[1] * size[1]) / 12.0;
    }
};

// A rigid disk (CONTRACT §6): unlike a particle it turns, so it can roll. I = ½·m·r².
struct DiskDesc : RigidDesc {
    double radius = 0.5;

    double resolvedMass() const;
    double momentOfInertia() const { return 0.5 * resolvedMass() * radius * radius; }
};

// A rigid convex polygon (CONTRACT §6): 3 to 16 vertices in its own frame, either winding. Its
// mass and moment of inertia come from its area; its state is that of its centroid, which the
// reader moves its frame to (recentrePolygons).
struct PolygonDesc : RigidDesc {
    std::vector<Point2> vertices;

    double area() const;             // > 0 for either winding
    Point2 centroid() const;         // in its own frame
    double resolvedMass() const;     // mass, else density·area
    double momentOfInertia() const;  // about the centroid
};

struct PlaneDesc {
    std::string id;  // empty = default "plane<index>"
    Point2 point{0.0, 0.0};
    Point2 normal{0.0, 1.0};
    double friction = 0.5;
    double restitution = 0.5;
};

struct SpringDesc {
    std::string id;  // empty = default "s<index>"
    std::string a;
    std::optional<std::string> b;  // object id, or
    std::optional<Point2> anchor;  // a fixed world point
    Point2 aPoint{0.0, 0.0};       // attachment in a box's own frame
    Point2 bPoint{0.0, 0.0};
    double stiffness = 0.0;
    double damping = 0.0;
    std::optional<double> restLength;  // absent = initial distance
};

// A joint (CONTRACT §6): holds body a (required) to body b (absent = the fixed world). A body
// is a particle, box, disk, polygon or cloth node, by id; points on a body are in its own frame
// (a particle's is ignored), `anchor` is a world point at load time.
enum class JointType { Hinge, Rod, Rope, Weld, Pulley, Track };

struct JointMotorDesc {
    double speed = 0.0;      // rad/s: the joint angle's rate it drives toward
    double maxTorque = 0.0;  // N·m
};

struct TrackCircleDesc {
    Point2 center{0.0, 0.0};
    double radius = 1.0;
};

struct TrackLineDesc {
    Point2 point{0.0, 0.0};
    Point2 direction{1.0, 0.0};
};

struct JointDesc {
    std::string id;  // empty = default "j<index>"
    JointType type = JointType::Hinge;
    std::string a;
    std::optional<std::string> b;  // absent = the world
    Point2 aPoint{0.0, 0.0};
    Point2 bPoint{0.0, 0.0};
    // hinge: the pivot (required); rod, rope: the world end when b is absent (else a_point and
    // b_point give the ends).
    std::optional<Point2> anchor;
    std::optional<double> length;  // rod, rope: absent = the initial distance
    // hinge
    std::optional<std::array<double, 2>> limits;  // [lower, upper] of the joint angle (rad)
    std::optional<JointMotorDesc> motor;
    // pulley: |ground_a − p_a| + ratio·|ground_b − p_b| stays at its initial value
    Point2 groundA{0.0, 0.0};
    Point2 groundB{0.0, 0.0};
    double ratio = 1.0;
    // track: exactly one curve; a is a particle, b absent
    std::optional<TrackCircleDesc> circle;
    std::optional<TrackLineDesc> line;
};

struct ClothStiffnessDesc {
    double structural = 1000.0;
    double shear = 100.0;
    double bend = 10.0;
};

struct ClothDesc {
    std::string id;
    Point2 origin{0.0, 0.0};  // top-left corner
    Point2 size{1.0, 1.0};
    std::array<int, 2> resolution{10, 10};
    double mass = 1.0;  // total
    ClothStiffnessDesc stiffness;
    double damping = 0.0;
    double radius = 0.01;
    // "top", "top_corners", "left", "none", or an explicit list of [i, j] nodes.
    std::variant<std::string, std::vector<std::array<int, 2>>> pinned = std::string("top");
};

struct SceneDesc {
    // The newest format version this program reads; a scene is written as the oldest version
    // that holds it (formatVersion()), so scenes without version 2's kinds save unchanged.
    static constexpr int kFormatVersion = 2;
    int formatVersion() const {
        const bool contactModels = simulation.contactModel != ContactModel::Impulse ||
                                   simulation.contactStiffness ||
                                   simulation.contactDamping != 0.0 || simulation.sleep;
        return disks.empty() && polygons.empty() && joints.empty() && !contactModels &&
                       instruments.empty()
                   ? 1
                   : 2;
    }

    std::string name;
    std::string description;
    SimulationDesc simulation;
    EffectsDesc effects;
    std::vector<ParticleDesc> particles;
    std::vector<BoxDesc> boxes;
    std::vector<DiskDesc> disks;
    std::vector<PolygonDesc> polygons;
    std::vector<PlaneDesc> planes;
    std::vector<SpringDesc> springs;
    std::vector<ClothDesc> cloths;
    std::vector<JointDesc> joints;
    InstrumentsDesc instruments;  // version 2; what the app's instruments were (§7)
};

// Default ids by position (CONTRACT.md §1, §6): p0…, b0…, d0…, poly0…, plane0…, s0….
std::string particleId(const SceneDesc& scene, std::size_t index);
std::string boxId(const SceneDesc& scene, std::size_t index);
std::string diskId(const SceneDesc& scene, std::size_t index);
std::string polygonId(const SceneDesc& scene, std::size_t index);

// CONTRACT §6: a polygon's state is its centroid's. Moves each polygon whose vertices are not
// centred on its origin (beyond 1e-12 of its size) so that they are: vertices and the points
// springs and joints attach to shift by −c, its position by R(angle)·c, its velocity by
// ω × R(angle)·c.
// Call on a valid scene (the reader does, after validating).
void recentrePolygons(SceneDesc& scene);
std::string planeId(const SceneDesc& scene, std::size_t index);
std::string springId(const SceneDesc& scene, std::size_t index);
std::string clothNodeId(const std::string& clothId, int i, int j);
// Whether node (i, j) of the cloth is pinned by its `pinned` mode or list.
bool clothNodePinned(const ClothDesc& cloth, int i, int j);
std::string jointId(const SceneDesc& scene, std::size_t index);
// The scene's size as a step's work counts it: particles, cloth nodes and the springs they
// make (cloth springs included) and springs 1 each, rigid bodies and joints
// SceneLimits::kCostlyWorkUnits each. Times the sub-steps, at most kMaxSubstepWork.
long long stepWorkUnits(const SceneDesc& scene);
// "" when `substeps` sub-steps a step are within kMaxSubstepWork for the scene, else the reason.
std::string substepWorkProblem(const SceneDesc& scene, long long substeps);

// Sizes past which a scene is refused: far beyond what runs interactively on a laptop, and
// small enough that a hostile file cannot exhaust memory or hang the program. Issue #20: the
// largest scene of each kind loads, builds and takes its first step within 20 s and 3 GB on a
// two-core machine (measured in docs/robustness.md, "The largest scenes"); the old limits let
// a 1000 x 1000 cloth take 77 s and 5.6 GB for `phasebox-cli info` alone.
struct SceneLimits {
    static constexpr long long kMaxParticles = 250'000;  // cloth nodes included
    // Cloth nodes of all cloths together (128 x 128). A stiff cloth is the costliest scene per
    // node: its springs, the stability advisor's estimate and an implicit step's matrix grow
    // with the nodes, and an explicit adaptive method's steps with its stiffest mode too
    // (adaptive_euler's first step of a 256 x 256 cloth took 81 s, of 128 x 128 4.8 s).
    static constexpr long long kMaxClothNodes = 16'384;
    // Particles with a charge: Coulomb's law runs over every pair (2e8 pairs at the limit, 3.2 s
    // a step on two cores; 50,000 took 20 s and the particle limit's 250,000 would take minutes).
    static constexpr long long kMaxChargedParticles = 20'000;
    // Particles (cloth nodes included) under particle_collisions or flocking: piled at one
    // point every pair of them is near (the contact caps bound the contacts, not the pairs a
    // sweep looks at; flocking's neighbours are every boid). 20,000 at one point take their
    // first step in 2 s under either; 100,000 took 25 s and 250,000 over 100 s.
    static constexpr long long kMaxInteractingParticles = 20'000;
    static constexpr long long kMaxRigidBodies = 25'000;  // rigid bodies: boxes, disks, polygons
    static constexpr int kMaxPolygonVertices = 16;
    static constexpr long long kMaxSprings = 250'000;
    static constexpr long long kMaxPlanes = 1'000;
    static constexpr long long kMaxJoints = 250'000;
    static constexpr int kMaxSubsteps = 10'000;
    // Sub-steps times the scene's size (stepWorkUnits): a step's cost grows with both, and the
    // largest scenes take seconds for one sub-step, so a scene may not ask for both at once. The
    // units estimate time: a particle, spring or cloth node is one, a rigid body or joint
    // kCostlyWorkUnits. The bound is set so that the sub-steps the stability advisor asks for on
    // a mid-sized cloth are allowed; a bound on sub-steps alone would refuse the advisor's own
    // remedy or let the largest scenes run for minutes a step. The measured costs behind the
    // figure are in docs/robustness.md ("sizes and work bounds") and docs/performance.md.
    static constexpr long long kMaxSubstepWork = kMaxStepWork;
    static constexpr long long kCostlyWorkUnits = phasebox::kCostlyWorkUnits;
    static constexpr int kMaxNewtonIterations = 100;

    // Magnitudes (docs/scene-format.md, "Limits"). A classroom scene is metres, kilograms and
    // seconds; these bounds are a million times past that, yet keep every product the engine
    // forms (m·v², k·x², G·M·m/r) far inside the double range, so a typo such as 1e300 is
    // reported at its JSON path instead of surfacing as an infinity somewhere in a step.
    static constexpr double kMaxLength = 1e6;          // m: coordinates, sizes, radii, lengths
    static constexpr double kMaxSpeed = 1e6;           // m/s, and rad/s for angular velocities
    static constexpr double kMaxAngle = 1e6;           // rad
    static constexpr double kMaxAcceleration = 1e6;    // m/s²: gravity's g
    static constexpr double kMinMass = 1e-12;          // kg: below it 1/m leaves the safe range
    static constexpr double kMaxMass = 1e12;           // kg (kg/m² for densities)
    static constexpr double kMaxAttractorMass = 1e30;  // kg: fixed attractors may be stars
    static constexpr double kMinBoxSize = 1e-6;        // m: a box's moment of inertia ∝ size²
    static constexpr double kMinNormalLength = 1e-12;
    static constexpr double kMaxCoefficient = 1e12;  // stiffness, damping, drag, G, k, ρ, …
    static constexpr double kMaxCharge = 1e6;        // C
    static constexpr double kMaxDuration = 1e6;      // s: simulation.duration (11.6 days)
    // The adaptive integrators' local error tolerance (CONTRACT §1): below this a double
    // cannot meet it, and the step size collapses until the run "diverges".
    static constexpr double kMinTolerance = 1e-14;
};

// One problem found by validateScene(): a JSON-style path and what is wrong, e.g.
// {"boxes[3].size[0]", "must be > 0"}.
struct SceneIssue {
    std::string path;
    std::string message;
};

// Checks every value against the contract's ranges and every reference against the ids.
// Empty result = the scene can be built.
std::vector<SceneIssue> validateScene(const SceneDesc& scene);

// The polygon rule alone (CONTRACT §6: 3 to 16 finite vertices, convex, either winding, no
// three in a line, no repeats), its problem named at path or path[i]; empty = a valid outline.
// For editors that build an outline vertex by vertex.
std::vector<SceneIssue> validatePolygonVertices(const std::vector<Point2>& vertices,
                                                const std::string& path = "vertices");

}  // namespace phasebox
