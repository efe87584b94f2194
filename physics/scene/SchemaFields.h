#pragma once
// What the schema's table files share (SceneSchema.cpp, EffectSchema.cpp, ObjectSchema.cpp,
// JointSchema.cpp): the property editor's ranges, the ranges of the format, the fields every
// kind spells the same way, and the macro that defines a kind's tableOf(). Private to
// physics/scene.

#include "physics/scene/SceneSchema.h"

namespace phasebox::schema::fields {

using L = SceneLimits;
using T = Type;

// The property editor's ranges: coordinates and speeds far past any classroom scene, and
// coefficients large enough for stiff springs yet small enough for a spin box.
inline constexpr double kFar = 1e6;
inline constexpr double kLarge = 1e9;
constexpr Editor kPlaces{-kFar, kFar, 3, true};  // positions, velocities, angles
constexpr Editor kMassEditor{0.001, kLarge, 3};
constexpr Editor kFrictionEditor{0.0, 10.0, 2};
constexpr Editor kRestitutionEditor{0.0, 1.0, 2};
constexpr Editor kSwitch{0.0, 1.0, 0};

constexpr Range kMass = positive(L::kMaxMass, L::kMinMass);
constexpr Range kLength = symmetric(L::kMaxLength);
constexpr Range kSpeed = symmetric(L::kMaxSpeed);
constexpr Range kCoefficient = nonNegative(L::kMaxCoefficient);

// An object's id is written only when it has one (empty = the default by position).
template <typename D>
bool hasId(const D& d) {
    return !d.id.empty();
}
template <typename D>
Field<D> idField(std::string_view defaults) {
    return {.key = key::id,
            .type = T::String,
            .member = &D::id,
            .label = "Id",
            .description = defaults,
            .present = hasId<D>};
}

// The material fields every collider shares (particles, boxes, planes).
template <typename D>
Field<D> frictionField(double D::*member) {
    return {.key = key::friction,
            .type = T::Number,
            .member = member,
            .range = kCoefficient,
            .label = "Friction",
            .description = "friction coefficient \u03bc",
            .editor = kFrictionEditor};
}
template <typename D>
Field<D> restitutionField(double D::*member) {
    return {.key = key::restitution,
            .type = T::Number,
            .member = member,
            .range = unitInterval(),
            .label = "Restitution",
            .description = "bounce, 0 to 1",
            .editor = kRestitutionEditor};
}

template <typename D, std::size_t N>
Table<D> makeTable(std::string_view tableKey, std::string_view description,
                   const Field<D> (&fields)[N], bool implied = false, int sinceVersion = 1) {
    return {tableKey, description, std::span<const Field<D>>(fields), implied, sinceVersion};
}

// Defines tableOf(std::type_identity<Desc>) for a kind's field array.
#define PB_TABLE(Desc, tableKey, description, fields, ...)                             \
    const Table<Desc>& tableOf(std::type_identity<Desc>) {                             \
        static const Table<Desc> t =                                                   \
            makeTable<Desc>(tableKey, description, fields __VA_OPT__(, ) __VA_ARGS__); \
        return t;                                                                      \
    }

}  // namespace phasebox::schema::fields
