// Contacts kept between frames (ContactStage's frames, ContactSettings::keepStillContacts): a
// pair of colliders neither of which has moved since its contact was found keeps that contact
// instead of a narrow phase, and a contact found anew is written in its colliders' frames.
//   - a settled pyramid keeps nearly all of its contacts, and ends where it ends when every
//     contact is found anew, within what a kept contact may be off (kStillMost, 0.5 mm);
//   - a box sliding into a resting pyramid's apex (a contact found anew between a moving body
//     and one that kept its frame) pushes it as far as when every contact is found anew;
//   - a box on a plank that a motor tilts slowly (both keep their frames for a few steps at a
//     time) starts to slide where tan θ = μ, as on an incline.

#include "../bench/SleepScenes.h"
#include "physics/contacts/ContactStage.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"

#include <QTest>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

using namespace phasebox;

namespace {

std::unique_ptr<World> build(const SceneDesc& desc, bool keep) {
    auto world = buildWorld(desc).world;
    SimulationSettings settings = world->settings();
    settings.contacts.keepStillContacts = keep;
    world->setSettings(settings);
    return world;
}

int boxIndex(const World& w, const std::string& id) {
    for (int i = 0; i < static_cast<int>(w.rigidBodies().size()); ++i)
        if (w.rigidBodies()[i].id == id) return i;
    return -1;
}

// The largest distance between the same body in two worlds of the same scene.
double largestGap(const World& a, const World& b) {
    double gap = 0.0;
    for (int i = 0; i < static_cast<int>(a.rigidBodies().size()); ++i)
        gap = std::max(gap, (a.bodyPosition(i) - b.bodyPosition(i)).norm());
    return gap;
}

// What a kept contact may be off from one found anew: its colliders moved at most kStillMost
// (0.5 mm) since it was found; the tests allow twice that.
constexpr double kKeptTolerance = 1e-3;

}  // namespace

class TestContactFrames : public QObject {
    Q_OBJECT

private slots:
    void settledPyramidKeepsItsContacts() {
        const SceneDesc scene = scenes::pyramid(20);
        auto kept = build(scene, true);
        auto found = build(scene, false);
        double keptShare = 0.0;
        int frames = 0;
        while (kept->time() < 10.0) {
            QVERIFY(kept->step());
            QVERIFY(found->step());
            QCOMPARE(found->contacts()->keptContacts(), 0);
            if (kept->time() < 3.0) continue;
            keptShare += double(kept->contacts()->keptContacts()) /
                         double(kept->contacts()->contacts().size());
            ++frames;
        }
        keptShare /= frames;
        const double gap = largestGap(*kept, *found);
        qInfo("contacts kept from 3 to 10 s: %.1f%%; largest gap to the run without: %.3g m",
              100.0 * keptShare, gap);
        QVERIFY2(keptShare > 0.9, qPrintable(QString("kept %1").arg(keptShare)));
        QVERIFY2(gap < kKeptTolerance, qPrintable(QString("gap %1 m").arg(gap)));
    }

    void sliderPushesTheApexAlike() {
        // The slider reaches the apex's side at about 8 s, the pyramid resting since 2 s.
        const SceneDesc scene = sleep_scenes::pyramidAndSlider(false);
        auto kept = build(scene, true);
        auto found = build(scene, false);
        const int apex = boxIndex(*kept, "r19c0");
        QVERIFY(apex >= 0);
        const double start = kept->bodyPosition(apex).x();
        while (kept->time() < 16.0) {
            QVERIFY(kept->step());
            QVERIFY(found->step());
        }
        const double pushed = start - kept->bodyPosition(apex).x();
        const double pushedFound = start - found->bodyPosition(apex).x();
        const double gap = largestGap(*kept, *found);
        qInfo("apex pushed %.4f m (every contact found anew: %.4f m); largest gap %.3g m", pushed,
              pushedFound, gap);
        QVERIFY2(pushed > 0.05, qPrintable(QString("apex pushed %1 m").arg(pushed)));
        QVERIFY2(gap < kKeptTolerance, qPrintable(QString("gap %1 m").arg(gap)));
    }

