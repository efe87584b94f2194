#include "physics/diagnostics/StabilityAdvisor.h"

#include "physics/joints/JointSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace phasebox {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// ω·h a penalty contact may reach under an explicit method (CONTRACT §6).
constexpr double kPenaltyMargin = 1.0;
// A method is recommended at a step only when its largest stable step is this much larger.
constexpr double kRecommendMargin = 1.25;

// The small-amplitude frequency of the pendulums in the world: each dynamic body held by one
// hinge, rod or rope (and no other joint) to a fixed point under uniform gravity. The force
// Jacobian does not see them (gravity is constant; the joints' pull is not a force source), yet
// a pendulum oscillates at ω² = m·g·d/I_pivot (a rigid body on a hinge, I_pivot = I + m·d²) or
// g/L (a particle on a rod or rope, a rigid body on one at its centre), and an explicit method
// meets that ω like a spring's. A rod at another point of a body makes a double pendulum: left
// out. 0 when there is none.
double pendulumOmega(const World& world) {
    Vec2 g(0.0, 0.0);
    bool uniform = false;
    for (const auto& effect : world.effects()) uniform = effect->uniformAcceleration(g) || uniform;
    const double gn = g.norm();
    const JointSolver* solver = world.jointSolver();
    if (!uniform || !(gn > 0.0) || !solver) return 0.0;
    const auto& joints = world.joints();
    // Bodies in more than one joint (chains, ragdolls) are not single pendulums.
    // (A fixed support may hold many: a pendulum wave.)
    std::vector<int> particleJoints(world.particles().size()),
        rigidJoints(world.rigidBodies().size());
    const auto count = [&](const JointBody& body) -> int* {
        if (body.kind == JointBody::Kind::Particle) return &particleJoints[body.index];
        if (body.kind == JointBody::Kind::Rigid) return &rigidJoints[body.index];
        return nullptr;
    };
    for (const Joint& joint : joints)
        for (const JointBody* body : {&joint.a, &joint.b})
            if (int* n = count(*body)) ++*n;
    const auto fixed = [&](const JointBody& body) {
        if (body.kind == JointBody::Kind::Particle) return world.particles()[body.index].dof < 0;
        if (body.kind == JointBody::Kind::Rigid) return world.rigidBodies()[body.index].dof < 0;
        return true;
    };
    double omega2 = 0.0;
    for (int j = 0; j < static_cast<int>(joints.size()); ++j) {
        const Joint& joint = joints[j];
        const bool line = joint.type == Joint::Type::Rod || joint.type == Joint::Type::Rope;
        if ((!line && joint.type != Joint::Type::Hinge) || !fixed(joint.b) || fixed(joint.a) ||
            *count(joint.a) != 1)
            continue;
        if (line && joint.length > 0.0 &&
            (joint.a.kind == JointBody::Kind::Particle || joint.a.point == Vec2::Zero())) {
            omega2 = std::max(omega2, gn / joint.length);
        } else if (!line && joint.a.kind == JointBody::Kind::Rigid) {
            const RigidBody& body = world.rigidBodies()[joint.a.index];
            const double d =
                (world.bodyPosition(joint.a.index) - solver->pointB(j, world.positions())).norm();
            if (d > 0.0)
                omega2 = std::max(omega2, body.mass * gn * d / (body.inertia + body.mass * d * d));
        }
    }
    return std::sqrt(omega2);
}

// A rigid body's extent along gravity's "up" and across it, from its shape's support function.
struct Extent {
    double low = 0.0, high = 0.0;          // along up
    double sideLow = 0.0, sideHigh = 0.0;  // across
    double centre = 0.0;                   // its centre along up
    int body = -1;
};

// How far the body reaches from its centre in direction d (unit).
double reach(const RigidBody& box, double angle, const Vec2& d) {
    const Vec2 axisX(std::cos(angle), std::sin(angle)), axisY(-axisX.y(), axisX.x());
    switch (box.shape) {
        case RigidShape::Disk:
            return box.radius;
        case RigidShape::Polygon: {
            double most = -std::numeric_limits<double>::infinity();
            for (const Vec2& v : box.vertices)
                most = std::max(most, d.dot(v.x() * axisX + v.y() * axisY));
            return most;
        }
        case RigidShape::Rectangle:
            break;
    }
    return 0.5 * (std::abs(d.dot(axisX)) * box.size.x() + std::abs(d.dot(axisY)) * box.size.y());
}

