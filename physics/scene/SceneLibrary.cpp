#include "physics/scene/SceneLibrary.h"

#include <cmath>
#include <numbers>
#include <random>

namespace phasebox::scenes {

namespace {
// The format's defaults, as a teacher's scene has them: one step per frame of 1/60 s and no
// solver keys. The contact solver takes the inner sub-steps a stack needs by itself.
SceneDesc contactScene(const std::string& name, const std::string& description) {
    SceneDesc s;
    s.name = name;
    s.description = description;
    s.simulation.integrator = "symplectic_euler";
    s.simulation.dt = 1.0 / 60.0;
    s.effects.gravity = GravityDesc{};
    return s;
}

PlaneDesc ground(double friction = 0.6, double restitution = 0.0) {
    PlaneDesc p;
    p.id = "ground";
    p.point = {0.0, 0.0};
    p.normal = {0.0, 1.0};
    p.friction = friction;
    p.restitution = restitution;
    return p;
}

// Builds "prefix" + n without GCC 12's false -Wrestrict alarm on operator+ of a literal.
std::string name(const char* prefix, int n) {
    std::string out(prefix);
    out += std::to_string(n);
    return out;
}

BoxDesc box(const std::string& id, double x, double y, double w, double h) {
    BoxDesc b;
    b.id = id;
    b.position = {x, y};
    b.size = {w, h};
    return b;
}
}  // namespace

SceneDesc untitled() {
    SceneDesc scene;
    scene.name = "Untitled";
    scene.effects.gravity = GravityDesc{};
    PlaneDesc ground;
    ground.id = "ground";
    ground.point = {0.0, -2.0};
    scene.planes.push_back(ground);
    return scene;
}

SceneDesc pyramid(int rows) {
    SceneDesc s = contactScene(name("Pyramid of ", rows) + " rows",
                               "1 m boxes with friction 0.6 stacked into a pyramid. A good "
                               "solver keeps it standing; watch the contact cost per step.");
    s.planes.push_back(ground());
    for (int row = 0; row < rows; ++row) {
        const int count = rows - row;
        for (int i = 0; i < count; ++i) {
            const double x = (i - 0.5 * (count - 1)) * 1.0;
            s.boxes.push_back(box(name("r", row) + name("c", i), x, 0.5 + row, 1.0, 1.0));
        }
    }
    return s;
}

SceneDesc hexagonPyramid(int rows) {
    SceneDesc s = contactScene(name("Pyramid of hexagons, ", rows) + " rows",
                               "Hexagons 1 m across the flats, pointy side up, stacked like a "
                               "honeycomb: each rests in the groove between two below.");
    s.planes.push_back(ground());
    const double r = 1.0 / std::sqrt(3.0);  // centre to corner
    for (int row = 0; row < rows; ++row) {
        const int count = rows - row;
        for (int i = 0; i < count; ++i) {
            PolygonDesc h;
            h.id = name("r", row) + name("h", i);
            h.position = {(i - 0.5 * (count - 1)) * 1.0, r + 1.5 * r * row};
            for (int k = 0; k < 6; ++k) {
                const double a = std::numbers::pi / 2.0 + std::numbers::pi / 3.0 * k;
                h.vertices.push_back({r * std::cos(a), r * std::sin(a)});
            }
            s.polygons.push_back(h);
        }
    }
    return s;
}

SceneDesc tower(int count) {
    SceneDesc s =
        contactScene(name("Tower of ", count) + " boxes",
                     "A single column of 1 m boxes. Tall towers are where solvers drift.");
    s.planes.push_back(ground());
    for (int i = 0; i < count; ++i) s.boxes.push_back(box(name("t", i), 0.0, 0.5 + i, 1.0, 1.0));
    return s;
}

SceneDesc stack(const std::vector<double>& masses) {
    SceneDesc s = contactScene("Heavy on light",
                               "Boxes of very different masses stacked, the "
                               "heaviest on top: a classic solver failure.");
    s.planes.push_back(ground());
    for (std::size_t i = 0; i < masses.size(); ++i) {
        BoxDesc b =
            box(name("m", static_cast<int>(i)), 0.0, 0.5 + static_cast<double>(i), 1.0, 1.0);
        b.mass = masses[i];
        s.boxes.push_back(b);
    }
    return s;
}

SceneDesc bigOnSmall(double ratio) {
    SceneDesc s =
        contactScene("Big on small", "A 2 m box far heavier than the 0.5 m box under it.");
    s.planes.push_back(ground());
    BoxDesc small = box("small", 0.0, 0.25, 0.5, 0.5);
    small.mass = 1.0;
    BoxDesc big = box("big", 0.0, 0.5 + 1.0, 2.0, 2.0);
    big.mass = ratio;
    s.boxes = {small, big};
    return s;
}

SceneDesc ballDrop(double height, double restitution) {
    SceneDesc s = contactScene("Bouncing ball",
                               "A ball dropped on the floor. With restitution e it "
                               "rises to e² of its drop height.");
    // Velocity Verlet is exact in free fall, so the rebound shows the contact law alone;
    // symplectic Euler's own flight error at dt = 1/60 s would lower the top by v·h/2 (3 cm).
    s.simulation.integrator = "velocity_verlet";
    s.planes.push_back(ground(0.2, 0.0));
    ParticleDesc p;
    p.id = "ball";
    p.radius = 0.1;
    p.position = {0.0, height + p.radius};
    p.restitution = restitution;
    s.particles.push_back(p);
    return s;
}

SceneDesc incline(double degrees, double friction) {
    SceneDesc s = contactScene("Box on an incline",
                               "A box on a slope: it holds when tan θ ≤ μ, "
                               "else it slides with a = g·(sin θ − μ·cos θ).");
    const double theta = degrees * std::numbers::pi / 180.0;
    PlaneDesc slope;
    slope.id = "slope";
    slope.point = {0.0, 0.0};
    slope.normal = {-std::sin(theta), std::cos(theta)};
    slope.friction = friction;
    s.planes.push_back(slope);
    BoxDesc b = box("box", 0.5 * -std::sin(theta), 0.5 * std::cos(theta), 1.0, 1.0);
    b.angle = theta;
    b.friction = friction;
    s.boxes.push_back(b);
    return s;
}

SceneDesc elasticGas(int count, unsigned seed) {
    SceneDesc s = contactScene("Elastic gas",
                               "Disks with restitution 1 and no friction in a closed "
                               "box: the kinetic energy stays constant.");
    s.effects.gravity.reset();
    s.effects.particleCollisions = ParticleCollisionsDesc{1.0};
    // e = 1: every impact bounces, however slow (the restitution threshold scales with 1 − e).
    // A 4 m box, grown for large counts so the disks start 3 radii apart: packed tighter, a
    // gas of thousands starts as one overlapping heap, not a gas.
    const int perRow = static_cast<int>(std::ceil(std::sqrt(count)));
    const double size = std::max(4.0, 0.4 + 0.15 * perRow);
    const Point2 normals[4] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};
    const Point2 points[4] = {{0, 0}, {0, size}, {0, 0}, {size, 0}};
    for (int k = 0; k < 4; ++k) {
        PlaneDesc wall;
        wall.id = name("wall", k);
        wall.point = points[k];
        wall.normal = normals[k];
        wall.friction = 0.0;
        wall.restitution = 1.0;
        s.planes.push_back(wall);
    }
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> speed(-2.0, 2.0);
    const double spacing = (size - 0.4) / perRow;
    for (int i = 0; i < count; ++i) {
        ParticleDesc p;
        p.id = name("d", i);
        p.radius = 0.05;
        p.position = {0.2 + spacing * (0.5 + i % perRow), 0.2 + spacing * (0.5 + i / perRow)};
        p.velocity = {speed(rng), speed(rng)};
        p.restitution = 1.0;
        p.friction = 0.0;
        s.particles.push_back(p);
    }
    return s;
}