    void slowlyTiltedBoxSlidesAtTheFrictionAngle() {
        // A 4 m plank hinged to the world at its centre, tilted to 0.40 rad and turned on by a
        // motor at 0.002 rad/s, with a 0.4 m box resting on it; μ = 0.5 both. Past
        // θ₀ = atan(0.5) the box accelerates along the plank at g·(sin θ − μ·cos θ), about
        // g·(cos θ₀ + μ·sin θ₀)·ω·t after θ₀, so it has slid d = 1 cm when
        // g·(cos θ₀ + μ·sin θ₀)·ω·t³/6 = d, at θ₀ + ω·t. Turning that slowly, the box and the
        // plank keep their frames for several steps at a time.
        constexpr double kMu = 0.5, kRate = 0.002, kStart = 0.40, kSlide = 0.01, kG = 9.81;
        SceneDesc s;
        s.effects.gravity = GravityDesc{};
        // Tilted by kStart, μ = kMu, no bounce.
        const auto addBox = [&](const char* id, Point2 position, Point2 size) {
            BoxDesc b;
            b.id = id;
            b.position = position;
            b.angle = kStart;
            b.size = size;
            b.friction = kMu;
            b.restitution = 0.0;
            s.boxes.push_back(b);
        };
        addBox("plank", {0.0, 2.0}, {4.0, 0.2});
        addBox("box", {-0.3 * std::sin(kStart), 2.0 + 0.3 * std::cos(kStart)}, {0.4, 0.4});
        JointDesc hinge;
        hinge.type = JointType::Hinge;
        hinge.a = "plank";
        hinge.anchor = Point2{0.0, 2.0};
        // The joint angle is θ_world − θ_plank: the motor turns it down to tilt the plank up.
        hinge.motor = JointMotorDesc{-kRate, 1e5};
        s.joints.push_back(hinge);
        auto w = build(s, true);
        const int p = boxIndex(*w, "plank"), b = boxIndex(*w, "box");
        QVERIFY(p >= 0 && b >= 0);
        // Where the box sits along the plank, in the plank's frame.
        const auto along = [&] {
            const double angle = w->bodyAngle(p);
            const Vec2 d = w->bodyPosition(b) - w->bodyPosition(p);
            return d.x() * std::cos(angle) + d.y() * std::sin(angle);
        };
        while (w->time() < 1.0) QVERIFY(w->step());  // settled on the plank
        const double rest = along();
        int keptFrames = 0, frames = 0;
        double slidAt = -1.0;
        while (w->time() < 60.0) {
            QVERIFY(w->step());
            ++frames;
            keptFrames += w->contacts()->keptContacts() > 0;
            if (std::abs(along() - rest) > kSlide) {
                slidAt = w->bodyAngle(p);
                break;
            }
        }
        const double onset = std::atan(kMu);
        const double lag =
            std::cbrt(6.0 * kSlide / (kG * (std::cos(onset) + kMu * std::sin(onset)) * kRate));
        const double expected = onset + kRate * lag;
        qInfo(
            "slid %.0f cm at %.4f rad (expected %.4f rad: atan μ %.4f + %.2f s of turning); "
            "frames with a kept contact: %d of %d",
            100.0 * kSlide, slidAt, expected, onset, lag, keptFrames, frames);
        QVERIFY2(keptFrames > frames / 2, "the contact was found anew in most frames");
        QVERIFY2(slidAt > 0.0, "the box never slid");
        QVERIFY2(std::abs(slidAt - expected) < 0.005,
                 qPrintable(QString("slid at %1 rad").arg(slidAt)));
    }
};

QTEST_GUILESS_MAIN(TestContactFrames)
#include "tst_contact_frames.moc"
