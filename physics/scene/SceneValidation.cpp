// validateScene() and validatePolygonVertices(): every field against its range in the schema,
// the sizes past which a scene is refused, unique ids and the references of springs, a cloth's
// pinning and a polygon's shape; the joints' checks are in JointValidation.cpp. Also the
// checks' shared helpers (ValidationChecks.h): a name quoted for a message, a number written
// so that it reads back, JSON-style paths, and checkFields(), which walks a kind's table.
#include "physics/scene/ValidationChecks.h"

#include "physics/integrators/Integrator.h"
#include "physics/scene/InstrumentValidation.h"
#include "physics/scene/SceneSchema.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <span>
#include <unordered_set>

namespace phasebox {

namespace validation {

// A name from the file (an id, an integrator) in quotes for a message, cut to its first 40
// bytes (at a UTF-8 character boundary) and its length when longer: a 20 MB id must not be
// echoed whole.
std::string quoted(const std::string& text) {
    constexpr std::size_t kShown = 40;
    if (text.size() <= kShown + 10) return "\"" + text + "\"";
    std::size_t cut = kShown;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    return "\"" + text.substr(0, cut) + "...\" (" + std::to_string(text.size()) + " bytes)";
}

// Shortest text that reads back as v, so that "got 1.0000001" is never printed as "got 1".
// The exponent is written as JSON authors write it: 1e300 and 1e-12, not 1e+300 and 1e-012.
std::string fmt(double v) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    std::string text(buffer, result.ptr);
    if (const auto e = text.find('e'); e != std::string::npos) {
        std::size_t digits = e + 1;
        if (digits < text.size() && text[digits] == '+')
            text.erase(digits, 1);
        else if (digits < text.size() && text[digits] == '-')
            ++digits;
        while (digits + 1 < text.size() && text[digits] == '0') text.erase(digits, 1);
    }
    return text;
}

std::string at(std::string_view array, std::size_t i) {
    return std::string(array) + "[" + std::to_string(i) + "]";
}

std::string join(const std::string& path, std::string_view key) {
    return path + "." + std::string(key);
}

namespace {

using L = SceneLimits;

std::string integerText(double v) {
    return std::to_string(static_cast<long long>(v));
}

// One number against its schema range, with the messages listed at schema::Bound.
void checkNumber(Checker& check, const std::string& path, double v, const schema::Range& r) {
    using schema::Bound;
    switch (r.bound) {
        case Bound::None:
            break;
        case Bound::Positive:
            if (check.positive(path, v, r.max) && r.min > 0.0) check.atLeast(path, v, r.min);
            break;
        case Bound::NonNegative:
            check.nonNegative(path, v, r.max);
            break;
        case Bound::Symmetric:
            check.magnitude(path, v, r.max);
            break;
        case Bound::UnitInterval:
            check.unitInterval(path, v);
            break;
        case Bound::PositiveUpTo:
            if (check.finite(path, v) && !(v > 0.0 && v <= r.max))
                check.fail(path, "must be > 0 and <= " + fmt(r.max) + " (got " + fmt(v) + ")");
            break;
        case Bound::IntegerAtLeast:
            if (v < r.min)
                check.fail(path, "must be an integer >= " + integerText(r.min));
            else if (v > r.max)
                check.fail(path, "must be <= " + integerText(r.max));
            break;
        case Bound::IntegerBetween:
            if (check.finite(path, v) && (v < r.min || v > r.max || v != std::floor(v)))
                check.fail(path, "must be an integer between " + integerText(r.min) + " and " +
                                     integerText(r.max));
            break;
    }
}

void checkDirection(Checker& check, const std::string& path, const Point2& p) {
    // The normal is normalised on load: a length that squares to zero or to infinity would
    // make it NaN, so its length must be representable (its bound is checked before this).
    const double length = std::hypot(p[0], p[1]);
    if (p[0] == 0.0 && p[1] == 0.0)
        check.fail(path, "must be non-zero");
    else if (std::isfinite(length) && length < L::kMinNormalLength)
        check.fail(path, "is too short to give a direction (length " + fmt(length) + "; at least " +
                             fmt(L::kMinNormalLength) + ")");
}

// [lower, upper] (a hinge's limits): each number has had its range checked.
void checkInterval(Checker& check, const std::string& path, const Point2& p) {
    if (std::isfinite(p[0]) && std::isfinite(p[1]) && p[0] > p[1])
        check.fail(path, "must be [lower, upper] with lower <= upper (got [" + fmt(p[0]) + ", " +
                             fmt(p[1]) + "])");
}

std::string joinNames(std::span<const std::string_view> names) {
    std::string out;
    for (std::string_view name : names) out += (out.empty() ? "" : ", ") + std::string(name);
    return out;
}

// The contact solver's settings (engine-defined); others are ignored like any unknown key.
void checkSolver(Checker& check, const std::string& path,
                 const std::map<std::string, double>& solver) {
    for (const auto& [key, value] : solver) {
        const std::string at = path + "." + key;
        if (!check.finite(at, value)) continue;
        for (const schema::SolverSetting& setting : schema::solverSettings())
            if (setting.key == key) checkNumber(check, at, value, setting.range);
    }
}

// A polygon's vertices (CONTRACT §6): 3 to 16, convex, either winding, no three in a line, with
// an area; the vertex where that fails is named (`polygons[2].vertices[4]: the polygon is not
// convex here`). Turning the same way at every vertex is not enough (a star turns the same way
// twice round), so the turns must also add up to one full turn.
void checkPolygon(Checker& check, const std::string& path, const std::vector<Point2>& v) {
    const std::size_t n = v.size();
    if (n < 3 || n > static_cast<std::size_t>(L::kMaxPolygonVertices)) {
        check.fail(path, "must have 3 to " + std::to_string(L::kMaxPolygonVertices) +
                             " vertices (got " + std::to_string(n) + ")");
        return;
    }
    for (const Point2& p : v)
        if (!std::isfinite(p[0]) || !std::isfinite(p[1])) return;  // reported by the ranges
    double size = 0.0;
    for (const Point2& p : v) size = std::max({size, std::abs(p[0]), std::abs(p[1])});
    const auto edge = [&](std::size_t i) {
        const Point2& a = v[i];
        const Point2& b = v[(i + 1) % n];
        return std::array<double, 2>{b[0] - a[0], b[1] - a[1]};
    };
    for (std::size_t i = 0; i < n; ++i) {
        const auto in = edge((i + n - 1) % n);
        if (!(std::hypot(in[0], in[1]) > 1e-12 * size)) {
            check.fail(at(path, i), "repeats the vertex before it");
            return;
        }
    }
    double sign = 0.0, turning = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto in = edge((i + n - 1) % n), out = edge(i);
        const double lengths = std::hypot(in[0], in[1]) * std::hypot(out[0], out[1]);
        const double cross = in[0] * out[1] - in[1] * out[0];
        const std::string here = at(path, i);
        if (!(std::abs(cross) > 1e-9 * lengths)) {
            check.fail(here, "three vertices in a line here");
            return;
        }
        if (sign == 0.0) sign = cross > 0.0 ? 1.0 : -1.0;
        if (cross * sign < 0.0) {
            check.fail(here, "the polygon is not convex here");
            return;
        }
        turning += std::atan2(cross, in[0] * out[0] + in[1] * out[1]);
    }
    if (!(std::abs(std::abs(turning) - 2.0 * std::numbers::pi) < 1e-6)) {
        check.fail(path, "the polygon is not convex: its edges cross");
        return;
    }
    // The size floor boxes have (kMinBoxSize on each side): a polygon's thinnest extent, its
    // width across the edge it is narrowest over (a convex polygon's width is least flush with
    // an edge), as a box's is its shorter side. Below it the moment of inertia (∝ size⁴·ρ)
    // leaves the range the solvers are accurate in: a 1e-9 triangle loaded and diverged.
    double width = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
        const auto e = edge(i);
        const double length = std::hypot(e[0], e[1]);
        double across = 0.0;
        for (const Point2& p : v)
            across = std::max(across,
                              std::abs(e[0] * (p[1] - v[i][1]) - e[1] * (p[0] - v[i][0])) / length);
        width = std::min(width, across);
    }
    if (!(width >= L::kMinBoxSize))
        check.fail(path, "the polygon is too small: its width is " + fmt(width) +
                             " m; it must be at least " + fmt(L::kMinBoxSize) +
                             " m across, as a box's sides must");
}

}  // namespace

