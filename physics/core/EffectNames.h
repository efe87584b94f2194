#pragma once
// The names the engine's effects give themselves (Effect::name()): what World::findEffect()
// looks up, World::effectCosts() and the effects panel list, and --json prints as
// effects[].name. They are the scene format's keys for the same effects, so the scene schema
// (physics/scene/SceneSchema.h) takes its effect keys from here: effects/ sits below scene/ and
// may not include it. The spring effect is named after the scene's springs array, which
// implies it. Spelled here and nowhere else.

#include <string_view>

namespace phasebox::effectName {

inline constexpr std::string_view gravity = "gravity";
inline constexpr std::string_view drag = "drag";
inline constexpr std::string_view newtonianGravity = "newtonian_gravity";
inline constexpr std::string_view buoyancy = "buoyancy";
inline constexpr std::string_view wind = "wind";
inline constexpr std::string_view flocking = "flocking";
inline constexpr std::string_view coulomb = "coulomb";
inline constexpr std::string_view springs = "springs";

}  // namespace phasebox::effectName
