#pragma once
// The forces on one body, each by its source, for the app's free-body view: every effect the
// world holds (gravity, drag, wind, …; the spring effect split into its springs), the contacts
// and each joint on the body, with its momentum. They are read from the same machinery the step
// uses, at the current state:
//
//   effects   Effect::addForces on the current (q, u, t), the (x, y) of the body's force; the
//             effect's torque on a rigid body is left out (the view draws forces at the centre)
//   springs   each spring with an end on the body: its signed tension k·(L − L₀) + c·L̇ along
//             the spring (World::springTension), as the spring effect applies it
//   contact   World::contactForce: the contact impulses of the last step over dt (impulse and
//             kinematic models), the penalty force at the current state (penalty)
//   joints    World::jointForceOn of each joint holding the body, at the last
//             derivative evaluation
//
// At a recorded frame the world shows (WorldSnapshot::show) the contact and joint forces are the
// frame's, as the step that ended there left them.
//
// At rest the sum is zero up to the solvers' tolerance; in free flight it is m·a.

#include "physics/core/Types.h"
#include "physics/world/Probes.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace phasebox {

class World;

struct BodyForce {
    enum class Source : unsigned char { Effect, Spring, Contact, Joint };
    Source source = Source::Effect;
    std::string name;  // the effect's name (effectName), the spring's or joint's id, "contact"
    Vec2 force{0.0, 0.0};
};

struct FreeBody {
    ProbeObject body;
    Vec2 position{0.0, 0.0};
    double mass = 0.0;
    Vec2 momentum{0.0, 0.0};
    std::vector<BodyForce> forces;

    Vec2 net() const {
        Vec2 sum = Vec2::Zero();
        for (const BodyForce& f : forces) sum += f.force;
        return sum;
    }
};

// The free body of the particle or rigid body with this id; nullopt when there is none or it
// is pinned or static (the world holds it: the forces on it are not summed anywhere). Effects
// keep only scratch between evaluations, so evaluating them here changes nothing in the run.
// Springs and joints on the body are listed even when their force is zero; effects and the
// contact only when theirs is not.
std::optional<FreeBody> freeBodyOf(const World& world, std::string_view id);

}  // namespace phasebox
