#pragma once
// The scene format's schema: one table of fields per object kind, effect and settings section
// (key, type, range, unit, label, one-line description, and the member of the Desc struct that
// holds it). The JSON reader and writer (app/io), validateScene(), the property editor and the
// effects panel walk these tables, so a scene key is spelled in this header and nowhere else
// (the effects' keys are the names the effects give themselves, spelled in
// physics/core/EffectNames.h, which this header uses), and a new kind is one table here plus
// its physics and drawing.
//
// Defaults are not repeated here: they are the Desc structs' member initialisers (SceneDesc.h),
// reached through the same member pointers from a default-made Desc. Rules that tie fields together
// (a spring's ends, unique ids, a cloth's pinning, what a joint's type needs of its bodies) stay
// in validateScene(), which names them by these keys.

#include "physics/core/EffectNames.h"
#include "physics/scene/SceneDesc.h"

#include <iterator>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>

namespace phasebox::schema {

// The value of a scene file's "format" key.
inline constexpr std::string_view kFormatName = "phasebox-scene";

// Every key of scene format v1 (CONTRACT.md §1), spelled once.
namespace key {
// the top level
inline constexpr std::string_view format = "format";
inline constexpr std::string_view version = "version";
inline constexpr std::string_view name = "name";
inline constexpr std::string_view description = "description";
inline constexpr std::string_view simulation = "simulation";
inline constexpr std::string_view effects = "effects";
inline constexpr std::string_view particles = "particles";
inline constexpr std::string_view boxes = "boxes";
inline constexpr std::string_view disks = "disks";
inline constexpr std::string_view polygons = "polygons";
inline constexpr std::string_view vertices = "vertices";
inline constexpr std::string_view planes = "planes";
// the array that implies the spring effect, which is named after it
inline constexpr std::string_view springs = effectName::springs;
inline constexpr std::string_view cloths = "cloths";
inline constexpr std::string_view joints = "joints";
inline constexpr std::string_view instruments = "instruments";
// simulation, and its contact solver settings
inline constexpr std::string_view integrator = "integrator";
inline constexpr std::string_view dt = "dt";
inline constexpr std::string_view substeps = "substeps";
inline constexpr std::string_view tolerance = "tolerance";
inline constexpr std::string_view newtonIterations = "newton_iterations";
inline constexpr std::string_view duration = "duration";
inline constexpr std::string_view solver = "solver";
inline constexpr std::string_view contactModel = "contact_model";
inline constexpr std::string_view contactStiffness = "contact_stiffness";
inline constexpr std::string_view contactDamping = "contact_damping";
inline constexpr std::string_view sleep = "sleep";
inline constexpr std::string_view iterations = "iterations";
inline constexpr std::string_view relaxIterations = "relax_iterations";
inline constexpr std::string_view contactHertz = "contact_hertz";
inline constexpr std::string_view dampingRatio = "damping_ratio";
inline constexpr std::string_view pushOut = "push_out";
inline constexpr std::string_view restitutionThreshold = "restitution_threshold";
inline constexpr std::string_view speculativeDistance = "speculative_distance";
// effects: the names the engine's effects give themselves (physics/core/EffectNames.h), and
// particle_collisions, which switches on a contact pair kind rather than adding an effect
inline constexpr std::string_view gravity = effectName::gravity;
inline constexpr std::string_view drag = effectName::drag;
inline constexpr std::string_view newtonianGravity = effectName::newtonianGravity;
inline constexpr std::string_view buoyancy = effectName::buoyancy;
inline constexpr std::string_view wind = effectName::wind;
inline constexpr std::string_view flocking = effectName::flocking;
inline constexpr std::string_view particleCollisions = "particle_collisions";
inline constexpr std::string_view coulomb = effectName::coulomb;
// effect fields
inline constexpr std::string_view g = "g";
inline constexpr std::string_view linear = "linear";
inline constexpr std::string_view quadratic = "quadratic";
inline constexpr std::string_view angular = "angular";
inline constexpr std::string_view G = "G";
inline constexpr std::string_view attractors = "attractors";
inline constexpr std::string_view mutual = "mutual";
inline constexpr std::string_view softening = "softening";
inline constexpr std::string_view fluidDensity = "fluid_density";
inline constexpr std::string_view surfaceY = "surface_y";
inline constexpr std::string_view separation = "separation";
inline constexpr std::string_view alignment = "alignment";
inline constexpr std::string_view cohesion = "cohesion";
inline constexpr std::string_view maxSpeed = "max_speed";
inline constexpr std::string_view k = "k";
// object fields
inline constexpr std::string_view id = "id";
inline constexpr std::string_view position = "position";
inline constexpr std::string_view velocity = "velocity";
inline constexpr std::string_view mass = "mass";
inline constexpr std::string_view radius = "radius";
inline constexpr std::string_view pinned = "pinned";
inline constexpr std::string_view restitution = "restitution";
inline constexpr std::string_view friction = "friction";
inline constexpr std::string_view charge = "charge";
inline constexpr std::string_view size = "size";
inline constexpr std::string_view angle = "angle";
inline constexpr std::string_view angularVelocity = "angular_velocity";
inline constexpr std::string_view density = "density";
inline constexpr std::string_view isStatic = "static";
inline constexpr std::string_view point = "point";
inline constexpr std::string_view normal = "normal";
inline constexpr std::string_view a = "a";
inline constexpr std::string_view b = "b";
inline constexpr std::string_view anchor = "anchor";
inline constexpr std::string_view aPoint = "a_point";
inline constexpr std::string_view bPoint = "b_point";
inline constexpr std::string_view stiffness = "stiffness";
inline constexpr std::string_view damping = "damping";
inline constexpr std::string_view restLength = "rest_length";
inline constexpr std::string_view origin = "origin";
inline constexpr std::string_view resolution = "resolution";
inline constexpr std::string_view structural = "structural";
inline constexpr std::string_view shear = "shear";
inline constexpr std::string_view bend = "bend";
// joint fields (CONTRACT §6)
inline constexpr std::string_view type = "type";
inline constexpr std::string_view length = "length";
inline constexpr std::string_view limits = "limits";
inline constexpr std::string_view motor = "motor";
inline constexpr std::string_view speed = "speed";
inline constexpr std::string_view maxTorque = "max_torque";
inline constexpr std::string_view groundA = "ground_a";
inline constexpr std::string_view groundB = "ground_b";
inline constexpr std::string_view ratio = "ratio";
inline constexpr std::string_view circle = "circle";
inline constexpr std::string_view center = "center";
inline constexpr std::string_view line = "line";
inline constexpr std::string_view direction = "direction";
// instruments (CONTRACT §7)
inline constexpr std::string_view probes = "probes";
inline constexpr std::string_view graphs = "graphs";
inline constexpr std::string_view x = "x";
inline constexpr std::string_view y = "y";
inline constexpr std::string_view timers = "timers";
inline constexpr std::string_view stopwatch = "stopwatch";
inline constexpr std::string_view rulers = "rulers";
inline constexpr std::string_view protractors = "protractors";
inline constexpr std::string_view ends = "ends";
inline constexpr std::string_view freeBody = "free_body";
inline constexpr std::string_view view = "view";
inline constexpr std::string_view width = "width";
inline constexpr std::string_view plots = "plots";
}  // namespace key

// The values of a joint's "type", in JointType's order (a Choice field's choices).
inline constexpr std::string_view kJointTypeNames[] = {"hinge", "rod",    "rope",
                                                       "weld",  "pulley", "track"};
static_assert(std::size(kJointTypeNames) == static_cast<std::size_t>(JointType::Track) + 1);

// How a value is written in JSON. Point, Size and Grid are pairs; the name says what the two
// numbers are in messages ([x, y], [w, h], [nx, ny]) and in the property editor.
enum class Type {
    Number,
    Integer,
    Bool,
    String,
    IdRef,        // the id of another object, a string
    Point,        // [x, y]
    Size,         // [w, h]
    Grid,         // [nx, ny], integers
    Choice,       // a string naming one of the field's choices, held as an enum
    Interval,     // [lower, upper], lower <= upper (a hinge's limits)
    Object,       // a nested object with its own table; in std::optional, absent until given
    ObjectArray,  // an array of objects with their own table
    Pinning,      // a cloth's pinning: a mode name or a list of [i, j] nodes
    NumberMap,    // an object of numbers by name (the contact solver's settings)
    PointList,    // an array of [x, y] points (a polygon's vertices)
};

// A value's range, checked by validateScene() with these messages (pairs: each number):
//   Positive      "must be > 0", then "must be <= max", then "must be >= min" when min > 0
//   NonNegative   "must be >= 0", then "must be <= max"
//   Symmetric     "must be between -max and max"
//   UnitInterval  "must be between 0 and 1"
//   PositiveUpTo  "must be > 0 and <= max" in one message
//   IntegerAtLeast "must be an integer >= min", then "must be <= max"
//   IntegerBetween "must be an integer between min and max"
// Every number must be finite first ("must be a finite number").
enum class Bound {
    None,
    Positive,
    NonNegative,
    Symmetric,
    UnitInterval,
    PositiveUpTo,
    IntegerAtLeast,
    IntegerBetween
};

struct Range {
    Bound bound = Bound::None;
    double max = std::numeric_limits<double>::infinity();
    double min = 0.0;

