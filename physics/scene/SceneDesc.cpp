#include "physics/scene/SceneDesc.h"

#include "physics/integrators/Integrator.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_set>

namespace phasebox {

namespace {
std::string defaultOr(const std::string& id, const char* prefix, std::size_t index) {
    return id.empty() ? prefix + std::to_string(index) : id;
}

// Shortest text that reads back as v, so that "got 1.0000001" is never printed as "got 1".
// The exponent is written as JSON authors write it: 1e300 and 1e-12, not 1e+300 and 1e-012.
std::string fmt(double v) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    std::string text(buffer, result.ptr);
    if (const auto e = text.find('e'); e != std::string::npos) {
        std::size_t digits = e + 1;
        if (digits < text.size() && text[digits] == '+') text.erase(digits, 1);
        else if (digits < text.size() && text[digits] == '-') ++digits;
        while (digits + 1 < text.size() && text[digits] == '0') text.erase(digits, 1);
    }
    return text;
}

using L = SceneLimits;

// Collects issues with JSON-style paths: check(path, condition, message).
class Checker {
public:
    explicit Checker(std::vector<SceneIssue>& out) : out_(out) {}

    void fail(const std::string& path, const std::string& message) {
        out_.push_back({path, message});
    }
    // Each numeric check first requires a finite number; each returns whether v passed, so
    // that checks chain (positive, then at most the limit) and report one problem per value.
    bool finite(const std::string& path, double v) {
        if (std::isfinite(v)) return true;
        fail(path, "must be a finite number");
        return false;
    }
    bool positive(const std::string& path, double v, double max = kNoLimit) {
        if (!finite(path, v)) return false;
        if (!(v > 0.0)) return fails(path, "must be > 0 (got " + fmt(v) + ")");
        return atMost(path, v, max);
    }
    bool nonNegative(const std::string& path, double v, double max = kNoLimit) {
        if (!finite(path, v)) return false;
        if (v < 0.0) return fails(path, "must be >= 0 (got " + fmt(v) + ")");
        return atMost(path, v, max);
    }
    bool unitInterval(const std::string& path, double v) {
        if (finite(path, v) && (v < 0.0 || v > 1.0))
            return fails(path, "must be between 0 and 1 (got " + fmt(v) + ")");
        return std::isfinite(v);
    }
    // A signed value: finite and |v| <= limit.
    bool magnitude(const std::string& path, double v, double limit) {
        if (!finite(path, v)) return false;
        if (std::abs(v) > limit)
            return fails(path, "must be between -" + fmt(limit) + " and " + fmt(limit) + " (got " +
                                   fmt(v) + ")");
        return true;
    }
    bool atMost(const std::string& path, double v, double max) {
        if (v > max) return fails(path, "must be <= " + fmt(max) + " (got " + fmt(v) + ")");
        return true;
    }
    bool atLeast(const std::string& path, double v, double min) {
        if (v < min) return fails(path, "must be >= " + fmt(min) + " (got " + fmt(v) + ")");
        return true;
    }
    // Both coordinates finite and within ±limit (lengths by default).
    void point(const std::string& path, const Point2& p, double limit = L::kMaxLength) {
        magnitude(path + "[0]", p[0], limit);
        magnitude(path + "[1]", p[1], limit);
    }
    // A positive mass within [kMinMass, max].
    void mass(const std::string& path, double v, double max = L::kMaxMass) {
        if (positive(path, v, max)) atLeast(path, v, L::kMinMass);
    }

    static constexpr double kNoLimit = std::numeric_limits<double>::infinity();

private:
    bool fails(const std::string& path, const std::string& message) {
        fail(path, message);
        return false;
    }

    std::vector<SceneIssue>& out_;
};

std::string at(const char* array, std::size_t i) {
    return std::string(array) + "[" + std::to_string(i) + "]";
}
}  // namespace

std::string particleId(const SceneDesc& s, std::size_t i) { return defaultOr(s.particles[i].id, "p", i); }
std::string boxId(const SceneDesc& s, std::size_t i) { return defaultOr(s.boxes[i].id, "b", i); }
std::string planeId(const SceneDesc& s, std::size_t i) { return defaultOr(s.planes[i].id, "plane", i); }
std::string springId(const SceneDesc& s, std::size_t i) { return defaultOr(s.springs[i].id, "s", i); }
std::string clothNodeId(const std::string& clothId, int i, int j) {
    return clothId + "[" + std::to_string(i) + "," + std::to_string(j) + "]";
}

