#pragma once
// The one drawing code for a World: the on-screen canvas (raster or OpenGL), picture export,
// the tests and the renderer benchmark all go through SceneRenderer::paint, so what is
// exported or tested is what the user sees. Picking lives here too because it must agree with
// the drawing (a particle drawn 3 px wide is clickable 3 px wide).

#include "physics/world/World.h"
#include "ui/canvas/ViewTransform.h"

#include <QColor>
#include <QLineF>
#include <QPointF>
#include <QSize>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_set>
#include <vector>

QT_BEGIN_NAMESPACE
class QPainter;
QT_END_NAMESPACE

namespace phasebox::ui {

// Chosen to stay readable on a light background and apart from one another: the blue of a
// particle never reads as the blue of a compressed spring because springs are thin lines.
// The default, light theme: Okabe–Ito hues (Appearance.h) where two things must be told apart
// (compressed blue against stretched vermillion springs, bluish-green velocity against purple
// force arrows), so that no pair differs in red against green alone.
struct SceneColors {
    QColor grid{0xe4, 0xe4, 0xe0};
    QColor axis{0xc4, 0xc4, 0xbe};
    QColor particle{0x00, 0x72, 0xb2};
    QColor pinnedParticle{0x44, 0x44, 0x4c};
    QColor dynamicBox{0xe6, 0x9f, 0x00};
    QColor staticBox{0xa6, 0xa6, 0xa6};
    // Bodies asleep (simulation.sleep) are drawn dimmed: their colours half-way to white.
    QColor sleepingParticle{0x97, 0xb7, 0xdf};
    QColor sleepingBox{0xf7, 0xd0, 0x9d};
    QColor plane{0xd9, 0xd2, 0xc3};
    QColor planeBorder{0x6e, 0x64, 0x55};
    QColor springCompressed{0x00, 0x72, 0xb2};
    QColor springRest{0x80, 0x80, 0x80};
    QColor springStretched{0xd5, 0x5e, 0x00};
    QColor cloth{0x4a, 0x5a, 0x70};
    QColor anchor{0x30, 0x30, 0x30};
    QColor joint{0x3a, 0x3a, 0x44};
    QColor rope{0x8a, 0x5a, 0x2b};
    QColor track{0x5f, 0x7f, 0x9f};
    QColor velocity{0x00, 0x9e, 0x73};
    QColor force{0x7b, 0x3f, 0xb5};
    QColor selection{0xe0, 0x20, 0x90};
    QColor hover{0xf0, 0x80, 0xc8};
    QColor text{0x20, 0x20, 0x20};
    QColor backdrop{0xff, 0xff, 0xff, 0xd2};  // behind labels drawn over the scene
};

struct RenderOptions {
    bool grid = true;
    bool scaleBar = true;
    bool trails = false;          // needs a TrailHistory passed to paint()
    bool velocityArrows = false;  // particles (not cloth nodes) and dynamic boxes
    // Only the spring and joint forces, summed per body: the world keeps no total force per
    // object (contacts act as impulses, fields are inside the integrator), and a finite
    // difference of velocities between frames is not available to a stateless renderer.
    bool forceArrows = false;
    bool labels = false;          // object ids, at most kMaxLabels of them
    double lineWidthScale = 1.0;  // presentation mode: thicker lines for a projector
    double fontScale = 1.0;
    double velocityArrowSeconds = 0.25;  // an arrow is where the object will be this much later
    double forceArrowMetresPerNewton = 0.05;
    // Above this many particle discs, discs are blitted from a pre-rendered sprite.
    int spriteThreshold = 500;
    std::unordered_set<std::string> selectedIds;
    std::string hoveredId;
    QColor background{0xfa, 0xfa, 0xf8};
    SceneColors colors;
};

// The recent path of the first objects of a world, for drawing trails: a ring buffer with one
// row of samples per recorded frame. Up to maxTracks moving particles and as many moving boxes
// are followed: a gas of 10,000 disks must not take every track from the three boxes in it.
// Cloth nodes have their mesh instead.
struct TrailHistory {
    struct Track {
        bool isBox = false;
        int index = -1;  // particle or box index
    };

    explicit TrailHistory(int capacity = 240, int maxTracks = 256)
        : capacity_(std::max(2, capacity)), maxTracks_(std::max(0, maxTracks)) {}

