#include "physics/scene/SceneSchema.h"

#include "physics/scene/SchemaFields.h"

namespace phasebox::schema {

namespace {

using namespace fields;

// ---- simulation ----

const Field<SimulationDesc> kSimulation[] = {
    {.key = key::integrator,
     .type = T::String,
     .member = &SimulationDesc::integrator,
     .label = "Integrator",
     .description = "one of the registered integrators (CONTRACT §3)",
     .rule = Rule::KnownIntegrator},
    {.key = key::dt,
     .type = T::Number,
     .member = &SimulationDesc::dt,
     .range = {Bound::PositiveUpTo, 1.0, 0.0},
     .unit = "s",
     .label = "Time step",
     .description = "the frame step: the time one step advances"},
    {.key = key::substeps,
     .type = T::Integer,
     .member = &SimulationDesc::substeps,
     .range = {Bound::IntegerAtLeast, L::kMaxSubsteps, 1.0},
     .label = "Sub-steps",
     .description = "each step is split into this many equal sub-steps"},
    {.key = key::tolerance,
     .type = T::Number,
     .member = &SimulationDesc::tolerance,
     .range = positive(L::kMaxCoefficient, L::kMinTolerance),
     .label = "Tolerance",
     .description = "local error tolerance of the adaptive integrators"},
    {.key = key::newtonIterations,
     .type = T::Integer,
     .member = &SimulationDesc::newtonIterations,
     .range = {Bound::IntegerAtLeast, L::kMaxNewtonIterations, 1.0},
     .label = "Newton iterations",
     .description = "Newton iterations of implicit_euler (1 = the linearised step)"},
    {.key = key::duration,
     .type = T::Number,
     .member = &SimulationDesc::duration,
     .range = positive(L::kMaxDuration),
     .unit = "s",
     .label = "Duration",
     .description = "default run length of phasebox-cli run"},
    {.key = key::solver,
     .type = T::NumberMap,
     .member = &SimulationDesc::solver,
     .label = "Contact solver",
     .description = "contact solver settings, all optional",
     .present = [](const SimulationDesc& s) { return !s.solver.empty(); }},
    {.key = key::contactModel,
     .type = T::Choice,
     .member = &SimulationDesc::contactModel,
     .label = "Contact model",
     .description = "how contacts respond: impulse, penalty or kinematic",
     .present = [](const SimulationDesc& s) { return s.contactModel != ContactModel::Impulse; },
     .choices = kContactModelNames},
    {.key = key::contactStiffness,
     .type = T::Number,
     .member = &SimulationDesc::contactStiffness,
     .range = positive(L::kMaxCoefficient),
     .unit = "N/m",
     .label = "Contact stiffness",
     .description = "penalty stiffness per contact point; absent: the lightest body gets "
                    "omega*h = 0.5"},
    {.key = key::contactDamping,
     .type = T::Number,
     .member = &SimulationDesc::contactDamping,
     .range = nonNegative(L::kMaxCoefficient),
     .unit = "N s/m",
     .label = "Contact damping",
     .description = "penalty damping per contact point",
     .present = [](const SimulationDesc& s) { return s.contactDamping != 0.0; }},
};

const SolverSetting kSolverSettings[] = {
    {key::substeps,
     {Bound::IntegerBetween, 64.0, 0.0},
     "inner sub-steps of the contact solver per step; 0: the solver's choice"},
    {key::iterations,
     {Bound::IntegerBetween, 1000.0, 0.0},
     "soft velocity iterations per inner sub-step"},
    {key::relaxIterations,
     {Bound::IntegerBetween, 1000.0, 0.0},
     "relax iterations per inner sub-step"},
    {key::contactHertz, positive(L::kMaxCoefficient), "stiffness of the soft contact, in Hz"},
    {key::dampingRatio, nonNegative(L::kMaxCoefficient), "damping ratio of the soft contact"},
    {key::pushOut, positive(L::kMaxCoefficient), "largest speed that pushes overlaps apart"},
    {key::restitutionThreshold, nonNegative(L::kMaxCoefficient),
     "approach speed below which contacts do not bounce"},
    {key::speculativeDistance, nonNegative(L::kMaxCoefficient),
     "distance at which contacts are created before touching"},
};

// ---- effects ----

const Field<GravityDesc> kGravity[] = {
    {.key = key::g,
     .type = T::Point,
     .member = &GravityDesc::g,
     .range = symmetric(L::kMaxAcceleration),
     .unit = "m/s\u00b2",
     .label = "g",
     .description = "the acceleration of gravity"},
};

const Field<DragDesc> kDrag[] = {
    {.key = key::linear,
     .type = T::Number,
     .member = &DragDesc::linear,
     .range = kCoefficient,
     .unit = "N\u00b7s/m",
     .label = "Linear b",
     .description = "F = \u2212b\u00b7v"},
    {.key = key::quadratic,
     .type = T::Number,
     .member = &DragDesc::quadratic,
     .range = kCoefficient,
     .unit = "N\u00b7s\u00b2/m\u00b2",
     .label = "Quadratic c",
     .description = "F = \u2212c\u00b7\u2016v\u2016\u00b7v"},
    {.key = key::angular,
     .type = T::Number,
     .member = &DragDesc::angular,
     .range = kCoefficient,
     .unit = "N\u00b7m\u00b7s",
     .label = "Angular \u03b2",
     .description = "torque \u2212\u03b2\u00b7\u03c9 on boxes"},
};

const Field<AttractorDesc> kAttractor[] = {
    {.key = key::position,
     .type = T::Point,
     .member = &AttractorDesc::position,
     .range = kLength,
     .unit = "m",
     .label = "Position",
     .description = "a fixed point that attracts"},
    {.key = key::mass,
     .type = T::Number,
     .member = &AttractorDesc::mass,
     .range = nonNegative(L::kMaxAttractorMass),
     .unit = "kg",
     .label = "Mass",
     .description = "the attractor's mass M"},
};

const Field<NewtonianGravityDesc> kNewtonianGravity[] = {
    {.key = key::G,
     .type = T::Number,
     .member = &NewtonianGravityDesc::G,
     .range = kCoefficient,
     .unit = "N\u00b7m\u00b2/kg\u00b2",
     .label = "G",
     .description = "the gravitational constant"},
    {.key = key::attractors,
     .type = T::ObjectArray,
     .member = &NewtonianGravityDesc::attractors,
     .label = "Attractors",
     .description = "fixed points that attract every particle"},
    {.key = key::mutual,
     .type = T::Bool,
     .member = &NewtonianGravityDesc::mutual,
     .label = "Mutual",
     .description = "also between every pair of dynamic particles"},
    {.key = key::softening,
     .type = T::Number,
     .member = &NewtonianGravityDesc::softening,
     .range = nonNegative(L::kMaxLength),
     .unit = "m",
     .label = "Softening \u03b5",
     .description = "F \u221d 1/(\u2016r\u2016\u00b2+\u03b5\u00b2)"},
};

const Field<BuoyancyDesc> kBuoyancy[] = {
    {.key = key::fluidDensity,
     .type = T::Number,
     .member = &BuoyancyDesc::fluidDensity,
     .range = positive(L::kMaxMass),
     .unit = "kg/m\u00b2",
     .label = "Fluid density \u03c1",
     .description = "density of the fluid below the surface"},
    {.key = key::surfaceY,
     .type = T::Number,
     .member = &BuoyancyDesc::surfaceY,
     .range = symmetric(L::kMaxLength),
     .unit = "m",
     .label = "Surface y",
     .description = "height of the fluid's surface"},
    {.key = key::drag,
     .type = T::Number,
     .member = &BuoyancyDesc::drag,
     .range = kCoefficient,
     .unit = "N\u00b7s/m",
     .label = "Drag b_f",
     .description = "extra linear drag while submerged"},
};

const Field<WindDesc> kWind[] = {
    {.key = key::velocity,
     .type = T::Point,
     .member = &WindDesc::velocity,
     .range = kSpeed,
     .unit = "m/s",
     .label = "Velocity w",
     .description = "the wind's velocity"},
    {.key = key::drag,
     .type = T::Number,
     .member = &WindDesc::drag,
     .range = kCoefficient,
     .unit = "N\u00b7s/m",
     .label = "Drag b",
     .description = "F = b\u00b7(w \u2212 v)"},
};

const Field<FlockingDesc> kFlocking[] = {
    {.key = key::radius,
     .type = T::Number,
     .member = &FlockingDesc::radius,
     .range = positive(L::kMaxLength),
     .unit = "m",
     .label = "Radius",
     .description = "particles closer than this steer together"},
    {.key = key::separation,
     .type = T::Number,
     .member = &FlockingDesc::separation,
     .range = kCoefficient,
     .label = "Separation",
     .description = "weight of steering apart"},
    {.key = key::alignment,
     .type = T::Number,
     .member = &FlockingDesc::alignment,
     .range = kCoefficient,
     .label = "Alignment",
     .description = "weight of matching velocity"},
    {.key = key::cohesion,
     .type = T::Number,
     .member = &FlockingDesc::cohesion,
     .range = kCoefficient,
     .label = "Cohesion",
     .description = "weight of steering to the centre"},
    {.key = key::maxSpeed,
     .type = T::Number,
     .member = &FlockingDesc::maxSpeed,
     .range = positive(L::kMaxSpeed),
     .unit = "m/s",
     .label = "Maximum speed",
     .description = "the speed steering aims for at most"},
};

const Field<ParticleCollisionsDesc> kParticleCollisions[] = {
    {.key = key::restitution,
     .type = T::Number,
     .member = &ParticleCollisionsDesc::restitution,
     .range = unitInterval(),
     .label = "Restitution e",
     .description = "bounce of particle-particle contacts"},
};

const Field<CoulombDesc> kCoulomb[] = {
    {.key = key::k,
     .type = T::Number,
     .member = &CoulombDesc::k,
     .range = kCoefficient,
     .unit = "N\u00b7m\u00b2/C\u00b2",
     .label = "k",
     .description = "Coulomb's constant"},
    {.key = key::softening,
     .type = T::Number,
     .member = &CoulombDesc::softening,
     .range = nonNegative(L::kMaxLength),
     .unit = "m",
     .label = "Softening \u03b5",
     .description = "as for newtonian_gravity"},
};

// ---- objects ----

// Where a body starts: required, in metres.
template <typename D>
Field<D> positionField(std::string_view description) {
    return {.key = key::position,
            .type = T::Point,
            .member = &D::position,
            .range = kLength,
            .unit = "m",
            .label = "Position",
            .description = description,
            .need = Need::Required,
            .editor = kPlaces};
}

const Field<ParticleDesc> kParticle[] = {
    idField<ParticleDesc>("unique across the scene; default p0, p1, \u2026 by position"),
    positionField<ParticleDesc>("where the particle starts"),
    {.key = key::velocity,
     .type = T::Point,
     .member = &ParticleDesc::velocity,
     .range = kSpeed,
     .unit = "m/s",
     .label = "Velocity",
     .description = "its initial velocity",
     .editor = kPlaces},
    {.key = key::mass,
     .type = T::Number,
     .member = &ParticleDesc::mass,
     .range = kMass,
     .unit = "kg",
     .label = "Mass",
     .description = "its mass",
     .editor = kMassEditor},
    {.key = key::radius,
     .type = T::Number,
     .member = &ParticleDesc::radius,
     .range = nonNegative(L::kMaxLength),
     .unit = "m",
     .label = "Radius",
     .description = "radius of its disk; 0 = a point that touches nothing",
     .editor = {0.0, kFar, 3}},
    {.key = key::pinned,
     .type = T::Bool,
     .member = &ParticleDesc::pinned,
     .label = "Pinned",
     .description = "held in place",
     .editor = kSwitch},
    restitutionField(&ParticleDesc::restitution),
    frictionField(&ParticleDesc::friction),
    {.key = key::charge,
     .type = T::Number,
     .member = &ParticleDesc::charge,
     .range = symmetric(L::kMaxCharge),
     .unit = "C",
     .label = "Charge",
     .description = "electric charge (Coulomb's law between charged particles)",
     .editor = {-kLarge, kLarge, 3}},
};

// The fields every rigid body shares (boxes, disks, polygons), one helper each.
template <typename D>
Field<D> angleField() {
    return {.key = key::angle,
            .type = T::Number,
            .member = &D::angle,
            .range = symmetric(L::kMaxAngle),
            .unit = "rad",
            .label = "Angle",
            .description = "its initial angle, counter-clockwise",
            .editor = kPlaces};
}
template <typename D>
Field<D> velocityField() {
    return {.key = key::velocity,
            .type = T::Point,
            .member = &D::velocity,
            .range = kSpeed,
            .unit = "m/s",
            .label = "Velocity",
            .description = "its initial velocity",
            .editor = kPlaces};
}
template <typename D>
Field<D> angularVelocityField() {
    return {.key = key::angularVelocity,
            .type = T::Number,
            .member = &D::angularVelocity,
            .range = kSpeed,
            .unit = "rad/s",
            .label = "Angular velocity \u03c9",
            .description = "its initial angular velocity",
            .editor = kPlaces};
}
// Which of mass and density the author gave is part of the scene: a file that states a density
// still states one after the body is resized and saved.
template <typename D>
Field<D> massField(std::string_view description) {
    return {.key = key::mass,
            .type = T::Number,
            .member = &D::mass,
            .range = kMass,
            .unit = "kg",
            .label = "Mass",
            .description = description,
            .editor = kMassEditor,
            .exclusiveWith = key::density};
}
template <typename D>
Field<D> densityField() {
    return {.key = key::density,
            .type = T::Number,
            .member = &D::density,
            .range = kMass,
            .unit = "kg/m\u00b2",
            .label = "Density",
            .description = "mass per area, when no mass is given",
            .present = [](const D& d) { return !d.mass; }};
}
template <typename D>
Field<D> staticField() {
    return {.key = key::isStatic,
            .type = T::Bool,
            .member = &D::isStatic,
            .label = "Static",
            .description = "never moves",
            .editor = kSwitch};
}

const Field<BoxDesc> kBox[] = {
    idField<BoxDesc>("unique across the scene; default b0, b1, \u2026 by position"),
    positionField<BoxDesc>("where its centre starts"),
    {.key = key::size,
     .type = T::Size,
     .member = &BoxDesc::size,
     .range = positive(L::kMaxLength, L::kMinBoxSize),
     .unit = "m",
     .label = "Size",
     .description = "width and height",
     .need = Need::Required,
     .editor = {0.001, kFar, 3}},
    angleField<BoxDesc>(),
    velocityField<BoxDesc>(),
    angularVelocityField<BoxDesc>(),
    massField<BoxDesc>("its mass; absent = density \u00b7 w \u00b7 h"),
    densityField<BoxDesc>(),
    staticField<BoxDesc>(),
    frictionField<BoxDesc>(&BoxDesc::friction),
    restitutionField<BoxDesc>(&BoxDesc::restitution),
};

const Field<DiskDesc> kDisk[] = {
    idField<DiskDesc>("unique across the scene; default d0, d1, \u2026 by position"),
    positionField<DiskDesc>("where its centre starts"),
    {.key = key::radius,
     .type = T::Number,
     .member = &DiskDesc::radius,
     .range = positive(L::kMaxLength, L::kMinBoxSize),
     .unit = "m",
     .label = "Radius",
     .description = "its radius",
     .need = Need::Required,
     .editor = {0.001, kFar, 3}},
    angleField<DiskDesc>(),
    velocityField<DiskDesc>(),
    angularVelocityField<DiskDesc>(),
    massField<DiskDesc>("its mass; absent = density \u00b7 \u03c0 \u00b7 r\u00b2"),
    densityField<DiskDesc>(),
    staticField<DiskDesc>(),
    frictionField<DiskDesc>(&DiskDesc::friction),
    restitutionField<DiskDesc>(&DiskDesc::restitution),
};

const Field<PolygonDesc> kPolygon[] = {
    idField<PolygonDesc>("unique across the scene; default poly0, poly1, \u2026 by position"),
    positionField<PolygonDesc>(
        "where its centroid starts (the origin of its vertices before loading)"),
    {.key = key::vertices,
     .type = T::PointList,
     .member = &PolygonDesc::vertices,
     .range = kLength,
     .unit = "m",
     .label = "Vertices",
     .description = "3 to 16 corners in its own frame, convex, either winding",
     .need = Need::Required},
    angleField<PolygonDesc>(),
    velocityField<PolygonDesc>(),
    angularVelocityField<PolygonDesc>(),
    massField<PolygonDesc>("its mass; absent = density \u00b7 area"),
    densityField<PolygonDesc>(),
    staticField<PolygonDesc>(),
    frictionField<PolygonDesc>(&PolygonDesc::friction),
    restitutionField<PolygonDesc>(&PolygonDesc::restitution),
};

const Field<PlaneDesc> kPlane[] = {
    idField<PlaneDesc>("unique across the scene; default plane0, plane1, \u2026 by position"),
    {.key = key::point,
     .type = T::Point,
     .member = &PlaneDesc::point,
     .range = kLength,
     .unit = "m",
     .label = "Point",
     .description = "a point of the surface",
     .need = Need::Required,
     .editor = {-kFar, kFar, 3}},
    // The editor shows the normal as the surface's tilt (PropertyTable).
    {.key = key::normal,
     .type = T::Point,
     .member = &PlaneDesc::normal,
     .range = kLength,
     .label = "Normal",
     .description = "points out of the solid side; normalised on load",
     .need = Need::Required,
     .rule = Rule::NonZeroDirection},
    frictionField(&PlaneDesc::friction),
    restitutionField(&PlaneDesc::restitution),
};

const Field<SpringDesc> kSpring[] = {
    idField<SpringDesc>("unique across the scene; default s0, s1, \u2026 by position"),
    {.key = key::a,
     .type = T::IdRef,
     .member = &SpringDesc::a,
     .label = "End a",
     .description = "the object at one end",
     .need = Need::Required},
    {.key = key::b,
     .type = T::IdRef,
     .member = &SpringDesc::b,
     .label = "End b",
     .description = "the object at the other end, or give anchor"},
    {.key = key::anchor,
     .type = T::Point,
     .member = &SpringDesc::anchor,
     .range = kLength,
     .unit = "m",
     .label = "Anchor",
     .description = "a fixed world point as the other end",
     .editor = {-kFar, kFar, 3, false, 1}},
    {.key = key::aPoint,
     .type = T::Point,
     .member = &SpringDesc::aPoint,
     .range = kLength,
     .unit = "m",
     .label = "Point on a",
     .description = "attachment in a's own frame"},
    {.key = key::bPoint,
     .type = T::Point,
     .member = &SpringDesc::bPoint,
     .range = kLength,
     .unit = "m",
     .label = "Point on b",
     .description = "attachment in b's own frame"},
    {.key = key::stiffness,
     .type = T::Number,
     .member = &SpringDesc::stiffness,
     .range = positive(L::kMaxCoefficient),
     .unit = "N/m",
     .label = "Stiffness k",
     .description = "force per metre of stretch",
     .need = Need::Required,
     .editor = {0.001, kLarge, 3}},
    {.key = key::damping,
     .type = T::Number,
     .member = &SpringDesc::damping,
     .range = kCoefficient,
     .unit = "N\u00b7s/m",
     .label = "Damping c",
     .description = "damping along the spring",
     .editor = {0.0, kLarge, 3}},
    {.key = key::restLength,
     .type = T::Number,
     .member = &SpringDesc::restLength,
     .range = nonNegative(L::kMaxLength),
     .unit = "m",
     .label = "Rest length",
     .description = "length without force; absent = the initial distance",
     .editor = {0.0, kFar, 3}},
};

const Field<ClothStiffnessDesc> kClothStiffness[] = {
    {.key = key::structural,
     .type = T::Number,
     .member = &ClothStiffnessDesc::structural,
     .range = kCoefficient,
     .unit = "N/m",
     .label = "Structural stiffness",
     .description = "springs between neighbours in a row or column",
     .editor = {0.0, kLarge, 2}},
    {.key = key::shear,
     .type = T::Number,
     .member = &ClothStiffnessDesc::shear,
     .range = kCoefficient,
     .unit = "N/m",
     .label = "Shear stiffness",
     .description = "springs along the diagonals",
     .editor = {0.0, kLarge, 2}},
    {.key = key::bend,
     .type = T::Number,
     .member = &ClothStiffnessDesc::bend,
     .range = kCoefficient,
     .unit = "N/m",
     .label = "Bend stiffness",
     .description = "springs that skip a node",
     .editor = {0.0, kLarge, 2}},
};

const Field<ClothDesc> kCloth[] = {
    {.key = key::id,
     .type = T::String,
     .member = &ClothDesc::id,
     .label = "Id",
     .description = "names the cloth; node ids are ID[i,j]",
     .need = Need::Required},
    {.key = key::origin,
     .type = T::Point,
     .member = &ClothDesc::origin,
     .range = kLength,
     .unit = "m",
     .label = "Origin",
     .description = "the top-left corner",
     .editor = kPlaces},
    {.key = key::size,
     .type = T::Size,
     .member = &ClothDesc::size,
     .range = positive(L::kMaxLength),
     .unit = "m",
     .label = "Size",
     .description = "width and height",
     .editor = {0.001, kFar, 3, true}},
    {.key = key::resolution,
     .type = T::Grid,
     .member = &ClothDesc::resolution,
     .range = {Bound::IntegerAtLeast, std::numeric_limits<double>::infinity(), 2.0},
     .label = "Resolution",
     .description = "nodes across and down",
     .editor = {2.0, 128.0, 0, true}},
    {.key = key::mass,
     .type = T::Number,
     .member = &ClothDesc::mass,
     .range = kMass,
     .unit = "kg",
     .label = "Mass (total)",
     .description = "the whole cloth's mass",
     .editor = kMassEditor},
    {.key = key::stiffness,
     .type = T::Object,
     .member = &ClothDesc::stiffness,
     .label = "Stiffness",
     .description = "of its three kinds of springs"},
    {.key = key::damping,
     .type = T::Number,
     .member = &ClothDesc::damping,
     .range = kCoefficient,
     .unit = "N\u00b7s/m",
     .label = "Damping",
     .description = "damping of its springs",
     .editor = {0.0, kLarge, 3}},
    {.key = key::radius,
     .type = T::Number,
     .member = &ClothDesc::radius,
     .range = nonNegative(L::kMaxLength),
     .unit = "m",
     .label = "Node radius",
     .description = "radius of each node's disk",
     .editor = {0.0, kFar, 3}},
    {.key = key::pinned,
     .type = T::Pinning,
     .member = &ClothDesc::pinned,
     .label = "Pinned",
     .description = "top, top_corners, left, none, or a list of [i, j] nodes"},
};

constexpr std::string_view kTopKeys[] = {
    key::format,  key::version,   key::name,   key::description, key::simulation,
    key::effects, key::particles, key::boxes,  key::disks,       key::polygons,
    key::planes,  key::springs,   key::cloths, key::joints};

}  // namespace

double Range::lowest() const {
    switch (bound) {
        case Bound::Symmetric:
            return -max;
        case Bound::Positive:
        case Bound::IntegerAtLeast:
        case Bound::IntegerBetween:
            return min;
        case Bound::NonNegative:
        case Bound::UnitInterval:
        case Bound::PositiveUpTo:
            return 0.0;
        case Bound::None:
            break;
    }
    return -std::numeric_limits<double>::infinity();
}

bool Range::lowestExcluded() const {
    return (bound == Bound::Positive && min <= 0.0) || bound == Bound::PositiveUpTo;
}

std::span<const SolverSetting> solverSettings() {
    return kSolverSettings;
}
std::span<const std::string_view> topKeys() {
    return kTopKeys;
}

std::span<const std::string_view> effectKeys() {
    static const std::vector<std::string_view> keys = [] {
        std::vector<std::string_view> out;
        forEachEffect([&](const auto& t, auto) { out.push_back(t.key); });
        return out;
    }();
    return keys;
}

PB_TABLE(SimulationDesc, key::simulation, "how time advances", kSimulation)
PB_TABLE(GravityDesc, key::gravity, "Uniform gravity: F = m\u00b7g on every dynamic body", kGravity)
PB_TABLE(DragDesc, key::drag,
         "Air drag: F = \u2212b\u00b7v \u2212 c\u00b7\u2016v\u2016\u00b7v, torque "
         "\u2212\u03b2\u00b7\u03c9",
         kDrag)
PB_TABLE(NewtonianGravityDesc, key::newtonianGravity,
         "Newtonian gravity toward attractors (and between particles if mutual)", kNewtonianGravity)
PB_TABLE(AttractorDesc, key::attractors, "fixed points of newtonian_gravity", kAttractor)
PB_TABLE(BuoyancyDesc, key::buoyancy,
         "Buoyancy \u03c1\u00b7A_sub\u00b7\u2016g\u2016 on the submerged part below the surface",
         kBuoyancy)
PB_TABLE(WindDesc, key::wind, "Wind: F = b\u00b7(w \u2212 v) on particles", kWind)
PB_TABLE(FlockingDesc, key::flocking,
         "Boids steering: separation, alignment, cohesion (Reynolds 1987)", kFlocking)
PB_TABLE(ParticleCollisionsDesc, key::particleCollisions, "Particle\u2013particle disk contacts",
         kParticleCollisions)
// Coulomb's law runs whenever two particles carry a charge; the entry only sets its constants.
PB_TABLE(CoulombDesc, key::coulomb, "Coulomb's law between charged particles", kCoulomb, true)
PB_TABLE(ParticleDesc, key::particles, "point masses, drawn as disks", kParticle)
PB_TABLE(BoxDesc, key::boxes, "rigid rectangles", kBox)
PB_TABLE(DiskDesc, key::disks, "rigid disks: they turn, so they roll", kDisk, false, 2)
PB_TABLE(PolygonDesc, key::polygons, "rigid convex polygons", kPolygon, false, 2)
PB_TABLE(PlaneDesc, key::planes, "static half-planes, solid opposite the normal", kPlane)
PB_TABLE(SpringDesc, key::springs, "damped springs between two objects or an anchor", kSpring)
PB_TABLE(ClothDesc, key::cloths, "grids of particles joined by springs", kCloth)
PB_TABLE(ClothStiffnessDesc, key::stiffness, "a cloth's spring stiffnesses", kClothStiffness)

}  // namespace phasebox::schema
