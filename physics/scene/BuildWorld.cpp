#include "physics/scene/BuildWorld.h"

#include "physics/effects/BuoyancyEffect.h"
#include "physics/effects/CoulombEffect.h"
#include "physics/effects/DragEffect.h"
#include "physics/effects/FlockingEffect.h"
#include "physics/effects/GravityEffect.h"
#include "physics/effects/NewtonianGravityEffect.h"
#include "physics/effects/WindEffect.h"
#include "physics/scene/InstrumentValidation.h"
#include "physics/scene/SceneSchema.h"

#include <algorithm>
#include <unordered_map>

namespace phasebox {

namespace {
Vec2 vec(const Point2& p) {
    return {p[0], p[1]};
}

std::string summarize(const std::vector<SceneIssue>& issues) {
    std::string out;
    for (const SceneIssue& issue : issues) {
        if (!out.empty()) out += "\n";
        out += issue.path + ": " + issue.message;
    }
    return out;
}

bool isPinned(const std::string& mode, int nx, int i, int j) {
    if (mode == "top") return j == 0;
    if (mode == "top_corners") return j == 0 && (i == 0 || i == nx - 1);
    if (mode == "left") return i == 0;
    return false;
}

// Which nodes are pinned, node (i, j) at j·nx + i. An explicit list is read once: looking every
// node up in it costs nodes × list entries, hours for a 1000 × 1000 cloth that lists its nodes
// (a generated or hostile file can).
std::vector<char> pinnedNodes(const ClothDesc& cloth) {
    const int nx = cloth.resolution[0], ny = cloth.resolution[1];
    std::vector<char> pinned(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), 0);
    if (const auto* mode = std::get_if<std::string>(&cloth.pinned)) {
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                pinned[static_cast<std::size_t>(j) * nx + i] = isPinned(*mode, nx, i, j);
        return pinned;
    }
    for (const auto& [i, j] : std::get<std::vector<std::array<int, 2>>>(cloth.pinned))
        if (i >= 0 && i < nx && j >= 0 && j < ny) pinned[static_cast<std::size_t>(j) * nx + i] = 1;
    return pinned;
}

void addClothSprings(World& world, const Cloth& cloth, const ClothDesc& desc) {
    const auto addSpring = [&](int i0, int j0, int i1, int j1, double k) {
        if (i1 >= cloth.nx || j1 >= cloth.ny || k <= 0.0) return;
        Spring s;
        s.a = {SpringEnd::Kind::Particle, clothNode(cloth, i0, j0), Vec2::Zero()};
        s.b = {SpringEnd::Kind::Particle, clothNode(cloth, i1, j1), Vec2::Zero()};
        s.stiffness = k;
        s.damping = desc.damping;
        s.restLength =
            (world.particles()[s.a.index].position - world.particles()[s.b.index].position).norm();
        s.cloth = static_cast<int>(world.cloths().size());
        world.addSpring(s);
    };
    const ClothStiffnessDesc& k = desc.stiffness;
    for (int j = 0; j < cloth.ny; ++j) {
        for (int i = 0; i < cloth.nx; ++i) {
            addSpring(i, j, i + 1, j, k.structural);  // structural
            addSpring(i, j, i, j + 1, k.structural);
            addSpring(i, j, i + 1, j + 1, k.shear);  // shear
            if (i + 1 < cloth.nx && j + 1 < cloth.ny) {
                Spring s;
                s.a = {SpringEnd::Kind::Particle, clothNode(cloth, i + 1, j), Vec2::Zero()};
                s.b = {SpringEnd::Kind::Particle, clothNode(cloth, i, j + 1), Vec2::Zero()};
                if (k.shear > 0.0) {
                    s.stiffness = k.shear;
                    s.damping = desc.damping;
                    s.restLength = (world.particles()[s.a.index].position -
                                    world.particles()[s.b.index].position)
                                       .norm();
                    s.cloth = static_cast<int>(world.cloths().size());
                    world.addSpring(s);
                }
            }
            addSpring(i, j, i + 2, j, k.bend);  // bend
            addSpring(i, j, i, j + 2, k.bend);
        }
    }
}

// Coulomb's law has something to do when two particles carry a charge and one of them can move.
bool needsCoulomb(const SceneDesc& scene) {
    int charged = 0;
    bool free = false;
    for (const ParticleDesc& p : scene.particles) {
        if (p.charge == 0.0) continue;
        ++charged;
        free = free || !p.pinned;
    }
    return charged >= 2 && free;
}
}  // namespace

