#pragma once
// The pieces of a scene description that the suites of every folder build by hand: a particle
// and the two kinds of spring. Built from SceneDesc, the way the app and the command line
// load a scene, so the suites go through buildWorld like everything else.

#include "physics/scene/SceneDesc.h"

#include <optional>
#include <string>

namespace phasebox::testing {

// A particle of the given mass and starting velocity. Its radius is 0 (a point, which no
// contact touches) unless one is given.
inline ParticleDesc particle(const std::string& id, Point2 position, double mass = 1.0,
                             Point2 velocity = {0.0, 0.0}, double radius = 0.0) {
    ParticleDesc p;
    p.id = id;
    p.position = position;
    p.velocity = velocity;
    p.mass = mass;
    p.radius = radius;
    return p;
}

// A spring between two objects; with no rest length, the distance at load.
inline SpringDesc bodySpring(const std::string& a, const std::string& b, double stiffness,
                             std::optional<double> restLength = std::nullopt) {
    SpringDesc s;
    s.a = a;
    s.b = b;
    s.stiffness = stiffness;
    s.restLength = restLength;
    return s;
}

// A spring from an object to a fixed world point; with no rest length, the distance at load.
inline SpringDesc anchorSpring(const std::string& a, Point2 anchor, double stiffness,
                               std::optional<double> restLength = std::nullopt) {
    SpringDesc s;
    s.a = a;
    s.anchor = anchor;
    s.stiffness = stiffness;
    s.restLength = restLength;
    return s;
}

}  // namespace phasebox::testing