// Every field of d whose table gives a range or rule, in the table's order; arrays of nested
// objects after the plain fields. Strings, booleans and a cloth's pinning are the callers'.
template <typename D>
void checkFields(Checker& check, const std::string& path, const D& d) {
    const schema::Table<D>& table = schema::table<D>();
    for (const bool arrays : {false, true}) {
        for (const schema::Field<D>& f : table.fields) {
            if ((f.type == schema::Type::ObjectArray) != arrays || !schema::isPresent(f, d))
                continue;
            const std::string here = join(path, f.key);
            std::visit(
                [&]<typename V>(V D::*member) {
                    const V& v = d.*member;
                    if constexpr (std::is_same_v<V, double> || std::is_same_v<V, int>) {
                        checkNumber(check, here, v, f.range);
                    } else if constexpr (std::is_same_v<V, std::optional<double>>) {
                        checkNumber(check, here, *v, f.range);
                    } else if constexpr (std::is_same_v<V, Point2> ||
                                         std::is_same_v<V, std::optional<Point2>> ||
                                         std::is_same_v<V, std::array<int, 2>>) {
                        const auto& pair = [&]() -> const auto& {
                            if constexpr (std::is_same_v<V, std::optional<Point2>>)
                                return *v;
                            else
                                return v;
                        }
                        ();
                        for (std::size_t k = 0; k < 2; ++k)
                            checkNumber(check, here + "[" + std::to_string(k) + "]", pair[k],
                                        f.range);
                        if constexpr (!std::is_same_v<V, std::array<int, 2>>) {
                            if (f.rule == schema::Rule::NonZeroDirection)
                                checkDirection(check, here, pair);
                            if (f.type == schema::Type::Interval) checkInterval(check, here, pair);
                        }
                    } else if constexpr (schema::Described<V>) {
                        checkFields(check, here, v);
                    } else if constexpr (schema::OptionalDescribed<V>) {
                        checkFields(check, here, *v);
                    } else if constexpr (std::is_enum_v<V>) {
                        // Only a description made in code can hold a value past the names.
                        if (static_cast<std::size_t>(v) >= f.choices.size())
                            check.fail(here, "must be one of " + joinNames(f.choices));
                    } else if constexpr (std::is_same_v<V, std::vector<AttractorDesc>>) {
                        for (std::size_t i = 0; i < v.size(); ++i)
                            checkFields(check, at(here, i), v[i]);
                    } else if constexpr (std::is_same_v<V, std::map<std::string, double>>) {
                        checkSolver(check, here, v);
                    } else if constexpr (std::is_same_v<V, std::vector<Point2>>) {
                        for (std::size_t i = 0; i < v.size(); ++i)
                            for (std::size_t k = 0; k < 2; ++k)
                                checkNumber(check, at(here, i) + "[" + std::to_string(k) + "]",
                                            v[i][k], f.range);
                    } else if constexpr (std::is_same_v<V, std::string>) {
                        if (f.rule == schema::Rule::KnownIntegrator && !findIntegrator(v))
                            check.fail(here, "unknown integrator " + quoted(v) +
                                                 "; known: " + knownIntegratorNames());
                    }
                },
                f.member);
        }
    }
}