SimulationSettings simulationSettings(const SimulationDesc& sim) {
    return {sim.integrator,       sim.dt,
            sim.substeps,         sim.tolerance,
            sim.newtonIterations, contactSettings(sim.solver),
            sim.contactModel,     sim.contactStiffness.value_or(0.0),
            sim.contactDamping,   sim.sleep};
}

ContactSettings contactSettings(const std::map<std::string, double>& solver) {
    ContactSettings settings;
    auto take = [&](std::string_view key, auto& field) {
        if (const auto it = solver.find(std::string(key)); it != solver.end())
            field = static_cast<std::remove_reference_t<decltype(field)>>(it->second);
    };
    namespace key = schema::key;
    take(key::substeps, settings.substeps);
    take(key::iterations, settings.iterations);
    take(key::relaxIterations, settings.relaxIterations);
    take(key::contactHertz, settings.hertz);
    take(key::dampingRatio, settings.dampingRatio);
    take(key::pushOut, settings.pushOut);
    take(key::restitutionThreshold, settings.restitutionThreshold);
    take(key::speculativeDistance, settings.speculativeDistance);
    return settings;
}

SceneError::SceneError(std::vector<SceneIssue> issues)
    : std::runtime_error(summarize(issues)), issues_(std::move(issues)) {}

