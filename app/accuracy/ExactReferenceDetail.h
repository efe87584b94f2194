#pragma once
// Pieces the closed forms' files share (ExactMotions.cpp, ExactReference.cpp,
// BodyReferences.cpp). Private to app/accuracy.

#include "physics/core/Bodies.h"
#include "physics/core/Types.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace phasebox::exact_detail {

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Relative tolerance for "this vector lies along that axis": the along-axis closed form is
// exact only when the motion never leaves the axis, and a scene whose numbers merely come close
// (a velocity typed to six digits) must fall back to rk45 rather than be judged against a
// slightly wrong "exact" answer.
inline constexpr double kAlongAxis = 1e-12;

inline bool alongAxis(const Vec2& v, const Vec2& axis) {
    return std::abs(cross(v, axis)) <= kAlongAxis * std::max(1.0, v.norm());
}

// Distance from a point to a static rectangle (zero inside).
inline double distanceToBox(const RigidBody& box, const Vec2& point) {
    const Vec2 local = rotation(-box.angle) * (point - box.position);
    const Vec2 half = 0.5 * box.size;
    const Vec2 outside(std::max(std::abs(local.x()) - half.x(), 0.0),
                       std::max(std::abs(local.y()) - half.y(), 0.0));
    return outside.norm();
}

}  // namespace phasebox::exact_detail