    // Appends the current positions. A repeated time adds nothing (a repaint without a step);
    // a time going back or a change in the number of objects (reset, edit) starts afresh.
    void record(const World& world) {
        if (world.particles().size() != particleCount_ || world.rigidBodies().size() != boxCount_ ||
            (count_ > 0 && world.time() < lastTime_))
            chooseTracks(world);
        if (count_ > 0 && world.time() == lastTime_) return;
        QPointF* row = samples_.data() + static_cast<std::size_t>(head_) * tracks_.size();
        for (std::size_t k = 0; k < tracks_.size(); ++k) {
            const Track& t = tracks_[k];
            const Vec2 p = t.isBox ? world.bodyPosition(t.index) : world.particlePosition(t.index);
            row[k] = QPointF(p.x(), p.y());
        }
        head_ = (head_ + 1) % capacity_;
        count_ = std::min(count_ + 1, capacity_);
        lastTime_ = world.time();
    }
    void clear() {
        tracks_.clear();
        samples_.clear();
        head_ = count_ = 0;
        // Impossible counts: the next record() chooses its tracks afresh.
        particleCount_ = boxCount_ = static_cast<std::size_t>(-1);
    }

    const std::vector<Track>& tracks() const { return tracks_; }
    int capacity() const { return capacity_; }
    int sampleCount() const { return count_; }
    // Sample `age` of a track, 0 = the oldest kept, sampleCount() − 1 = the newest (world m).
    QPointF sample(int track, int age) const {
        const int row = ((head_ - count_ + age) % capacity_ + capacity_) % capacity_;
        return samples_[static_cast<std::size_t>(row) * tracks_.size() +
                        static_cast<std::size_t>(track)];
    }

private:
    void chooseTracks(const World& world) {
        clear();
        particleCount_ = world.particles().size();
        boxCount_ = world.rigidBodies().size();
        int particles = 0, boxes = 0;
        for (std::size_t i = 0; i < particleCount_ && particles < maxTracks_; ++i)
            if (!world.particles()[i].pinned && world.particles()[i].cloth < 0) {
                tracks_.push_back({false, static_cast<int>(i)});
                ++particles;
            }
        for (std::size_t i = 0; i < boxCount_ && boxes < maxTracks_; ++i)
            if (!world.rigidBodies()[i].isStatic) {
                tracks_.push_back({true, static_cast<int>(i)});
                ++boxes;
            }
        samples_.resize(tracks_.size() * static_cast<std::size_t>(capacity_));
    }

    int capacity_, maxTracks_;
    std::vector<Track> tracks_;
    std::vector<QPointF> samples_;  // capacity_ rows of tracks_.size() points
    int head_ = 0;                  // row written next
    int count_ = 0;
    double lastTime_ = 0.0;
    std::size_t particleCount_ = static_cast<std::size_t>(-1), boxCount_ = particleCount_;
};

struct PickResult {
    enum Kind { None, Particle, Box, Plane, Spring, Joint };
    Kind kind = None;
    int index = -1;
    std::string id;

    explicit operator bool() const { return kind != None; }
};

class SceneRenderer {
public:
    static constexpr int kMaxLabels = 300;
    static constexpr double kMinParticlePixels = 3.0;  // a radius-0 particle stays visible
    static constexpr double kGridMinPixels = 40.0;
    static constexpr double kPivotPixels = 4.5;  // a hinge's drawn ring (line width scale 1)

    // Draws the world as seen through `view`; the view's centre is put at the centre of the
    // viewport. Leaves the painter's state as it found it.
    static void paint(QPainter& painter, const ViewTransform& view, QSize viewportPixels,
                      const World& world, const RenderOptions& options,
                      const TrailHistory* trails = nullptr);
    // Background, grid and scale bar only: the canvas with no world.
    static void paintEmpty(QPainter& painter, const ViewTransform& view, QSize viewportPixels,
                           const RenderOptions& options);

    // The object under a widget point: particles first (nearest centre within its drawn radius
    // plus the tolerance), then hinge and weld pivots (drawn over the bodies), then rigid
    // bodies, boxes and disks (topmost containing it), then springs, rods and ropes (within the
    // tolerance of the segment; cloth springs are left to their nodes), then planes (the one
    // whose solid side contains it with the nearest border).
    static PickResult pick(const World& world, const ViewTransform& view, QPointF widgetPoint,
                           double tolerancePixels = 6.0);