namespace {

// Where an object id is, for the springs and joints that name it.
using EndsById = std::unordered_map<std::string, SpringEnd>;

// Effects the scene lists, in the contract's order.
void addEffects(World& world, const SceneDesc& scene) {
    const EffectsDesc& fx = scene.effects;
    if (fx.gravity) world.addEffect(std::make_unique<GravityEffect>(vec(fx.gravity->g)));
    if (fx.drag)
        world.addEffect(
            std::make_unique<DragEffect>(fx.drag->linear, fx.drag->quadratic, fx.drag->angular));
    if (fx.newtonianGravity) {
        std::vector<Attractor> attractors;
        for (const AttractorDesc& a : fx.newtonianGravity->attractors)
            attractors.push_back({vec(a.position), a.mass});
        world.addEffect(std::make_unique<NewtonianGravityEffect>(
            fx.newtonianGravity->G, std::move(attractors), fx.newtonianGravity->mutual,
            fx.newtonianGravity->softening));
    }
    if (fx.buoyancy) {
        // validateScene() has made sure gravity is there: the fluid's weight is what lifts.
        const Vec2 g = fx.gravity ? vec(fx.gravity->g) : Vec2::Zero();
        world.addEffect(std::make_unique<BuoyancyEffect>(
            fx.buoyancy->fluidDensity, fx.buoyancy->surfaceY, fx.buoyancy->drag, g.norm()));
    }
    if (fx.wind)
        world.addEffect(std::make_unique<WindEffect>(vec(fx.wind->velocity), fx.wind->drag));
    if (fx.flocking) {
        const FlockingDesc& f = *fx.flocking;
        world.addEffect(std::make_unique<FlockingEffect>(
            FlockingParameters{f.radius, f.separation, f.alignment, f.cohesion, f.maxSpeed}));
    }
    // Coulomb's law is implied by the charges, as the spring force is by springs.
    if (needsCoulomb(scene)) {
        const CoulombDesc coulomb = fx.coulomb.value_or(CoulombDesc{});
        world.addEffect(std::make_unique<CoulombEffect>(coulomb.k, coulomb.softening));
    }
    if (fx.particleCollisions)
        world.setParticleCollisions(true, fx.particleCollisions->restitution);
}

void addParticles(World& world, const SceneDesc& scene, EndsById& ends) {
    for (std::size_t i = 0; i < scene.particles.size(); ++i) {
        const ParticleDesc& d = scene.particles[i];
        Particle p;
        p.id = particleId(scene, i);
        p.position = vec(d.position);
        p.velocity = vec(d.velocity);
        p.mass = d.mass;
        p.radius = d.radius;
        p.pinned = d.pinned;
        p.restitution = d.restitution;
        p.friction = d.friction;
        p.charge = d.charge;
        ends[p.id] = {SpringEnd::Kind::Particle, world.addParticle(p), Vec2::Zero()};
    }
}

// Boxes, polygons and disks, in that order: the rigid bodies share one array in the world.
void addRigidBodies(World& world, const SceneDesc& scene, EndsById& ends) {
    // A rigid body (box or disk) from what every rigid kind's description holds.
    const auto rigid = [&](const auto& d, std::string id) {
        RigidBody b;
        b.id = std::move(id);
        b.position = vec(d.position);
        b.angle = d.angle;
        b.velocity = vec(d.velocity);
        b.angularVelocity = d.angularVelocity;
        b.mass = d.resolvedMass();
        b.inertia = d.momentOfInertia();
        b.isStatic = d.isStatic;
        b.friction = d.friction;
        b.restitution = d.restitution;
        return b;
    };
    const auto addRigid = [&](const RigidBody& b) {
        ends[b.id] = {SpringEnd::Kind::Rigid, world.addRigidBody(b), Vec2::Zero()};
    };
    for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
        RigidBody b = rigid(scene.boxes[i], boxId(scene, i));
        b.size = vec(scene.boxes[i].size);
        addRigid(b);
    }
    for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
        const PolygonDesc& d = scene.polygons[i];
        RigidBody b = rigid(d, polygonId(scene, i));
        b.shape = RigidShape::Polygon;
        // About the centroid (recentrePolygons moved the frame there), counter-clockwise.
        double reach = 0.0;
        for (const Point2& v : d.vertices) {
            b.vertices.emplace_back(v[0], v[1]);
            reach = std::max(reach, b.vertices.back().norm());
        }
        double signedArea = 0.0;
        for (std::size_t k = 0; k < b.vertices.size(); ++k)
            signedArea += cross(b.vertices[k], b.vertices[(k + 1) % b.vertices.size()]);
        if (signedArea < 0.0) std::reverse(b.vertices.begin(), b.vertices.end());
        b.inradius = reach;
        for (std::size_t k = 0; k < b.vertices.size(); ++k) {
            const Vec2 e = b.vertices[(k + 1) % b.vertices.size()] - b.vertices[k];
            b.normals.push_back(Vec2(e.y(), -e.x()).normalized());
            b.inradius = std::min(b.inradius, b.normals.back().dot(b.vertices[k]));
        }
        b.size = Vec2::Constant(2.0 * reach);
        addRigid(b);
    }
    for (std::size_t i = 0; i < scene.disks.size(); ++i) {
        RigidBody b = rigid(scene.disks[i], diskId(scene, i));
        b.shape = RigidShape::Disk;
        b.radius = scene.disks[i].radius;
        b.size = Vec2::Constant(2.0 * b.radius);
        addRigid(b);
    }
}

void addPlanes(World& world, const SceneDesc& scene) {
    for (std::size_t i = 0; i < scene.planes.size(); ++i) {
        const PlaneDesc& d = scene.planes[i];
        Plane p;
        p.id = planeId(scene, i);
        p.point = vec(d.point);
        p.normal = vec(d.normal).normalized();
        p.friction = d.friction;
        p.restitution = d.restitution;
        world.addPlane(p);
    }
}

