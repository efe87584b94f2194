// The objects' tables: particles, boxes, disks, polygons, planes, springs and cloths (with a
// cloth's stiffnesses), and the fields the rigid bodies share (position, angle, velocities, mass
// or density, static). The effects' tables are in EffectSchema.cpp, the joints' in
// JointSchema.cpp.
#include "physics/scene/SchemaFields.h"

#include <numbers>

namespace phasebox::schema {

namespace {

using namespace fields;

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
    // The editor shows the normal as the surface's tilt.
    {.key = key::normal,
     .type = T::Point,
     .member = &PlaneDesc::normal,
     .range = kLength,
     .label = "Normal",
     .description = "points out of the solid side; normalised on load",
     .need = Need::Required,
     .editor = {.min = -std::numbers::pi, .max = std::numbers::pi, .decimals = 3, .tilt = true},
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

}  // namespace

PB_TABLE(ParticleDesc, key::particles, "point masses, drawn as disks", kParticle)
PB_TABLE(BoxDesc, key::boxes, "rigid rectangles", kBox)
PB_TABLE(DiskDesc, key::disks, "rigid disks: they turn, so they roll", kDisk, false, 2)
PB_TABLE(PolygonDesc, key::polygons, "rigid convex polygons", kPolygon, false, 2)
PB_TABLE(PlaneDesc, key::planes, "static half-planes, solid opposite the normal", kPlane)
PB_TABLE(SpringDesc, key::springs, "damped springs between two objects or an anchor", kSpring)
PB_TABLE(ClothDesc, key::cloths, "grids of particles joined by springs", kCloth)
PB_TABLE(ClothStiffnessDesc, key::stiffness, "a cloth's spring stiffnesses", kClothStiffness)

}  // namespace phasebox::schema
