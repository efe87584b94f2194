#pragma once
// Scene pieces for the joint suites (tst_joints, tst_heavy_chains): a scene under g = 9.81
// with one integrator and dt, particles, joints, and the exact period of a pendulum.

#include "PhysicsTestSupport.h"

#include <QString>

#include <cmath>
#include <optional>
#include <string>
#include <utility>

namespace phasebox::testing {

inline constexpr double kG = 9.81;

inline SceneDesc scene(const QString& integrator, double dt) {
    SceneDesc s;
    s.simulation.integrator = integrator.toStdString();
    s.simulation.dt = dt;
    s.effects.gravity = GravityDesc{};
    return s;
}

inline ParticleDesc particle(const std::string& id, Point2 position, double mass = 1.0) {
    ParticleDesc p;
    p.id = id;
    p.position = position;
    p.mass = mass;
    p.radius = 0.05;
    return p;
}

inline JointDesc joint(JointType type, const std::string& a, std::optional<std::string> b = {}) {
    JointDesc j;
    j.type = type;
    j.a = a;
    j.b = std::move(b);
    return j;
}

// The exact period of a pendulum of reduced length l = I/(m·d) released from rest at θ0.
inline double exactPeriod(double reducedLength, double theta0) {
    return 4.0 * std::sqrt(reducedLength / kG) * std::comp_ellint_1(std::sin(0.5 * theta0));
}

}  // namespace phasebox::testing
