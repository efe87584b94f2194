// validateScene()'s checks of the joints: their ids and the bodies they hold, then what each
// type of joint needs of its fields and of the setup at load (a hinge's anchor, a rod's two ends
// apart, a pulley's rope with a direction, a track's particle and curve). The bodies are found
// by id, cloth nodes included, where the scene places them at load.
#include "physics/scene/ValidationChecks.h"

#include "physics/scene/SceneSchema.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <unordered_map>

namespace phasebox::validation {

namespace {

// A body as the joint checks see it at load: where it is, and whether it moves and turns.
struct BodyAtLoad {
    Point2 position{0.0, 0.0};
    double angle = 0.0;
    bool rigid = false;  // a box, disk or polygon: it has a frame and turns
    bool fixed = false;  // pinned or static

    bool turns() const { return rigid && !fixed; }
    // Where a point given in the body's own frame is (a particle has no frame: its position).
    Point2 pointAt(const Point2& local) const {
        if (!rigid) return position;
        const double c = std::cos(angle), s = std::sin(angle);
        return {position[0] + c * local[0] - s * local[1],
                position[1] + s * local[0] + c * local[1]};
    }
    std::string fixedWord() const { return rigid ? "static" : "pinned"; }
};

// Finds bodies by id, cloth nodes included, without listing every node of every cloth.
class BodiesAtLoad {
public:
    explicit BodiesAtLoad(const SceneDesc& scene) : scene_(scene) {
        for (std::size_t i = 0; i < scene.particles.size(); ++i) {
            const ParticleDesc& p = scene.particles[i];
            bodies_[particleId(scene, i)] = {p.position, 0.0, false, p.pinned};
        }
        const auto rigid = [&](const RigidDesc& d, std::string id) {
            bodies_[std::move(id)] = {d.position, d.angle, true, d.isStatic};
        };
        for (std::size_t i = 0; i < scene.boxes.size(); ++i) rigid(scene.boxes[i], boxId(scene, i));
        for (std::size_t i = 0; i < scene.disks.size(); ++i)
            rigid(scene.disks[i], diskId(scene, i));
        for (std::size_t i = 0; i < scene.polygons.size(); ++i)
            rigid(scene.polygons[i], polygonId(scene, i));
        for (std::size_t c = 0; c < scene.cloths.size(); ++c) cloths_[scene.cloths[c].id] = c;
    }

    // nullopt for an id that is not a body.
    std::optional<BodyAtLoad> find(const std::string& id) const {
        if (const auto it = bodies_.find(id); it != bodies_.end()) return it->second;
        // A cloth node: ID[i,j]. The cloth's id may itself hold brackets, the node's are last.
        const std::size_t open = id.rfind('[');
        if (open == std::string::npos || id.back() != ']') return std::nullopt;
        const auto cloth = cloths_.find(id.substr(0, open));
        if (cloth == cloths_.end()) return std::nullopt;
        int i = -1, j = -1;
        const char* end = id.data() + id.size() - 1;
        const auto [comma, ok] = std::from_chars(id.data() + open + 1, end, i);
        if (ok != std::errc() || comma == end || *comma != ',' ||
            std::from_chars(comma + 1, end, j).ptr != end)
            return std::nullopt;
        const ClothDesc& cl = scene_.cloths[cloth->second];
        const int nx = cl.resolution[0], ny = cl.resolution[1];
        if (i < 0 || i >= nx || j < 0 || j >= ny || nx < 2 || ny < 2) return std::nullopt;
        const Point2 position{cl.origin[0] + i * cl.size[0] / (nx - 1),
                              cl.origin[1] - j * cl.size[1] / (ny - 1)};
        return BodyAtLoad{position, 0.0, false, clothNodePinned(cl, i, j)};
    }

private:
    const SceneDesc& scene_;
    std::unordered_map<std::string, BodyAtLoad> bodies_;
    std::unordered_map<std::string, std::size_t> cloths_;
};

bool finitePoint(const Point2& p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]);
}

// Whether two points computed from the setup are one, up to the rounding of computing them.
bool samePoint(const Point2& p, const Point2& q) {
    if (!finitePoint(p) || !finitePoint(q)) return false;  // the ranges report those
    const double scale =
        std::max({1.0, std::abs(p[0]), std::abs(p[1]), std::abs(q[0]), std::abs(q[1])});
    return std::hypot(p[0] - q[0], p[1] - q[1]) <= 1e-12 * scale;
}

}  // namespace