// JointValidation.cpp checks a joint's fields through this one.
template void checkFields(Checker& check, const std::string& path, const JointDesc& d);

}  // namespace validation

using namespace validation;

std::vector<SceneIssue> validatePolygonVertices(const std::vector<Point2>& vertices,
                                                const std::string& path) {
    std::vector<SceneIssue> issues;
    Checker check(issues);
    for (std::size_t i = 0; i < vertices.size(); ++i)
        for (int k = 0; k < 2; ++k)
            if (!std::isfinite(vertices[i][k])) check.fail(at(path, i), "must be a finite number");
    if (issues.empty()) checkPolygon(check, path, vertices);
    return issues;
}

namespace {

// Sizes: past these limits a scene is refused rather than allowed to exhaust memory or hang (the
// limits are documented in docs/scene-format.md). Returns whether the scene has more particles
// (cloth nodes included) than allowed, when checking the rest object by object is pointless.
bool checkSizes(Checker& check, const SceneDesc& scene) {
    namespace key = schema::key;
    const EffectsDesc& fx = scene.effects;
    const std::string effects(key::effects);
    long long clothNodes = 0;
    bool tooManyClothNodes = false;
    for (std::size_t i = 0; i < scene.cloths.size(); ++i) {
        const ClothDesc& cl = scene.cloths[i];
        const long long nodes =
            static_cast<long long>(std::max(0, cl.resolution[0])) * std::max(0, cl.resolution[1]);
        clothNodes += nodes;
        // Named at the cloth that crosses the limit, with the limit and its square side.
        if (clothNodes > SceneLimits::kMaxClothNodes && !tooManyClothNodes) {
            tooManyClothNodes = true;
            const long long side = std::llround(std::sqrt(double(SceneLimits::kMaxClothNodes)));
            check.fail(join(at(key::cloths, i), key::resolution),
                       "the cloth has " + std::to_string(nodes) + " nodes (" +
                           std::to_string(cl.resolution[0]) + " x " +
                           std::to_string(cl.resolution[1]) + ")" +
                           (clothNodes > nodes
                                ? ", " + std::to_string(clothNodes) + " with the cloths before it"
                                : std::string()) +
                           "; at most " + std::to_string(SceneLimits::kMaxClothNodes) +
                           " cloth nodes (" + std::to_string(side) + " x " + std::to_string(side) +
                           ") are allowed in a scene");
        }
    }
    const long long particleCount = static_cast<long long>(scene.particles.size()) + clothNodes;
    if (particleCount > SceneLimits::kMaxParticles && !tooManyClothNodes)
        check.fail(std::string(scene.cloths.empty() ? key::particles : key::cloths),
                   "the scene has " + std::to_string(particleCount) +
                       " particles (cloth nodes included); at most " +
                       std::to_string(SceneLimits::kMaxParticles) + " are allowed");
    const long long charged = std::count_if(scene.particles.begin(), scene.particles.end(),
                                            [](const ParticleDesc& p) { return p.charge != 0.0; });
    if (charged > SceneLimits::kMaxChargedParticles)
        check.fail(std::string(key::particles),
                   "the scene has " + std::to_string(charged) + " charged particles; at most " +
                       std::to_string(SceneLimits::kMaxChargedParticles) +
                       " are allowed (Coulomb's law acts between every pair of them)");
    if ((fx.particleCollisions || fx.flocking) &&
        particleCount > SceneLimits::kMaxInteractingParticles && !tooManyClothNodes &&
        particleCount <= SceneLimits::kMaxParticles)
        check.fail(join(effects, fx.particleCollisions ? key::particleCollisions : key::flocking),
                   "the scene has " + std::to_string(particleCount) +
                       " particles (cloth nodes included); with particle_collisions or flocking "
                       "at most " +
                       std::to_string(SceneLimits::kMaxInteractingParticles) +
                       " are allowed (either acts between every pair of particles near each "
                       "other)");
    if (const std::string problem = substepWorkProblem(scene, scene.simulation.substeps);
        !problem.empty() && !tooManyClothNodes && particleCount <= SceneLimits::kMaxParticles)
        check.fail(join(std::string(key::simulation), key::substeps), problem);
    if (static_cast<long long>(scene.boxes.size() + scene.disks.size() + scene.polygons.size()) >
        SceneLimits::kMaxRigidBodies)
        check.fail(std::string(!scene.polygons.empty() ? key::polygons
                               : !scene.disks.empty()  ? key::disks
                                                       : key::boxes),
                   "at most " + std::to_string(SceneLimits::kMaxRigidBodies) +
                       " rigid bodies (boxes, disks and polygons) are allowed");
    if (static_cast<long long>(scene.springs.size()) > SceneLimits::kMaxSprings)
        check.fail(std::string(key::springs),
                   "at most " + std::to_string(SceneLimits::kMaxSprings) + " springs are allowed");
    if (static_cast<long long>(scene.planes.size()) > SceneLimits::kMaxPlanes)
        check.fail(std::string(key::planes),
                   "at most " + std::to_string(SceneLimits::kMaxPlanes) + " planes are allowed");
    if (static_cast<long long>(scene.joints.size()) > SceneLimits::kMaxJoints)
        check.fail(std::string(key::joints),
                   "at most " + std::to_string(SceneLimits::kMaxJoints) + " joints are allowed");
    return particleCount > SceneLimits::kMaxParticles || tooManyClothNodes;
}

// A cloth's pinned nodes: a known mode, or nodes inside its grid.
void checkClothPinning(Checker& check, const std::string& path, const ClothDesc& cl) {
    namespace key = schema::key;
    const std::string pinned = join(path, key::pinned);
    if (const auto* mode = std::get_if<std::string>(&cl.pinned)) {
        if (*mode != "top" && *mode != "top_corners" && *mode != "left" && *mode != "none")
            check.fail(pinned, "unknown pinning " + quoted(*mode) +
                                   "; known: top, top_corners, left, none");
    } else {
        const auto& nodes = std::get<std::vector<std::array<int, 2>>>(cl.pinned);
        for (std::size_t k = 0; k < nodes.size(); ++k) {
            const auto [i, j] = nodes[k];
            if (i < 0 || i >= cl.resolution[0] || j < 0 || j >= cl.resolution[1])
                check.fail(at(pinned, k), "node [" + std::to_string(i) + "," + std::to_string(j) +
                                              "] is outside the " +
                                              std::to_string(cl.resolution[0]) + "x" +
                                              std::to_string(cl.resolution[1]) + " grid");
        }
    }
}

}  // namespace