SceneDesc newtonsCradle(int count, double speed) {
    SceneDesc s = contactScene("Newton's cradle",
                               "Touching balls in a row: the momentum of the "
                               "first passes down the row to the last.");
    s.effects.gravity.reset();
    s.effects.particleCollisions = ParticleCollisionsDesc{1.0};
    // A cradle swings slowly: every impact must bounce, not only those above 1 m/s.
    for (int i = 0; i < count; ++i) {
        ParticleDesc p;
        p.id = name("ball", i);
        p.radius = 0.1;
        p.position = {0.2 * i, 0.0};
        p.restitution = 1.0;
        p.friction = 0.0;
        s.particles.push_back(p);
    }
    s.particles.front().position = {-0.3, 0.0};
    s.particles.front().velocity = {speed, 0.0};
    return s;
}

SceneDesc bullet(double speed) {
    SceneDesc s = contactScene("Bullet and thin wall",
                               "A small fast disk against a thin wall: "
                               "it must not tunnel through.");
    s.effects.gravity.reset();
    BoxDesc wall = box("wall", 5.0, 0.0, 0.1, 4.0);
    wall.isStatic = true;
    s.boxes.push_back(wall);
    ParticleDesc p;
    p.id = "bullet";
    p.radius = 0.05;
    p.position = {0.0, 0.0};
    p.velocity = {speed, 0.0};
    p.mass = 0.01;
    s.particles.push_back(p);
    return s;
}

SceneDesc dominoes(int count) {
    SceneDesc s = contactScene("Dominoes", "A row of dominoes; the first is tipped over.");
    s.planes.push_back(ground());
    for (int i = 0; i < count; ++i) {
        BoxDesc d = box(name("d", i), 0.5 * i, 0.5, 0.1, 1.0);
        d.friction = 0.6;
        s.boxes.push_back(d);
    }
    // Spun about its centre, the first domino hits the floor with one corner and then turns
    // about it with a quarter of its spin (I_centre/I_corner ≈ 0.25). To tip it must lift its
    // centre by √(0.5² + 0.05²) − 0.5 = 2.5 mm, which needs |ω| ≥ 1.53 rad/s: 3 rad/s tips it.
    s.boxes.front().angularVelocity = -3.0;
    return s;
}