// Each cloth's nodes as particles (row by row), then its springs.
void addCloths(World& world, const SceneDesc& scene, EndsById& ends) {
    for (const ClothDesc& d : scene.cloths) {
        Cloth cloth;
        cloth.id = d.id;
        cloth.nx = d.resolution[0];
        cloth.ny = d.resolution[1];
        cloth.firstParticle = static_cast<int>(world.particles().size());
        cloth.firstSpring = static_cast<int>(world.springs().size());
        const double nodeMass = d.mass / (static_cast<double>(cloth.nx) * cloth.ny);
        const double dx = d.size[0] / (cloth.nx - 1), dy = d.size[1] / (cloth.ny - 1);
        const std::vector<char> pinned = pinnedNodes(d);
        for (int j = 0; j < cloth.ny; ++j) {
            for (int i = 0; i < cloth.nx; ++i) {
                Particle p;
                p.id = clothNodeId(d.id, i, j);
                p.position = {d.origin[0] + i * dx, d.origin[1] - j * dy};
                p.mass = nodeMass;
                p.radius = d.radius;
                p.pinned = pinned[static_cast<std::size_t>(j) * cloth.nx + i] != 0;
                p.cloth = static_cast<int>(world.cloths().size());
                ends[p.id] = {SpringEnd::Kind::Particle, world.addParticle(p), Vec2::Zero()};
            }
        }
        addClothSprings(world, cloth, d);
        cloth.springCount = static_cast<int>(world.springs().size()) - cloth.firstSpring;
        world.addCloth(cloth);
    }
}

// A spring without a rest length rests at its ends' distance in the scene.
void addSprings(World& world, const SceneDesc& scene, const EndsById& ends) {
    for (std::size_t i = 0; i < scene.springs.size(); ++i) {
        const SpringDesc& d = scene.springs[i];
        Spring s;
        s.id = springId(scene, i);
        s.a = ends.at(d.a);
        s.a.point = vec(d.aPoint);
        if (d.b) {
            s.b = ends.at(*d.b);
            s.b.point = vec(d.bPoint);
        } else {
            s.b = {SpringEnd::Kind::Anchor, -1, vec(*d.anchor)};
        }
        s.stiffness = d.stiffness;
        s.damping = d.damping;
        s.restLength = d.restLength
                           ? *d.restLength
                           : (world.springEndPosition(s.a) - world.springEndPosition(s.b)).norm();
        world.addSpring(s);
    }
}

