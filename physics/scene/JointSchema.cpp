// The joints' tables (CONTRACT §6): which fields each type of joint uses, its motor and its
// track's curves.
#include "physics/scene/SchemaFields.h"

namespace phasebox::schema {

namespace {

using namespace fields;

// ---- joints (CONTRACT §6) ----

const Field<JointMotorDesc> kJointMotor[] = {
    {.key = key::speed,
     .type = T::Number,
     .member = &JointMotorDesc::speed,
     .range = kSpeed,
     .unit = "rad/s",
     .label = "Speed",
     .description = "the rate of the joint angle it drives toward",
     .editor = {-1000.0, 1000.0, 2}},
    // Required: a motor whose torque defaulted to 0 would silently do nothing.
    {.key = key::maxTorque,
     .type = T::Number,
     .member = &JointMotorDesc::maxTorque,
     .range = kCoefficient,
     .unit = "N\u00b7m",
     .label = "Maximum torque",
     .description = "the largest torque it applies",
     .need = Need::Required,
     .editor = {0.0, kLarge, 2}},
};

const Field<TrackCircleDesc> kTrackCircle[] = {
    {.key = key::center,
     .type = T::Point,
     .member = &TrackCircleDesc::center,
     .range = kLength,
     .unit = "m",
     .label = "Centre",
     .description = "the circle's centre",
     .need = Need::Required,
     .editor = {-kFar, kFar, 3}},
    {.key = key::radius,
     .type = T::Number,
     .member = &TrackCircleDesc::radius,
     .range = positive(L::kMaxLength),
     .unit = "m",
     .label = "Radius",
     .description = "the circle's radius",
     .need = Need::Required,
     .editor = {0.001, kFar, 3}},
};

const Field<TrackLineDesc> kTrackLine[] = {
    {.key = key::point,
     .type = T::Point,
     .member = &TrackLineDesc::point,
     .range = kLength,
     .unit = "m",
     .label = "Point",
     .description = "a point of the line",
     .need = Need::Required,
     .editor = {-kFar, kFar, 3}},
    {.key = key::direction,
     .type = T::Point,
     .member = &TrackLineDesc::direction,
     .range = kLength,
     .label = "Direction",
     .description = "along the line, of any non-zero length",
     .need = Need::Required,
     .editor = {-kFar, kFar, 3},
     .rule = Rule::NonZeroDirection},
};

// Which fields each type of joint uses (CONTRACT §6, the joints table).
bool isHinge(const JointDesc& j) {
    return j.type == JointType::Hinge;
}
bool isPulley(const JointDesc& j) {
    return j.type == JointType::Pulley;
}
bool isTrack(const JointDesc& j) {
    return j.type == JointType::Track;
}
bool isRodOrRope(const JointDesc& j) {
    return j.type == JointType::Rod || j.type == JointType::Rope;
}
bool holdsPoints(const JointDesc& j) {
    return isRodOrRope(j) || isPulley(j);
}
// The world's end of a rod or rope is its anchor, not a point in a frame.
bool holdsPointOnB(const JointDesc& j) {
    return holdsPoints(j) && j.b.has_value();
}
bool hasAnchor(const JointDesc& j) {
    return isHinge(j) || isRodOrRope(j);
}

const Field<JointDesc> kJoint[] = {
    idField<JointDesc>("unique across the scene; default j0, j1, \u2026 by position"),
    {.key = key::type,
     .type = T::Choice,
     .member = &JointDesc::type,
     .label = "Type",
     .description = "hinge, rod, rope, weld, pulley or track",
     .need = Need::Required,
     .choices = kJointTypeNames},
    {.key = key::a,
     .type = T::IdRef,
     .member = &JointDesc::a,
     .label = "Body a",
     .description = "the body it holds",
     .need = Need::Required},
    {.key = key::b,
     .type = T::IdRef,
     .member = &JointDesc::b,
     .label = "Body b",
     .description = "the body it holds a to; absent = the fixed world"},
    {.key = key::aPoint,
     .type = T::Point,
     .member = &JointDesc::aPoint,
     .range = kLength,
     .unit = "m",
     .label = "Point on a",
     .description = "where it holds a, in a's own frame",
     .editor = {-kFar, kFar, 3},
     .uses = holdsPoints,
     .usedBy = "rod, rope and pulley joints"},
    {.key = key::bPoint,
     .type = T::Point,
     .member = &JointDesc::bPoint,
     .range = kLength,
     .unit = "m",
     .label = "Point on b",
     .description = "where it holds b, in b's own frame",
     .editor = {-kFar, kFar, 3},
     .uses = holdsPointOnB,
     .usedBy = "rod, rope and pulley joints with b"},
    {.key = key::anchor,
     .type = T::Point,
     .member = &JointDesc::anchor,
     .range = kLength,
     .unit = "m",
     .label = "Anchor",
     .description =
         "a world point at load: a hinge's pivot, or a rod's or rope's end when b is absent",
     .editor = {-kFar, kFar, 3},
     .uses = hasAnchor,
     .usedBy = "hinge, rod and rope joints"},
    {.key = key::length,
     .type = T::Number,
     .member = &JointDesc::length,
     .range = positive(L::kMaxLength),
     .unit = "m",
     .label = "Length",
     .description = "a rod's distance, a rope's longest; absent = the initial distance",
     .editor = {0.001, kFar, 3},
     .uses = isRodOrRope,
     .usedBy = "rod and rope joints"},
    {.key = key::limits,
     .type = T::Interval,
     .member = &JointDesc::limits,
     .range = symmetric(L::kMaxAngle),
     .unit = "rad",
     .label = "Limits",
     .description = "[lower, upper] of the joint angle, counted from its value at load",
     .editor = {-100.0, 100.0, 3},
     .uses = isHinge,
     .usedBy = "hinge joints"},
    {.key = key::motor,
     .type = T::Object,
     .member = &JointDesc::motor,
     .label = "Motor",
     .description = "drives the joint angle's rate",
     .uses = isHinge,
     .usedBy = "hinge joints"},
    {.key = key::groundA,
     .type = T::Point,
     .member = &JointDesc::groundA,
     .range = kLength,
     .unit = "m",
     .label = "Ground a",
     .description = "the fixed pulley a's side of the rope runs over",
     .need = Need::Required,
     .editor = {-kFar, kFar, 3},
     .uses = isPulley,
     .usedBy = "pulley joints"},
    {.key = key::groundB,
     .type = T::Point,
     .member = &JointDesc::groundB,
     .range = kLength,
     .unit = "m",
     .label = "Ground b",
     .description = "the fixed pulley b's side of the rope runs over",
     .need = Need::Required,
     .editor = {-kFar, kFar, 3},
     .uses = isPulley,
     .usedBy = "pulley joints"},
    {.key = key::ratio,
     .type = T::Number,
     .member = &JointDesc::ratio,
     .range = positive(L::kMaxCoefficient),
     .label = "Ratio",
     .description = "|ground_a \u2212 p_a| + ratio\u00b7|ground_b \u2212 p_b| stays constant",
     .editor = {0.01, 100.0, 3},
     .uses = isPulley,
     .usedBy = "pulley joints"},
    {.key = key::circle,
     .type = T::Object,
     .member = &JointDesc::circle,
     .label = "Circle",
     .description = "the circle the particle runs on",
     .uses = isTrack,
     .usedBy = "track joints"},
    {.key = key::line,
     .type = T::Object,
     .member = &JointDesc::line,
     .label = "Line",
     .description = "the line the particle runs on",
     .uses = isTrack,
     .usedBy = "track joints"},
};

}  // namespace

PB_TABLE(JointDesc, key::joints,
         "joints holding bodies together: hinges, rods, ropes, welds, pulleys, tracks", kJoint,
         false, 2)
PB_TABLE(JointMotorDesc, key::motor, "a hinge's motor", kJointMotor)
PB_TABLE(TrackCircleDesc, key::circle, "the circle of a track", kTrackCircle)
PB_TABLE(TrackLineDesc, key::line, "the line of a track", kTrackLine)

}  // namespace phasebox::schema