    // The smallest value allowed, and whether it is itself excluded (> rather than >=).
    double lowest() const;
    bool lowestExcluded() const;
};

constexpr Range positive(double max, double min = 0.0) {
    return {Bound::Positive, max, min};
}
constexpr Range nonNegative(double max) {
    return {Bound::NonNegative, max, 0.0};
}
constexpr Range symmetric(double max) {
    return {Bound::Symmetric, max, 0.0};
}
constexpr Range unitInterval() {
    return {Bound::UnitInterval, 1.0, 0.0};
}

// The editors' view of a field, where it differs from the format's: a spin box range that fits
// the classroom (the format's bounds are a million times past it), the decimals shown, and
// whether an edit places or launches the object (it then restarts from its setup). The property
// editor shows an object's fields with decimals >= 0; the parameters panel lays out the
// simulation settings itself and takes their ranges from here.
struct Editor {
    double min = 0.0;
    double max = 0.0;
    int decimals = -1;
    bool movesObject = false;
    // Shown after the fields of rank 0 (a spring's anchor after its stiffness).
    int rank = 0;
    // A direction (Type::Point) edited as one angle, the tilt of the surface it is normal to
    // (0: normal up, a floor; π/2: a wall facing −x): two components could be made zero.
    bool tilt = false;
};

enum class Need { Optional, Required };

// Checks that involve more than the field's own range, done by validateScene().
enum class Rule { None, NonZeroDirection, KnownIntegrator };

using Pinning = std::variant<std::string, std::vector<std::array<int, 2>>>;

// Where a field lives in its Desc struct.
template <typename D>
using Member = std::variant<double D::*, int D::*, bool D::*, std::string D::*, Point2 D::*,
                            std::array<int, 2> D::*, std::optional<double> D::*,
                            std::optional<std::string> D::*, std::optional<Point2> D::*,
                            ClothStiffnessDesc D::*, std::vector<AttractorDesc> D::*, Pinning D::*,
                            std::map<std::string, double> D::*, std::vector<Point2> D::*,
                            JointType D::*, ContactModel D::*, std::optional<JointMotorDesc> D::*,
                            std::optional<TrackCircleDesc> D::*, std::optional<TrackLineDesc> D::*>;

template <typename D>
struct Field {
    std::string_view key{};
    Type type = Type::Number;
    Member<D> member{};
    Range range{};
    std::string_view unit{};         // "kg", "m/s", … ; empty for plain numbers
    std::string_view label{};        // for people: "Mass"
    std::string_view description{};  // one line
    Need need = Need::Optional;
    Editor editor{};
    // A field given only when this holds (the writer omits, the validator and editor skip it
    // otherwise); fields held in std::optional are present when set, ids when not empty.
    bool (*present)(const D&) = nullptr;
    // The key this one may not be given together with ("give mass or density, not both").
    std::string_view exclusiveWith{};
    Rule rule = Rule::None;
    // Choice fields: the names in the file, the enum's values in order (0, 1, …).
    std::span<const std::string_view> choices{};
    // A field that only some objects of its kind use (a joint's fields by its type): whether d
    // uses it, which may look at the fields before it in the table. One that d does not use is
    // neither written nor checked, nor required when Need::Required; given in a file anyway,
    // it is refused as "is only for " + usedBy, since dropping it would lose what its author
    // meant.
    bool (*uses)(const D&) = nullptr;
    std::string_view usedBy{};
};

// One object kind, effect or section: its key in the file and its fields in the file's order.
template <typename D>
struct Table {
    std::string_view key;
    std::string_view description;
    std::span<const Field<D>> fields;
    // Effects only: run because of what the scene holds (the entry sets only constants), so not
    // something a user adds from the effects menu.
    bool implied = false;
    // The format version that brought the kind (CONTRACT §6): the writer leaves out an empty
    // array of a kind newer than version 1, so that older scenes save unchanged.
    int sinceVersion = 1;
};

// The contact solver's settings (simulation.solver): numbers by name, each with its range;
// other names are kept so that they round-trip.
struct SolverSetting {
    std::string_view key;
    Range range;
    std::string_view description;
};
std::span<const SolverSetting> solverSettings();

// The tables. table<D>() picks the one for D.
const Table<SimulationDesc>& tableOf(std::type_identity<SimulationDesc>);
const Table<GravityDesc>& tableOf(std::type_identity<GravityDesc>);
const Table<DragDesc>& tableOf(std::type_identity<DragDesc>);
const Table<NewtonianGravityDesc>& tableOf(std::type_identity<NewtonianGravityDesc>);
const Table<AttractorDesc>& tableOf(std::type_identity<AttractorDesc>);
const Table<BuoyancyDesc>& tableOf(std::type_identity<BuoyancyDesc>);
const Table<WindDesc>& tableOf(std::type_identity<WindDesc>);
const Table<FlockingDesc>& tableOf(std::type_identity<FlockingDesc>);
const Table<ParticleCollisionsDesc>& tableOf(std::type_identity<ParticleCollisionsDesc>);
const Table<CoulombDesc>& tableOf(std::type_identity<CoulombDesc>);
const Table<ParticleDesc>& tableOf(std::type_identity<ParticleDesc>);
const Table<BoxDesc>& tableOf(std::type_identity<BoxDesc>);
const Table<DiskDesc>& tableOf(std::type_identity<DiskDesc>);
const Table<PolygonDesc>& tableOf(std::type_identity<PolygonDesc>);
const Table<PlaneDesc>& tableOf(std::type_identity<PlaneDesc>);
const Table<SpringDesc>& tableOf(std::type_identity<SpringDesc>);
const Table<ClothDesc>& tableOf(std::type_identity<ClothDesc>);
const Table<ClothStiffnessDesc>& tableOf(std::type_identity<ClothStiffnessDesc>);
const Table<JointDesc>& tableOf(std::type_identity<JointDesc>);
const Table<JointMotorDesc>& tableOf(std::type_identity<JointMotorDesc>);
const Table<TrackCircleDesc>& tableOf(std::type_identity<TrackCircleDesc>);
const Table<TrackLineDesc>& tableOf(std::type_identity<TrackLineDesc>);

// The simulation setting with this key (key::dt, …): its range, which World and the commands
// check too, and its editor's limits.
const Field<SimulationDesc>& simulationField(std::string_view key);

template <typename D>
const Table<D>& table() {
    return tableOf(std::type_identity<D>{});
}

// A value that is a nested object (Type::Object): one with a table of its own, such as a
// cloth's stiffness, or one in std::optional, such as a hinge's motor.
template <typename V>
concept Described = requires {
    tableOf(std::type_identity<V>{});
};
template <typename V>
struct IsOptional : std::false_type {};
template <typename V>
struct IsOptional<std::optional<V>> : std::true_type {};
template <typename V>
concept OptionalDescribed = IsOptional<V>::value && Described<typename V::value_type>;

// The effects in the contract's order: fn(table<XDesc>(), &EffectsDesc::x).
template <typename Fn>
void forEachEffect(Fn&& fn) {
    fn(table<GravityDesc>(), &EffectsDesc::gravity);
    fn(table<DragDesc>(), &EffectsDesc::drag);
    fn(table<NewtonianGravityDesc>(), &EffectsDesc::newtonianGravity);
    fn(table<BuoyancyDesc>(), &EffectsDesc::buoyancy);
    fn(table<WindDesc>(), &EffectsDesc::wind);
    fn(table<FlockingDesc>(), &EffectsDesc::flocking);
    fn(table<ParticleCollisionsDesc>(), &EffectsDesc::particleCollisions);
    fn(table<CoulombDesc>(), &EffectsDesc::coulomb);
}

// The object arrays in the file's order: fn(table<XDesc>(), &SceneDesc::xs).
template <typename Fn>
void forEachObjectKind(Fn&& fn) {
    fn(table<ParticleDesc>(), &SceneDesc::particles);
    fn(table<BoxDesc>(), &SceneDesc::boxes);
    fn(table<DiskDesc>(), &SceneDesc::disks);
    fn(table<PolygonDesc>(), &SceneDesc::polygons);
    fn(table<PlaneDesc>(), &SceneDesc::planes);
    fn(table<SpringDesc>(), &SceneDesc::springs);
    fn(table<ClothDesc>(), &SceneDesc::cloths);
    fn(table<JointDesc>(), &SceneDesc::joints);
}

// The keys of the top level, and of the effects object, in the file's order.
std::span<const std::string_view> topKeys();
std::span<const std::string_view> effectKeys();

// A table's keys, for telling a misspelt key from an unknown one.
template <typename D>
std::vector<std::string_view> keysOf(const Table<D>& t) {
    std::vector<std::string_view> keys;
    for (const Field<D>& f : t.fields) keys.push_back(f.key);
    return keys;
}

// Whether field f is given in d (see Field::present and Field::uses).
template <typename D>
bool isPresent(const Field<D>& f, const D& d) {
    if (f.uses && !f.uses(d)) return false;
    if (f.present) return f.present(d);
    return std::visit(
        [&]<typename T>(T D::*m) {
            if constexpr (requires { (d.*m).has_value(); })
                return (d.*m).has_value();
            else
                return true;
        },
        f.member);
}

}  // namespace phasebox::schema