// The first pair (upper, lower) of dynamic rigid bodies where one rests on the other along up:
// the upper one's bottom within a tenth of the smaller height above the lower one's top (or
// sunk into it by less than half of it), their spans across overlapping, and the upper one's
// centre higher. A sweep over the spans across keeps it near linear for a row of bodies.
std::optional<std::pair<int, int>> findStack(const World& world, const Vec2& up) {
    const Vec2 side(up.y(), -up.x());
    std::vector<Extent> extents;
    for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i) {
        const RigidBody& box = world.rigidBodies()[i];
        if (box.isStatic) continue;
        const Vec2 c = world.bodyPosition(i);
        const double angle = world.bodyAngle(i);
        Extent e;
        e.centre = c.dot(up);
        e.low = e.centre - reach(box, angle, -up);
        e.high = e.centre + reach(box, angle, up);
        e.sideLow = c.dot(side) - reach(box, angle, -side);
        e.sideHigh = c.dot(side) + reach(box, angle, side);
        e.body = i;
        extents.push_back(e);
    }
    std::sort(extents.begin(), extents.end(),
              [](const Extent& a, const Extent& b) { return a.sideLow < b.sideLow; });
    const auto restsOn = [](const Extent& upper, const Extent& lower) {
        const double height = std::min(upper.high - upper.low, lower.high - lower.low);
        const double width =
            std::min(upper.sideHigh - upper.sideLow, lower.sideHigh - lower.sideLow);
        const double gap = upper.low - lower.high;
        const double across =
            std::min(upper.sideHigh, lower.sideHigh) - std::max(upper.sideLow, lower.sideLow);
        return upper.centre > lower.centre && gap <= 0.1 * height && gap >= -0.5 * height &&
               across > 0.1 * width;
    };
    for (std::size_t i = 0; i < extents.size(); ++i)
        for (std::size_t j = i + 1; j < extents.size() && extents[j].sideLow < extents[i].sideHigh;
             ++j) {
            if (restsOn(extents[i], extents[j])) return std::pair{extents[i].body, extents[j].body};
            if (restsOn(extents[j], extents[i])) return std::pair{extents[j].body, extents[i].body};
        }
    return std::nullopt;
}

std::string number(double v) {
    std::ostringstream out;
    out.precision(3);
    out << v;
    return out.str();
}
}  // namespace

std::string contactModelWarning(const World& world) {
    if (world.settings().contactModel != ContactModel::Kinematic || !world.contacts()) return {};
    Vec2 g = Vec2::Zero();
    for (const auto& effect : world.effects()) {
        Vec2 a;
        if (effect->uniformAcceleration(a)) g += a;
    }
    if (!(g.norm() > 0.0)) return {};  // nothing presses one body on another
    const auto stack = findStack(world, -g.normalized());
    if (!stack) return {};
    return "Kinematic contacts cannot hold a stack (\"" + world.rigidBodies()[stack->first].id +
           "\" rests on \"" + world.rigidBodies()[stack->second].id +
           "\"): they only stop bodies moving into each other and push them apart, so the stack "
           "sinks into the floor. Use impulse contacts for stacks.";
}

double stabilityBound(std::string_view integrator) {
    const IntegratorInfo* info = findIntegrator(integrator);
    return info ? info->stabilityBound : 0.0;
}