void addJoints(World& world, const SceneDesc& scene, const EndsById& ends) {
    // Joints: their points are resolved against the bodies where the scene sets them.
    const auto position = [&](const JointBody& body) -> Vec2 {
        switch (body.kind) {
            case JointBody::Kind::Particle:
                return world.particles()[body.index].position;
            case JointBody::Kind::Rigid: {
                const RigidBody& b = world.rigidBodies()[body.index];
                return b.position + rotation(b.angle) * body.point;
            }
            case JointBody::Kind::World:
                break;
        }
        return body.point;
    };
    const auto angle = [&](const JointBody& body) {
        return body.kind == JointBody::Kind::Rigid ? world.rigidBodies()[body.index].angle : 0.0;
    };
    // The point of body at a world point w (a rigid body's frame; the world's is w itself).
    const auto pointAt = [&](JointBody& body, const Vec2& w) {
        if (body.kind == JointBody::Kind::Rigid) {
            const RigidBody& b = world.rigidBodies()[body.index];
            body.point = rotation(-b.angle) * (w - b.position);
        } else if (body.kind == JointBody::Kind::World) {
            body.point = w;
        }
    };
    for (std::size_t i = 0; i < scene.joints.size(); ++i) {
        const JointDesc& d = scene.joints[i];
        Joint j;
        j.id = jointId(scene, i);
        const auto body = [&](const std::string& id, const Point2& point) {
            const SpringEnd& e = ends.at(id);
            return e.kind == SpringEnd::Kind::Particle
                       ? JointBody{JointBody::Kind::Particle, e.index, Vec2::Zero()}
                       : JointBody{JointBody::Kind::Rigid, e.index, vec(point)};
        };
        j.a = body(d.a, d.aPoint);
        j.b = d.b ? body(*d.b, d.bPoint)
                  : JointBody{JointBody::Kind::World, -1, d.anchor ? vec(*d.anchor) : Vec2::Zero()};
        switch (d.type) {
            case JointType::Hinge:
            case JointType::Weld: {
                j.type = d.type == JointType::Hinge ? Joint::Type::Hinge : Joint::Type::Weld;
                // A hinge's pivot is its anchor; a weld holds at a's centre.
                const Vec2 pivot = d.type == JointType::Hinge && d.anchor
                                       ? vec(*d.anchor)
                                       : position(JointBody{j.a.kind, j.a.index, Vec2::Zero()});
                pointAt(j.a, pivot);
                pointAt(j.b, pivot);
                j.offset = position(j.a) - position(j.b);  // nonzero only for particle ends
                j.referenceAngle = angle(j.b) - angle(j.a);
                if (d.limits) {
                    j.hasLimits = true;
                    j.lower = (*d.limits)[0];
                    j.upper = (*d.limits)[1];
                }
                if (d.motor) {
                    j.hasMotor = true;
                    j.motorSpeed = d.motor->speed;
                    j.maxMotorTorque = d.motor->maxTorque;
                }
                break;
            }
            case JointType::Rod:
            case JointType::Rope:
                j.type = d.type == JointType::Rod ? Joint::Type::Rod : Joint::Type::Rope;
                j.length = d.length ? *d.length : (position(j.a) - position(j.b)).norm();
                break;
            case JointType::Pulley:
                j.type = Joint::Type::Pulley;
                j.groundA = vec(d.groundA);
                j.groundB = vec(d.groundB);
                j.ratio = d.ratio;
                j.length = (position(j.a) - j.groundA).norm() +
                           j.ratio * (position(j.b) - j.groundB).norm();
                break;
            case JointType::Track:
                j.type = Joint::Type::Track;
                j.b = JointBody{};
                if (d.circle) {
                    j.circle = true;
                    j.center = vec(d.circle->center);
                    j.radius = d.circle->radius;
                } else if (d.line) {
                    j.circle = false;
                    j.linePoint = vec(d.line->point);
                    const Vec2 dir = vec(d.line->direction).normalized();
                    j.lineNormal = Vec2(-dir.y(), dir.x());
                }
                break;
        }
        world.addJoint(j);
    }
}

}  // namespace

BuildResult buildWorld(const SceneDesc& setup) {
    if (auto issues = validateScene(setup); !issues.empty()) throw SceneError(std::move(issues));
    // A polygon's state is its centroid's: a description not read from a file (a test's, the
    // library's) may not be centred yet.
    SceneDesc centred;
    if (!setup.polygons.empty()) {
        centred = setup;
        recentrePolygons(centred);
    }
    const SceneDesc& scene = setup.polygons.empty() ? setup : centred;

    BuildResult result;
    result.world = std::make_unique<World>();
    World& world = *result.world;

    addEffects(world, scene);
    // Objects. Ids map to particle or box indices for the springs and joints.
    EndsById ends;
    addParticles(world, scene, ends);
    addRigidBodies(world, scene, ends);
    addPlanes(world, scene);
    addCloths(world, scene, ends);
    addSprings(world, scene, ends);
    addJoints(world, scene, ends);

    world.setSettings(simulationSettings(scene.simulation));
    world.commit();
    // The instruments name objects and joints, which only the world resolves.
    if (auto issues = checkInstruments(scene.instruments, world); !issues.empty())
        throw SceneError(std::move(issues));
    return result;
}

}  // namespace phasebox