std::vector<SceneIssue> validateScene(const SceneDesc& scene) {
    std::vector<SceneIssue> issues;
    Checker check(issues);

    // simulation
    const SimulationDesc& sim = scene.simulation;
    if (!findIntegrator(sim.integrator))
        check.fail("simulation.integrator",
                   "unknown integrator \"" + sim.integrator + "\"; known: " + knownIntegratorNames());
    if (check.finite("simulation.dt", sim.dt) && !(sim.dt > 0.0 && sim.dt <= 1.0))
        check.fail("simulation.dt", "must be > 0 and <= 1 (got " + fmt(sim.dt) + ")");
    if (sim.substeps < 1) check.fail("simulation.substeps", "must be an integer >= 1");
    check.positive("simulation.tolerance", sim.tolerance, L::kMaxCoefficient);
    if (sim.newtonIterations < 1)
        check.fail("simulation.newton_iterations", "must be an integer >= 1");
    check.positive("simulation.duration", sim.duration, L::kMaxDuration);
    // The contact solver's keys (engine-defined); others are ignored like any unknown key.
    for (const auto& [key, value] : sim.solver) {
        const std::string path = "simulation.solver." + key;
        if (!check.finite(path, value)) continue;
        if (key == "iterations" || key == "relax_iterations") {
            if (value < 0 || value > 1000 || value != std::floor(value))
                check.fail(path, "must be an integer between 0 and 1000");
        } else if (key == "contact_hertz" || key == "push_out") {
            check.positive(path, value, L::kMaxCoefficient);
        } else if (key == "damping_ratio" || key == "restitution_threshold" ||
                   key == "speculative_distance") {
            check.nonNegative(path, value, L::kMaxCoefficient);
        }
    }

    // effects
    const EffectsDesc& fx = scene.effects;
    if (fx.gravity) check.point("effects.gravity.g", fx.gravity->g, L::kMaxAcceleration);
    if (fx.drag) {
        check.nonNegative("effects.drag.linear", fx.drag->linear, L::kMaxCoefficient);
        check.nonNegative("effects.drag.quadratic", fx.drag->quadratic, L::kMaxCoefficient);
        check.nonNegative("effects.drag.angular", fx.drag->angular, L::kMaxCoefficient);
    }
    if (fx.newtonianGravity) {
        const auto& ng = *fx.newtonianGravity;
        check.nonNegative("effects.newtonian_gravity.G", ng.G, L::kMaxCoefficient);
        check.nonNegative("effects.newtonian_gravity.softening", ng.softening, L::kMaxLength);
        for (std::size_t i = 0; i < ng.attractors.size(); ++i) {
            const std::string path = "effects.newtonian_gravity." + at("attractors", i);
            check.point(path + ".position", ng.attractors[i].position);
            check.nonNegative(path + ".mass", ng.attractors[i].mass, L::kMaxAttractorMass);
        }
    }
    if (fx.buoyancy) {
        check.positive("effects.buoyancy.fluid_density", fx.buoyancy->fluidDensity, L::kMaxMass);
        check.magnitude("effects.buoyancy.surface_y", fx.buoyancy->surfaceY, L::kMaxLength);
        check.nonNegative("effects.buoyancy.drag", fx.buoyancy->drag, L::kMaxCoefficient);
        if (!fx.gravity) check.fail("effects.buoyancy", "needs the gravity effect");
    }
    if (fx.wind) {
        check.point("effects.wind.velocity", fx.wind->velocity, L::kMaxSpeed);
        check.nonNegative("effects.wind.drag", fx.wind->drag, L::kMaxCoefficient);
    }
    if (fx.flocking) {
        check.positive("effects.flocking.radius", fx.flocking->radius, L::kMaxLength);
        const FlockingDesc& f = *fx.flocking;
        check.nonNegative("effects.flocking.separation", f.separation, L::kMaxCoefficient);
        check.nonNegative("effects.flocking.alignment", f.alignment, L::kMaxCoefficient);
        check.nonNegative("effects.flocking.cohesion", f.cohesion, L::kMaxCoefficient);
        check.positive("effects.flocking.max_speed", fx.flocking->maxSpeed, L::kMaxSpeed);
    }
    if (fx.particleCollisions)
        check.unitInterval("effects.particle_collisions.restitution",
                           fx.particleCollisions->restitution);
    if (fx.coulomb) {
        check.nonNegative("effects.coulomb.k", fx.coulomb->k, L::kMaxCoefficient);
        check.nonNegative("effects.coulomb.softening", fx.coulomb->softening, L::kMaxLength);
    }

    // Sizes: past these limits a scene is refused rather than allowed to exhaust memory or
    // hang (the limits are documented in docs/scene-format.md).
    if (sim.substeps > SceneLimits::kMaxSubsteps)
        check.fail("simulation.substeps", "must be <= " + std::to_string(SceneLimits::kMaxSubsteps));
    if (sim.newtonIterations > SceneLimits::kMaxNewtonIterations)
        check.fail("simulation.newton_iterations",
                   "must be <= " + std::to_string(SceneLimits::kMaxNewtonIterations));
    long long clothNodes = 0;
    for (const ClothDesc& cl : scene.cloths)
        clothNodes += static_cast<long long>(std::max(0, cl.resolution[0])) * std::max(0, cl.resolution[1]);
    const long long particleCount = static_cast<long long>(scene.particles.size()) + clothNodes;
    if (particleCount > SceneLimits::kMaxParticles)
        check.fail(scene.cloths.empty() ? "particles" : "cloths",
                   "the scene has " + std::to_string(particleCount) + " particles (cloth nodes included); at most " +
                       std::to_string(SceneLimits::kMaxParticles) + " are allowed");
    if (static_cast<long long>(scene.boxes.size()) > SceneLimits::kMaxBoxes)
        check.fail("boxes", "at most " + std::to_string(SceneLimits::kMaxBoxes) + " boxes are allowed");
    if (static_cast<long long>(scene.springs.size()) > SceneLimits::kMaxSprings)
        check.fail("springs", "at most " + std::to_string(SceneLimits::kMaxSprings) + " springs are allowed");
    if (static_cast<long long>(scene.planes.size()) > SceneLimits::kMaxPlanes)
        check.fail("planes", "at most " + std::to_string(SceneLimits::kMaxPlanes) + " planes are allowed");
    if (!issues.empty() && (particleCount > SceneLimits::kMaxParticles)) return issues;

    // ids: unique across the scene (cloth node ids included); springs may refer to particles,
    // boxes and cloth nodes. Each id remembers who holds it, for the messages.
    std::map<std::string, std::string> ids;  // id → path of its holder
    std::unordered_set<std::string> bodies;
    auto claim = [&](const std::string& path, const std::string& id, bool body, bool isDefault) {
        const auto [it, fresh] = ids.emplace(id, path);
        if (!fresh) {
            if (isDefault)
                check.fail(path, "the default id \"" + id + "\" is already used by " + it->second +
                                     "; give this object an id");
            else
                check.fail(path + ".id", "duplicate id \"" + id + "\" (also used by " + it->second + ")");
        }
        if (body) bodies.insert(id);
    };

    for (std::size_t i = 0; i < scene.particles.size(); ++i) {
        const ParticleDesc& p = scene.particles[i];
        const std::string path = at("particles", i);
        claim(path, particleId(scene, i), true, p.id.empty());
        check.point(path + ".position", p.position);
        check.point(path + ".velocity", p.velocity, L::kMaxSpeed);
        check.mass(path + ".mass", p.mass);
        check.nonNegative(path + ".radius", p.radius, L::kMaxLength);
        check.unitInterval(path + ".restitution", p.restitution);
        check.nonNegative(path + ".friction", p.friction, L::kMaxCoefficient);
        check.magnitude(path + ".charge", p.charge, L::kMaxCharge);
    }
    for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
        const BoxDesc& b = scene.boxes[i];
        const std::string path = at("boxes", i);
        claim(path, boxId(scene, i), true, b.id.empty());
        check.point(path + ".position", b.position);
        for (int k = 0; k < 2; ++k) {
            const std::string size = path + ".size[" + std::to_string(k) + "]";
            if (check.positive(size, b.size[k], L::kMaxLength))
                check.atLeast(size, b.size[k], L::kMinBoxSize);
        }
        check.magnitude(path + ".angle", b.angle, L::kMaxAngle);
        check.point(path + ".velocity", b.velocity, L::kMaxSpeed);
        check.magnitude(path + ".angular_velocity", b.angularVelocity, L::kMaxSpeed);
        if (b.mass) check.mass(path + ".mass", *b.mass);
        else check.mass(path + ".density", b.density);
        check.nonNegative(path + ".friction", b.friction, L::kMaxCoefficient);
        check.unitInterval(path + ".restitution", b.restitution);
    }
    for (std::size_t i = 0; i < scene.planes.size(); ++i) {
        const PlaneDesc& p = scene.planes[i];
        const std::string path = at("planes", i);
        claim(path, planeId(scene, i), false, p.id.empty());
        check.point(path + ".point", p.point);
        check.point(path + ".normal", p.normal);
        // The normal is normalised on load: a length that squares to zero or to infinity would
        // make it NaN, so its length must be representable (the bound is checked just above).
        const double length = std::hypot(p.normal[0], p.normal[1]);
        if (p.normal[0] == 0.0 && p.normal[1] == 0.0) check.fail(path + ".normal", "must be non-zero");
        else if (std::isfinite(length) && length < L::kMinNormalLength)
            check.fail(path + ".normal", "is too short to give a direction (length " + fmt(length) +
                                             "; at least " + fmt(L::kMinNormalLength) + ")");
        check.nonNegative(path + ".friction", p.friction, L::kMaxCoefficient);
        check.unitInterval(path + ".restitution", p.restitution);
    }
    for (std::size_t c = 0; c < scene.cloths.size(); ++c) {
        const ClothDesc& cl = scene.cloths[c];
        const std::string path = at("cloths", c);
        if (cl.id.empty()) check.fail(path + ".id", "is required");
        else claim(path, cl.id, false, false);
        check.point(path + ".origin", cl.origin);
        check.positive(path + ".size[0]", cl.size[0], L::kMaxLength);
        check.positive(path + ".size[1]", cl.size[1], L::kMaxLength);
        if (cl.resolution[0] < 2) check.fail(path + ".resolution[0]", "must be an integer >= 2");
        if (cl.resolution[1] < 2) check.fail(path + ".resolution[1]", "must be an integer >= 2");
        check.mass(path + ".mass", cl.mass);
        const ClothStiffnessDesc& k = cl.stiffness;
        check.nonNegative(path + ".stiffness.structural", k.structural, L::kMaxCoefficient);
        check.nonNegative(path + ".stiffness.shear", k.shear, L::kMaxCoefficient);
        check.nonNegative(path + ".stiffness.bend", k.bend, L::kMaxCoefficient);
        check.nonNegative(path + ".damping", cl.damping, L::kMaxCoefficient);
        check.nonNegative(path + ".radius", cl.radius, L::kMaxLength);
        if (const auto* mode = std::get_if<std::string>(&cl.pinned)) {
            if (*mode != "top" && *mode != "top_corners" && *mode != "left" && *mode != "none")
                check.fail(path + ".pinned", "unknown pinning \"" + *mode +
                                                 "\"; known: top, top_corners, left, none");
        } else {
            const auto& nodes = std::get<std::vector<std::array<int, 2>>>(cl.pinned);
            for (std::size_t k = 0; k < nodes.size(); ++k) {
                const auto [i, j] = nodes[k];
                if (i < 0 || i >= cl.resolution[0] || j < 0 || j >= cl.resolution[1])
                    check.fail(path + ".pinned[" + std::to_string(k) + "]",
                               "node [" + std::to_string(i) + "," + std::to_string(j) +
                                   "] is outside the " + std::to_string(cl.resolution[0]) + "x" +
                                   std::to_string(cl.resolution[1]) + " grid");
            }
        }
        if (!cl.id.empty() && cl.resolution[0] >= 2 && cl.resolution[1] >= 2)
            for (int j = 0; j < cl.resolution[1]; ++j)
                for (int i = 0; i < cl.resolution[0]; ++i)
                    claim(path, clothNodeId(cl.id, i, j), true, false);
    }
    for (std::size_t i = 0; i < scene.springs.size(); ++i) {
        const SpringDesc& s = scene.springs[i];
        const std::string path = at("springs", i);
        claim(path, springId(scene, i), false, s.id.empty());
        auto reference = [&](const std::string& where, const std::string& id) {
            if (bodies.count(id)) return;
            const auto it = ids.find(id);
            if (it == ids.end())
                check.fail(where, "unknown object id \"" + id + "\"");
            else
                check.fail(where, "\"" + id + "\" is " + it->second +
                                      "; springs attach to particles, boxes and cloth nodes");
        };
        if (s.a.empty()) check.fail(path + ".a", "is required");
        else reference(path + ".a", s.a);
        if (s.b && s.anchor) check.fail(path, "has both b and anchor; give one");
        else if (!s.b && !s.anchor) check.fail(path, "needs either b (an object id) or anchor [x, y]");
        if (s.b) reference(path + ".b", *s.b);
        if (s.b && *s.b == s.a) check.fail(path + ".b", "must differ from a");
        if (s.anchor) check.point(path + ".anchor", *s.anchor);
        check.point(path + ".a_point", s.aPoint);
        check.point(path + ".b_point", s.bPoint);
        check.positive(path + ".stiffness", s.stiffness, L::kMaxCoefficient);
        check.nonNegative(path + ".damping", s.damping, L::kMaxCoefficient);
        if (s.restLength) check.nonNegative(path + ".rest_length", *s.restLength, L::kMaxLength);
    }
    return issues;
}

}  // namespace phasebox