StabilityAdvice adviseStability(World& world, int powerIterations) {
    StabilityAdvice advice;
    world.commit();
    advice.contactWarning = contactModelWarning(world);
    const SimulationSettings& settings = world.settings();
    advice.dt = settings.dt / settings.substeps;

    // ω²_max by power iteration on S = M^{-1/2}·(−K)·M^{-1/2} (symmetric; K from the exact
    // Jacobian, so a compressed spring's softening counts).
    const int n = world.dimension();
    ForceJacobians jac;
    Vec force(n);
    world.diagnosticForcesAndJacobians(force, jac);
    if (n > 0 && jac.hasStiffness()) {
        SparseMatrix k(n, n);
        const std::vector<Triplet> triplets = jac.stiffnessTriplets();
        k.setFromTriplets(triplets.begin(), triplets.end());
        const Vec scale = world.inverseMass().cwiseSqrt();
        Vec x = Vec::Ones(n).normalized(), y(n);
        // A fixed, irregular start so no mode is missed by symmetry.
        for (int i = 0; i < n; ++i) x[i] += 0.01 * std::sin(1.7 * i);
        x.normalize();
        // The Rayleigh quotient approaches the top eigenvalue from below, slowly when the top
        // modes crowd together (a fine cloth): iterate until it settles to 1e-6, so that the
        // advised step is not optimistic.
        double lambda = 0.0;
        for (int it = 0; it < powerIterations; ++it) {
            y = -(scale.asDiagonal() * (k * (scale.asDiagonal() * x)));
            const double norm = y.norm();
            if (!(norm > 0.0) || !std::isfinite(norm)) break;
            const double next = x.dot(y);
            x = y / norm;
            const bool settled = it > 10 && std::abs(next - lambda) <= 1e-6 * std::abs(next);
            lambda = next;
            if (settled) break;
        }
        advice.omegaMax = lambda > 0.0 ? std::sqrt(lambda) : 0.0;
    }
    // Penalty contacts that have not begun yet (a ball in flight) are stiff all the same: the
    // stiffest a body resting on its points can be. Contacts that begin mid-step pump energy
    // even below the linear limit, so explicit methods keep a margin, ω·h ≤ 1 (CONTRACT §6).
    const double anticipated = world.anticipatedContactOmegaSquared();
    const bool penalty =
        world.settings().contactModel == ContactModel::Penalty && anticipated > 0.0;
    advice.omegaMax = std::max({advice.omegaMax, std::sqrt(anticipated), pendulumOmega(world)});
    const auto boundOf = [penalty](double bound) {
        return penalty && bound > 0.0 && std::isfinite(bound) ? std::min(bound, kPenaltyMargin)
                                                              : bound;
    };

    const double omega = advice.omegaMax;
    for (const IntegratorInfo& info : integratorRegistry()) {
        if (info.adaptive) continue;
        StepLimit limit{info.name, 0.0, {}};
        const double bound = boundOf(info.stabilityBound);
        if (omega == 0.0 || bound == kInfinity) {
            limit.maxDt = kInfinity;
            limit.note = omega == 0.0 ? "nothing oscillates" : "stable at any step";
        } else if (bound > 0.0) {
            limit.maxDt = bound / omega;
            limit.note = "omega*h < " + number(bound);
        } else {
            limit.maxDt = 0.0;
            limit.note = "gains energy at every step";
        }
        advice.limits.push_back(limit);
    }

    // The methods stable at this step with a margin: the only ones the advice may name.
    for (const StepLimit& limit : advice.limits)
        if (limit.maxDt >= kRecommendMargin * advice.dt) advice.recommended.push_back(limit);
    const auto alternatives = [&](std::ostringstream& out) {
        bool first = true;
        for (const StepLimit& limit : advice.recommended) {
            if (limit.integrator == settings.integrator) continue;
            out << (first ? "" : ", ") << limit.integrator;
            if (std::isfinite(limit.maxDt))
                out << " (stable below " << number(limit.maxDt) << " s)";
            first = false;
        }
        return !first;
    };

    const std::string& method = settings.integrator;
    const IntegratorInfo& info = world.integrator().info();
    const double bound = boundOf(info.stabilityBound);
    const auto growth = info.energyGrowth;
    const double wh = omega * advice.dt;
    if (omega > 0.0 && bound != kInfinity && wh >= bound) {
        advice.currentStable = false;
        std::ostringstream out;
        out << method << " at a sub-step of " << number(advice.dt)
            << " s has omega*h = " << number(wh);
        // Between the penalty margin and the method's linear limit the step is stable for a
        // contact already pressed, but one that begins mid-step can gain energy at every touch.
        const bool marginOnly = bound < info.stabilityBound && wh < info.stabilityBound;
        if (bound > 0.0 && marginOnly)
            out << " (below the linear limit " << number(info.stabilityBound) << " but above "
                << number(bound)
                << ", the margin for penalty contacts): a contact that begins within a step can "
                   "gain energy at every touch. Use dt/substeps below "
                << number(bound / omega) << " s (" << std::ceil(settings.dt * omega / bound)
                << " sub-steps)";
        else if (bound > 0.0)
            out << " (stable below " << number(bound)
                << "): it will blow up. Use dt/substeps below " << number(bound / omega) << " s ("
                << std::ceil(settings.dt * omega / bound) << " sub-steps, more for a margin)";
        else
            out << ": it gains energy at every step (its stiffest mode by a factor of about "
                << number(growth ? growth(wh) : kInfinity) << " per sub-step)";
        std::ostringstream others;
        if (alternatives(others))
            out << (bound > 0.0 ? ", or" : ". Use")
                << " a method stable at this step: " << others.str();
        out << ".";
        advice.message = out.str();
    } else {
        advice.message = omega > 0.0
                             ? method + " is stable at this step (omega*h = " + number(wh) + ")"
                             : "nothing in the scene oscillates";
    }
    return advice;
}

}  // namespace phasebox
