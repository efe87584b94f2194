#pragma once
// What the scene-file suites share (tst_sceneio, tst_sceneio_joints): files with the required
// header, the shape of an error message, a scene with every field away from its default, and
// the check that a file is refused with exactly the given messages.

#include "app/io/SceneIO.h"
#include "physics/scene/SceneDesc.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <QTest>

#include <cmath>
#include <limits>

namespace phasebox::testing {

inline const QString kName = QStringLiteral("lesson.json");

// A file with the required header and then body, e.g. scene(R"("particles": [])").
inline QByteArray scene(const char* body = "") {
    QByteArray json = R"({"format": "phasebox-scene", "version": 1)";
    if (*body) json += ", ";
    json += body;
    json += "}";
    return json;
}

// "lesson.json: PATH: what", the shape of every message but a syntax error's.
inline QString msg(const QString& path, const QString& what) {
    return kName + QStringLiteral(": ") + path + QStringLiteral(": ") + what;
}

// Every field away from its default, ids given and left out, both kinds of spring end, both
// kinds of box mass and of cloth pinning, and numbers that have no short decimal form.
inline SceneDesc richScene() {
    SceneDesc s;
    s.name =
        "Rich \"scene\" \xc3\xbcnic\xc3\xb6"
        "de\ttab";
    s.description = "Every field set.\nA backslash \\, a slash / and a control char \x01.";

    s.simulation.integrator = "rk45";
    s.simulation.dt = 1.0 / 300.0;
    s.simulation.substeps = 3;
    s.simulation.tolerance = 1e-9;
    s.simulation.newtonIterations = 4;
    s.simulation.duration = 12.5;
    s.simulation.solver = {{"iterations", 25.0}, {"baumgarte", 0.2}, {"slop", 1e-3}};

    s.effects.gravity = GravityDesc{{0.1, -9.80665}};
    s.effects.drag = DragDesc{0.1, 0.02, 0.3};
    NewtonianGravityDesc ng;
    ng.G = 1.5;
    ng.attractors = {{{1.0 / 3.0, -2.0 / 7.0}, 1e3}, {{-4.0, 5.0}, 0.5}};
    ng.mutual = true;
    ng.softening = 0.05;
    s.effects.newtonianGravity = ng;
    s.effects.buoyancy = BuoyancyDesc{998.2, -1.5, 0.4};
    s.effects.wind = WindDesc{{2.5, -0.5}, 0.7};
    s.effects.flocking = FlockingDesc{1.5, 2.0, 0.5, 0.25, 3.0};
    s.effects.particleCollisions = ParticleCollisionsDesc{0.8};

    ParticleDesc ball;
    ball.id = "ball";
    ball.position = {0.1, 0.2};
    ball.velocity = {1.0 / 3.0, -1e-300};
    ball.mass = 2.5;
    ball.radius = 0.125;
    ball.pinned = true;
    ball.restitution = 0.9;
    ball.friction = 0.35;
    ball.charge = -1.602176634e-19;
    ParticleDesc anonymous;  // id left out: p1
    anonymous.position = {-1.0, 2.0};
    anonymous.mass = 0.1;
    s.particles = {ball, anonymous};

    BoxDesc crate;
    crate.id = "crate";
    crate.position = {3.0, -1.25};
    crate.size = {0.8, 0.5};
    crate.angle = 0.3;
    crate.velocity = {1.0, -0.5};
    crate.angularVelocity = -2.0;
    crate.mass = 3.0;
    crate.friction = 0.4;
    crate.restitution = 0.2;
    BoxDesc wall;
    wall.id = "wall";
    wall.position = {-6.0, 0.0};
    wall.size = {0.5, 4.0};
    wall.density = 2.5;
    wall.isStatic = true;
    s.boxes = {crate, wall};

    PlaneDesc ground;
    ground.id = "ground";
    ground.point = {0.0, -3.0};
    ground.normal = {0.6, 0.8};
    ground.friction = 0.7;
    ground.restitution = 0.1;
    s.planes = {ground};

    SpringDesc rope;
    rope.id = "rope";
    rope.a = "ball";
    rope.b = "crate";
    rope.aPoint = {0.01, 0.02};
    rope.bPoint = {0.4, 0.25};
    rope.stiffness = 150.0;
    rope.damping = 0.5;
    rope.restLength = 1.25;
    SpringDesc hook;  // id left out: s1
    hook.a = "flag[0,0]";
    hook.anchor = Point2{1.0, 2.0};
    hook.stiffness = 20.0;
    s.springs = {rope, hook};

    ClothDesc flag;
    flag.id = "flag";
    flag.origin = {5.0, 1.0};
    flag.size = {2.0, 1.5};
    flag.resolution = {4, 3};
    flag.mass = 0.3;
    flag.stiffness = {500.0, 50.0, 5.0};
    flag.damping = 0.01;
    flag.radius = 0.02;
    flag.pinned = std::vector<std::array<int, 2>>{{0, 0}, {3, 0}};
    ClothDesc sheet;
    sheet.id = "sheet";
    sheet.origin = {-5.0, 3.0};
    sheet.resolution = {3, 5};
    sheet.pinned = std::string("top_corners");
    s.cloths = {flag, sheet};
    return s;
}

// The file is refused with exactly these messages, in this order.
inline void expectRefused(const QByteArray& json, const QStringList& expected) {
    const SceneLoadResult result = SceneIO::parse(json, kName);
    QVERIFY(!result.ok());
    QCOMPARE(result.errorText(), expected.join(QLatin1Char('\n')));
}

}  // namespace phasebox::testing