// The joints (CONTRACT §6): their ids and bodies, then what each type needs of its fields and of
// the setup. claim and reference are validateScene's, for the ids.
void checkJoints(Checker& check, const SceneDesc& scene, const ClaimId& claim,
                 const ReferenceId& reference) {
    namespace key = schema::key;
    const BodiesAtLoad bodies(scene);
    const std::string_view holds = "joints hold";
    for (std::size_t i = 0; i < scene.joints.size(); ++i) {
        const JointDesc& j = scene.joints[i];
        const std::string path = at(key::joints, i);
        const auto here = [&](std::string_view field) { return join(path, field); };
        claim(path, jointId(scene, i), false, j.id.empty());
        bool aKnown = false, bKnown = false;
        if (j.a.empty())
            check.fail(here(key::a), "is required");
        else
            aKnown = reference(here(key::a), j.a, holds);
        if (j.b) bKnown = reference(here(key::b), *j.b, holds);
        if (j.b && *j.b == j.a) {
            check.fail(here(key::b), "must differ from a");
            bKnown = false;
        }
        checkFields(check, path, j);
        if (static_cast<std::size_t>(j.type) >= std::size(schema::kJointTypeNames)) continue;

        // The two ends; b absent is the fixed world. Rules about the setup need both known.
        const std::optional<BodyAtLoad> a = aKnown ? bodies.find(j.a) : std::nullopt;
        const std::optional<BodyAtLoad> b = bKnown ? bodies.find(*j.b) : std::nullopt;
        const bool endsKnown = a && (!j.b || b);
        if (endsKnown && a->fixed && (!b || b->fixed))
            check.fail(path, "a joint needs a dynamic body: " + quoted(j.a) + " is " +
                                 a->fixedWord() + " and " +
                                 (b ? quoted(*j.b) + " is " + b->fixedWord() : "b is the world"));

        switch (j.type) {
            case JointType::Hinge:
                if (!j.anchor) check.fail(here(key::anchor), "is required");
                // The joint angle is θb − θa: with no body that turns it never changes. A free
                // particle has no angle and takes no torque: a motor or a limit against one would
                // turn the other body alone, an external torque out of nowhere.
                if (const char* why =
                        !endsKnown ? nullptr
                        : !a->turns() && !(b && b->turns())
                            ? "neither body can turn, so the joint angle cannot change; limits "
                              "and a motor need a dynamic box, disk or polygon"
                        : (!a->rigid && !a->fixed) || (b && !b->rigid && !b->fixed)
                            ? "a free particle has no angle and takes no torque; limits and a "
                              "motor need both ends to be boxes, disks, polygons or fixed, so "
                              "that their torque acts on both"
                            : nullptr)
                    for (const auto& [field, given] : {std::pair{key::limits, j.limits.has_value()},
                                                       std::pair{key::motor, j.motor.has_value()}})
                        if (given) check.fail(here(field), why);
                break;
            case JointType::Rod:
            case JointType::Rope:
                if (j.b && j.anchor) {
                    check.fail(path, "has both b and anchor; give one");
                } else if (!j.b && !j.anchor) {
                    check.fail(path, "needs either b (an object id) or anchor [x, y]");
                } else if (endsKnown && !j.length) {
                    const Point2 pb = b ? b->pointAt(j.bPoint) : *j.anchor;
                    if (samePoint(a->pointAt(j.aPoint), pb))
                        check.fail(path,
                                   "its two ends start at the same point, so its length would be "
                                   "0; give a length > 0");
                }
                break;
            case JointType::Pulley:
                if (!j.b) {
                    check.fail(here(key::b), "is required: a pulley holds two bodies");
                } else if (endsKnown) {
                    const std::string atLoad =
                        " at load, so the rope there would have no direction";
                    if (samePoint(j.groundA, a->pointAt(j.aPoint)))
                        check.fail(here(key::groundA), "is where the point on a is" + atLoad);
                    if (samePoint(j.groundB, b->pointAt(j.bPoint)))
                        check.fail(here(key::groundB), "is where the point on b is" + atLoad);
                }
                break;
            case JointType::Track:
                if (a && a->rigid)
                    check.fail(here(key::a), quoted(j.a) +
                                                 " is not a particle; a track holds a particle or "
                                                 "a cloth node");
                if (j.b) check.fail(here(key::b), "a track has no b: it holds a on a fixed curve");
                if (j.circle && j.line)
                    check.fail(path, "has both circle and line; give one");
                else if (!j.circle && !j.line)
                    check.fail(path,
                               "needs either circle {center, radius} or line {point, direction}");
                break;
            case JointType::Weld:
                break;
        }
    }
}

}  // namespace phasebox::validation
