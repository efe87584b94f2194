// The effects' tables: gravity, drag, Newtonian gravity and its attractors, buoyancy, wind,
// flocking, particle collisions and Coulomb's law, one table each with its fields' keys, ranges,
// units and labels. The simulation's table, the contact solver's settings and the top-level keys
// are in SceneSchema.cpp; the objects' tables in ObjectSchema.cpp.
#include "physics/scene/SchemaFields.h"

namespace phasebox::schema {

namespace {

using namespace fields;

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

}  // namespace

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

}  // namespace phasebox::schema