SceneDesc clusteredBodies(int count, unsigned seed) {
    SceneDesc scene;
    scene.name = name("Clustered bodies ", count);
    scene.simulation.integrator = "symplectic_euler";
    scene.simulation.dt = 1e-3;
    NewtonianGravityDesc ng;
    ng.G = 1.0;
    ng.mutual = true;
    ng.softening = 0.0;
    scene.effects.newtonianGravity = ng;
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::uniform_real_distribution<double> uniform(-20.0, 20.0), mass(0.5, 2.0);
    const double centres[3][3] = {{-8.0, 3.0, 1.0}, {6.0, 5.0, 2.5}, {2.0, -7.0, 0.5}};  // x, y, σ
    for (int i = 0; i < count; ++i) {
        ParticleDesc p;
        if (i % 5 == 4) {
            p.position = {uniform(rng), uniform(rng)};
        } else {
            const double* c = centres[i % 3];
            p.position = {c[0] + c[2] * normal(rng), c[1] + c[2] * normal(rng)};
        }
        p.mass = mass(rng);
        p.radius = 0.0;
        scene.particles.push_back(p);
    }
    return scene;
}

SceneDesc hingedChain(int links) {
    SceneDesc s = contactScene(name("Chain of ", links) + " hinged boxes",
                               "Boxes hinged end to end, released level: the chain swings down "
                               "and its end whips. Watch the hinges hold.");
    s.effects.gravity = GravityDesc{{0.0, -10.0}};
    for (int i = 0; i < links; ++i) {
        BoxDesc b = box(name("b", i), 0.5 + i, 20.0, 1.0, 0.25);
        b.density = 20.0;
        b.friction = 0.2;
        JointDesc hinge;
        hinge.type = JointType::Hinge;
        hinge.a = i == 0 ? b.id : name("b", i - 1);
        if (i > 0) hinge.b = b.id;  // the first box's hinge holds it to the world
        hinge.anchor = Point2{static_cast<double>(i), 20.0};
        s.boxes.push_back(b);
        s.joints.push_back(hinge);
    }
    return s;
}

SceneDesc cloth(int n, double structuralStiffness) {
    SceneDesc s;
    s.name = name("Cloth ", n) + "x" + std::to_string(n);
    s.description =
        "A square of cloth hanging from its top edge. Stiff springs at a large step: "
        "explicit methods blow up, implicit Euler stays calm.";
    s.simulation.integrator = "implicit_euler";
    s.simulation.dt = 1.0 / 60.0;
    s.effects.gravity = GravityDesc{};
    ClothDesc c;
    c.id = "cloth";
    c.origin = {-0.5, 1.0};
    c.size = {1.0, 1.0};
    c.resolution = {n, n};
    c.mass = 1.0;
    c.stiffness = {structuralStiffness, structuralStiffness / 10.0, structuralStiffness / 100.0};
    c.damping = 0.0;
    c.pinned = std::string("top");
    s.cloths.push_back(c);
    return s;
}

const std::vector<NamedScene>& library() {
    static const std::vector<NamedScene> scenes{
        {"pyramid", "20-row box pyramid", [] { return pyramid(20); }},
        {"pyramid40", "40-row box pyramid", [] { return pyramid(40); }},
        {"pyramid100", "100-row box pyramid (5,050 boxes)", [] { return pyramid(100); }},
        {"hexagons", "20-row pyramid of hexagons", [] { return hexagonPyramid(20); }},
        {"tower", "tower of 40 boxes", [] { return tower(40); }},
        {"heavy-on-light", "1, 20 and 400 kg boxes stacked",
         [] {
             return stack({1, 20, 400});
         }},
        {"big-on-small", "2 m box 100× heavier than the 0.5 m box under it",
         [] { return bigOnSmall(100); }},
        {"ball-drop", "ball with restitution 0.8 dropped from 1 m",
         [] { return ballDrop(1.0, 0.8); }},
        {"incline", "box on a 20° incline, μ = 0.5", [] { return incline(20, 0.5); }},
        {"gas", "200 elastic disks in a box", [] { return elasticGas(200); }},
        {"cradle", "Newton's cradle of 5 balls", [] { return newtonsCradle(5, 1.0); }},
        {"bullet", "0.05 m disk at 200 m/s against a 0.1 m wall", [] { return bullet(200); }},
        {"dominoes", "row of 30 dominoes", [] { return dominoes(30); }},
        {"chain100", "chain of 100 hinged boxes whipping down", [] { return hingedChain(100); }},
        {"cloth", "40 x 40 cloth, structural stiffness 2e4, implicit Euler",
         [] { return cloth(40, 2e4); }},
    };
    return scenes;
}

}  // namespace phasebox::scenes