std::vector<SceneIssue> validateScene(const SceneDesc& scene) {
    namespace key = schema::key;
    std::vector<SceneIssue> issues;
    Checker check(issues);

    // Every field against its range in the schema; what ties fields together follows.
    const SimulationDesc& sim = scene.simulation;
    checkFields(check, std::string(key::simulation), sim);
    const EffectsDesc& fx = scene.effects;
    const std::string effects(key::effects);
    schema::forEachEffect([&](const auto& table, auto member) {
        const auto& effect = fx.*member;
        if (!effect) return;
        checkFields(check, join(effects, table.key), *effect);
        if constexpr (std::is_same_v<std::decay_t<decltype(*effect)>, BuoyancyDesc>)
            if (!fx.gravity) check.fail(join(effects, table.key), "needs the gravity effect");
    });

    // Past the size limits, the rest would check (and name) a million objects one by one.
    if (checkSizes(check, scene) && !issues.empty()) return issues;

    // ids: unique across the scene (cloth node ids included); springs and joints may refer to
    // particles, boxes, disks, polygons and cloth nodes. Each id remembers who holds it, for the
    // messages.
    std::map<std::string, std::string> ids;  // id → path of its holder
    std::unordered_set<std::string> bodies;
    auto claim = [&](const std::string& path, const std::string& id, bool body, bool isDefault) {
        const auto [it, fresh] = ids.emplace(id, path);
        if (!fresh) {
            if (isDefault)
                check.fail(path, "the default id " + quoted(id) + " is already used by " +
                                     it->second + "; give this object an id");
            else
                check.fail(join(path, key::id),
                           "duplicate id " + quoted(id) + " (also used by " + it->second + ")");
        }
        if (body) bodies.insert(id);
    };

    auto objects = [&](std::string_view array, const auto& items, auto idOf, bool body) {
        for (std::size_t i = 0; i < items.size(); ++i) {
            const std::string path = at(array, i);
            claim(path, idOf(scene, i), body, items[i].id.empty());
            checkFields(check, path, items[i]);
        }
    };
    objects(key::particles, scene.particles, particleId, true);
    objects(key::boxes, scene.boxes, boxId, true);
    objects(key::disks, scene.disks, diskId, true);
    objects(key::polygons, scene.polygons, polygonId, true);
    for (std::size_t i = 0; i < scene.polygons.size(); ++i)
        checkPolygon(check, join(at(key::polygons, i), key::vertices), scene.polygons[i].vertices);
    objects(key::planes, scene.planes, planeId, false);
    for (std::size_t c = 0; c < scene.cloths.size(); ++c) {
        const ClothDesc& cl = scene.cloths[c];
        const std::string path = at(key::cloths, c);
        if (cl.id.empty())
            check.fail(join(path, key::id), "is required");
        else
            claim(path, cl.id, false, false);
        checkFields(check, path, cl);
        checkClothPinning(check, path, cl);
        if (!cl.id.empty() && cl.resolution[0] >= 2 && cl.resolution[1] >= 2)
            for (int j = 0; j < cl.resolution[1]; ++j)
                for (int i = 0; i < cl.resolution[0]; ++i)
                    claim(path, clothNodeId(cl.id, i, j), true, false);
    }
    // Whether id names a body; if not, says so at where. what: who refers to it, and to what.
    auto reference = [&](const std::string& where, const std::string& id, std::string_view what) {
        if (bodies.count(id)) return true;
        const auto it = ids.find(id);
        if (it == ids.end())
            check.fail(where, "unknown object id " + quoted(id));
        else
            check.fail(where, quoted(id) + " is " + it->second + "; " + std::string(what) +
                                  " particles, boxes, disks, polygons and cloth nodes");
        return false;
    };
    for (std::size_t i = 0; i < scene.springs.size(); ++i) {
        const SpringDesc& s = scene.springs[i];
        const std::string path = at(key::springs, i);
        claim(path, springId(scene, i), false, s.id.empty());
        const std::string a = join(path, key::a), b = join(path, key::b);
        if (s.a.empty())
            check.fail(a, "is required");
        else
            reference(a, s.a, "springs attach to");
        if (s.b && s.anchor)
            check.fail(path, "has both b and anchor; give one");
        else if (!s.b && !s.anchor)
            check.fail(path, "needs either b (an object id) or anchor [x, y]");
        if (s.b) reference(b, *s.b, "springs attach to");
        if (s.b && *s.b == s.a) check.fail(b, "must differ from a");
        checkFields(check, path, s);
    }
    if (!scene.joints.empty()) checkJoints(check, scene, claim, reference);
    validateInstrumentValues(scene.instruments, issues);
    return issues;
}

}  // namespace phasebox