    // The radius a particle is drawn with (and picked by), in pixels.
    static double drawnRadius(const Particle& particle, double pixelsPerMetre) {
        return std::max(particle.radius * pixelsPerMetre, kMinParticlePixels);
    }
    // Metres between grid lines at this scale: {1, 2, 5}·10^k, at least kGridMinPixels apart.
    static double gridSpacing(double pixelsPerMetre);
    // The colour of a spring with this strain (L − L₀)/L₀ (damping included): blue when
    // compressed, grey at rest, red when stretched, saturating at ±kFullStrain.
    static constexpr double kFullStrain = 0.2;
    static QColor springColor(double strain, const SceneColors& colors = {});
};

// Inline here because it is the short counterpart of the drawing code it must agree with.
inline PickResult SceneRenderer::pick(const World& world, const ViewTransform& view,
                                      QPointF widgetPoint, double tolerancePixels) {
    constexpr double kMiss = std::numeric_limits<double>::infinity();
    // The index with the smallest finite key, or −1.
    const auto nearest = [](std::size_t count, const auto& key) {
        int best = -1;
        double bestKey = kMiss;
        for (std::size_t i = 0; i < count; ++i)
            if (const double k = key(static_cast<int>(i)); k < bestKey) {
                best = static_cast<int>(i);
                bestKey = k;
            }
        return best;
    };
    const double ppm = view.pixelsPerMetre();
    int i = nearest(world.particles().size(), [&](int k) {
        const Vec2 c = world.particlePosition(k);
        const double d = QLineF(widgetPoint, view.toScreen(c.x(), c.y())).length();
        return d <= drawnRadius(world.particles()[k], ppm) + tolerancePixels ? d : kMiss;
    });
    if (i >= 0) return {PickResult::Particle, i, world.particles()[i].id};

    const JointSolver* joints = world.jointSolver();
    const int jointCount = joints ? static_cast<int>(world.joints().size()) : 0;
    i = nearest(jointCount, [&](int k) {
        const Joint::Type t = world.joints()[k].type;
        if (t != Joint::Type::Hinge && t != Joint::Type::Weld) return kMiss;
        const Vec2 c = joints->pointA(k, world.positions());
        const double d = QLineF(widgetPoint, view.toScreen(c.x(), c.y())).length();
        return d <= kPivotPixels + tolerancePixels ? d : kMiss;
    });
    if (i >= 0) return {PickResult::Joint, i, world.joints()[i].id};

    const QPointF wp = view.toWorld(widgetPoint);
    const Vec2 point(wp.x(), wp.y());
    const double tolerance = view.toMetres(tolerancePixels);
    // Dynamic boxes are drawn over static ones and later boxes over earlier: topmost first.
    for (const bool isStatic : {false, true})
        for (i = static_cast<int>(world.rigidBodies().size()) - 1; i >= 0; --i) {
            const RigidBody& box = world.rigidBodies()[i];
            if (box.isStatic != isStatic) continue;
            const Vec2 local = rotation(-world.bodyAngle(i)) * (point - world.bodyPosition(i));
            bool inside = false;
            if (box.shape == RigidShape::Disk) {
                inside = local.norm() <= box.radius + tolerance;
            } else if (box.shape == RigidShape::Polygon) {
                inside = true;
                for (std::size_t k = 0; k < box.vertices.size() && inside; ++k)
                    inside = box.normals[k].dot(local - box.vertices[k]) <= tolerance;
            } else {
                inside = std::abs(local.x()) <= 0.5 * box.size.x() + tolerance &&
                         std::abs(local.y()) <= 0.5 * box.size.y() + tolerance;
            }
            if (inside) return {PickResult::Box, i, box.id};
        }

    // Pixels from the point to the segment a–b when within the tolerance, else a miss.
    const auto segment = [&](const Vec2& a, const Vec2& b) {
        const Vec2 ab = b - a;
        const double t = ab.squaredNorm() > 0.0
                             ? std::clamp((point - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0)
                             : 0.0;
        const double d = view.toPixels((a + t * ab - point).norm());
        return d <= tolerancePixels ? d : kMiss;
    };
    i = nearest(world.springs().size(), [&](int k) {
        const Spring& s = world.springs()[k];
        // Thousands of cloth springs cover a cloth: its nodes are the handles.
        if (s.cloth >= 0) return kMiss;
        return segment(world.springEndPosition(s.a), world.springEndPosition(s.b));
    });
    if (i >= 0) return {PickResult::Spring, i, world.springs()[i].id};
    i = nearest(jointCount, [&](int k) {
        const Joint::Type t = world.joints()[k].type;
        if (t != Joint::Type::Rod && t != Joint::Type::Rope) return kMiss;
        return segment(joints->pointA(k, world.positions()), joints->pointB(k, world.positions()));
    });
    if (i >= 0) return {PickResult::Joint, i, world.joints()[i].id};

    // Inside the solid side (or within the tolerance of its border); the nearest border wins
    // where solids overlap, e.g. in the corner of a closed box.
    i = nearest(world.planes().size(), [&](int k) {
        const Plane& plane = world.planes()[k];
        const double side = view.toPixels((point - plane.point).dot(plane.normal));
        return side <= tolerancePixels ? std::abs(side) : kMiss;
    });
    if (i >= 0) return {PickResult::Plane, i, world.planes()[i].id};
    return {};
}

}  // namespace phasebox::ui
