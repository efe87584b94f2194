#include "ui/canvas/SceneRenderer.h"

#include "physics/world/World.h"

#include <QFontMetricsF>
#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace phasebox::ui {

namespace {

double lengthOf(QPointF v) {
    return std::hypot(v.x(), v.y());
}

bool selected(const RenderOptions& o, const std::string& id) {
    return !o.selectedIds.empty() && o.selectedIds.count(id) > 0;
}

// What one paint call shares between its passes.
struct Frame {
    QPainter& painter;
    ViewTransform view;
    QRectF viewport;  // in pixels
    const World& world;
    const RenderOptions& o;
    double lw;  // line width scale

    bool visible(QPointF screen, double radius) const {
        return screen.x() + radius >= viewport.left() && screen.x() - radius <= viewport.right() &&
               screen.y() + radius >= viewport.top() && screen.y() - radius <= viewport.bottom();
    }
    QPointF screen(const Vec2& world) const { return view.toScreen(world.x(), world.y()); }
    QPen pen(const QColor& c, double width) const {
        QPen p(c, width * lw);
        p.setCapStyle(Qt::RoundCap);
        p.setJoinStyle(Qt::RoundJoin);
        return p;
    }
};

// Sutherland–Hodgman against one half-plane: keeps the points x with (x − p)·n ≤ 0.
QPolygonF clipToHalfPlane(const QPolygonF& polygon, QPointF p, QPointF n) {
    QPolygonF out;
    const auto side = [&](QPointF x) { return (x.x() - p.x()) * n.x() + (x.y() - p.y()) * n.y(); };
    for (qsizetype i = 0; i < polygon.size(); ++i) {
        const QPointF a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        const double sa = side(a), sb = side(b);
        if (sa <= 0.0) out << a;
        if ((sa <= 0.0) != (sb <= 0.0)) out << a + (b - a) * (sa / (sa - sb));
    }
    return out;
}

// The part of the infinite line through p along d inside rect (Liang–Barsky).
bool clipLineToRect(QPointF p, QPointF d, const QRectF& rect, QLineF& out) {
    double t0 = -std::numeric_limits<double>::infinity(), t1 = -t0;
    const double lo[2] = {rect.left(), rect.top()}, hi[2] = {rect.right(), rect.bottom()};
    const double pv[2] = {p.x(), p.y()}, dv[2] = {d.x(), d.y()};
    for (int k = 0; k < 2; ++k) {
        if (std::abs(dv[k]) < 1e-12) {
            if (pv[k] < lo[k] || pv[k] > hi[k]) return false;
            continue;
        }
        double a = (lo[k] - pv[k]) / dv[k], b = (hi[k] - pv[k]) / dv[k];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    if (t0 > t1) return false;
    out = QLineF(p + d * t0, p + d * t1);
    return true;
}

QString lengthLabel(double metres) {
    const auto number = [](double v) { return QString::number(v, 'g', 6); };
    if (metres >= 1000.0) return number(metres / 1000.0) + QStringLiteral(" km");
    if (metres >= 1.0) return number(metres) + QStringLiteral(" m");
    if (metres >= 0.01) return number(metres * 100.0) + QStringLiteral(" cm");
    if (metres >= 0.001) return number(metres * 1000.0) + QStringLiteral(" mm");
    return number(metres * 1e6) + QStringLiteral(" µm");
}

QFont labelFont(const RenderOptions& o, double pixels) {
    QFont font;
    font.setPixelSize(std::max(6, static_cast<int>(std::lround(pixels * o.fontScale))));
    return font;
}

void drawGrid(QPainter& p, const ViewTransform& view, QSize size, const RenderOptions& o) {
    const double spacing = SceneRenderer::gridSpacing(view.pixelsPerMetre());
    const QRectF w = view.visibleWorldRect();
    QVector<QLineF> lines, axes;
    // Integer pixel positions with antialiasing off: 1 px lines that stay crisp.
    for (double k = std::ceil(w.left() / spacing); k * spacing <= w.right(); k += 1.0) {
        const double x = std::round(view.toScreen(k * spacing, 0.0).x());
        (k == 0.0 ? axes : lines).push_back(QLineF(x, 0, x, size.height()));
    }
    for (double k = std::ceil(w.top() / spacing); k * spacing <= w.bottom(); k += 1.0) {
        const double y = std::round(view.toScreen(0.0, k * spacing).y());
        (k == 0.0 ? axes : lines).push_back(QLineF(0, y, size.width(), y));
    }
    p.setRenderHint(QPainter::Antialiasing, false);
    p.setPen(QPen(o.colors.grid, 0));
    p.drawLines(lines);
    p.setPen(QPen(o.colors.axis, 0));
    p.drawLines(axes);
}

void drawScaleBar(QPainter& p, const ViewTransform& view, QSize size, const RenderOptions& o) {
    const double lw = o.lineWidthScale;
    const double metres = view.niceLength(80.0 * std::max(1.0, lw));
    const double pixels = view.toPixels(metres);
    const QFont font = labelFont(o, 11.0);
    const QString label = lengthLabel(metres);
    const double textHeight = QFontMetricsF(font).height();
    const double x0 = 12.0 * lw, y = size.height() - 12.0 * lw;
    const QRectF backdrop(x0 - 6.0 * lw, y - textHeight - 10.0 * lw, pixels + 12.0 * lw,
                          textHeight + 16.0 * lw);
    p.setRenderHint(QPainter::Antialiasing, false);
    p.fillRect(backdrop, o.colors.backdrop);
    p.setPen(QPen(o.colors.text, 2.0 * lw, Qt::SolidLine, Qt::FlatCap));
    p.drawLine(QPointF(x0, y), QPointF(x0 + pixels, y));
    p.drawLine(QPointF(x0, y - 5.0 * lw), QPointF(x0, y + 3.0 * lw));
    p.drawLine(QPointF(x0 + pixels, y - 5.0 * lw), QPointF(x0 + pixels, y + 3.0 * lw));
    p.setRenderHint(QPainter::TextAntialiasing, true);
    p.setFont(font);
    p.drawText(QRectF(x0, y - textHeight - 6.0 * lw, pixels, textHeight), Qt::AlignCenter, label);
}

// The border line of a plane on screen, clipped to area; false when it misses the area.
bool planeBorder(const Frame& f, const Plane& plane, const QRectF& area, QLineF& border) {
    const QPointF n(plane.normal.x(), -plane.normal.y());  // y flips on screen
    return clipLineToRect(f.screen(plane.point), QPointF(-n.y(), n.x()), area, border);
}

void drawPlanes(const Frame& f) {
    QPainter& p = f.painter;
    // A few pixels wider than the viewport so the border's caps stay out of sight.
    const QRectF area = f.viewport.adjusted(-8, -8, 8, 8);
    const QPolygonF rect({area.topLeft(), area.topRight(), area.bottomRight(), area.bottomLeft()});
    for (const Plane& plane : f.world.planes()) {
        const QPointF point = f.screen(plane.point);
        const QPolygonF solid = clipToHalfPlane(rect, point, {plane.normal.x(), -plane.normal.y()});
        p.setPen(Qt::NoPen);
        p.setBrush(f.o.colors.plane);
        if (solid.size() >= 3) p.drawPolygon(solid);
        QLineF border;
        if (planeBorder(f, plane, area, border)) {
            p.setPen(f.pen(f.o.colors.planeBorder, 2.0));
            p.drawLine(border);
        }
    }
}

void drawTrails(const Frame& f, const TrailHistory& trails) {
    const int n = trails.sampleCount();
    if (n < 2) return;
    QPainter& p = f.painter;
    p.setBrush(Qt::NoBrush);
    // Older quarters fainter: four polylines per track instead of one pen per segment.
    constexpr int kChunks = 4;
    QPolygonF line;
    for (int t = 0; t < static_cast<int>(trails.tracks().size()); ++t) {
        QColor c =
            trails.tracks()[t].isBox ? f.o.colors.dynamicBox.darker(130) : f.o.colors.particle;
        for (int chunk = 0; chunk < kChunks; ++chunk) {
            const int begin = chunk * (n - 1) / kChunks, end = (chunk + 1) * (n - 1) / kChunks;
            if (end <= begin) continue;
            line.clear();
            for (int age = begin; age <= end; ++age) {
                const QPointF w = trails.sample(t, age);
                line << f.view.toScreen(w.x(), w.y());
            }
            c.setAlpha(40 + 150 * chunk / (kChunks - 1));
            p.setPen(f.pen(c, 1.5));
            p.drawPolyline(line);
        }
    }
}

// A rigid body's outline: a box's four corners, or a disk's circle (as many sides as keep
// the outline within half a pixel of the true circle, at least 12).
QPolygonF boxPolygon(const Frame& f, int i) {
    const RigidBody& box = f.world.rigidBodies()[i];
    const Mat2 r = rotation(f.world.bodyAngle(i));
    const Vec2 c = f.world.bodyPosition(i), h = 0.5 * box.size;
    QPolygonF polygon;
    if (box.shape == RigidShape::Disk) {
        const double pixels = f.view.toPixels(box.radius);
        const int sides = std::clamp(
            static_cast<int>(std::ceil(std::numbers::pi / std::sqrt(1.0 / std::max(pixels, 1.0)))),
            12, 256);
        for (int k = 0; k < sides; ++k) {
            const double a = 2.0 * std::numbers::pi * k / sides;
            polygon << f.screen(c + box.radius * Vec2(std::cos(a), std::sin(a)));
        }
        return polygon;
    }
    if (box.shape == RigidShape::Polygon) {
        for (const Vec2& corner : box.vertices) polygon << f.screen(c + r * corner);
        return polygon;
    }
    for (const Vec2& corner :
         {Vec2(-h.x(), -h.y()), Vec2(h.x(), -h.y()), Vec2(h.x(), h.y()), Vec2(-h.x(), h.y())})
        polygon << f.screen(c + r * corner);
    return polygon;
}

void drawBoxes(const Frame& f) {
    QPainter& p = f.painter;
    // Static boxes first, then the dynamic ones asleep (dimmed), then those awake over them:
    // one pen and brush per pass.
    enum Pass { Static, Asleep, Awake };
    const auto passOf = [](const RigidBody& box) {
        return box.isStatic ? Static : box.asleep ? Asleep : Awake;
    };
    for (const Pass pass : {Static, Asleep, Awake}) {
        const QColor fill = pass == Static   ? f.o.colors.staticBox
                            : pass == Asleep ? f.o.colors.sleepingBox
                                             : f.o.colors.dynamicBox;
        p.setPen(f.pen(fill.darker(pass == Static ? 150 : pass == Asleep ? 130 : 165), 1.0));
        p.setBrush(fill);
        for (int i = 0; i < static_cast<int>(f.world.rigidBodies().size()); ++i) {
            const RigidBody& box = f.world.rigidBodies()[i];
            const double reach = f.view.toPixels(0.5 * box.size.norm());
            if (passOf(box) == pass && f.visible(f.screen(f.world.bodyPosition(i)), reach))
                p.drawPolygon(boxPolygon(f, i));
        }
        // A disk's spoke, from its centre along its angle, shows it turning.
        for (int i = 0; i < static_cast<int>(f.world.rigidBodies().size()); ++i) {
            const RigidBody& box = f.world.rigidBodies()[i];
            if (box.shape != RigidShape::Disk || passOf(box) != pass) continue;
            const Vec2 c = f.world.bodyPosition(i);
            const double a = f.world.bodyAngle(i);
            p.drawLine(f.screen(c), f.screen(c + box.radius * Vec2(std::cos(a), std::sin(a))));
        }
    }
}

QVector<QLineF> clothMesh(const Frame& f, const Cloth& cloth) {
    std::vector<QPointF> nodes(static_cast<std::size_t>(cloth.nx) * cloth.ny);
    for (std::size_t k = 0; k < nodes.size(); ++k)
        nodes[k] = f.screen(f.world.particlePosition(cloth.firstParticle + static_cast<int>(k)));
    QVector<QLineF> lines;
    lines.reserve(2 * static_cast<qsizetype>(nodes.size()));
    for (int j = 0; j < cloth.ny; ++j)
        for (int i = 0; i < cloth.nx; ++i) {
            const QPointF a = nodes[static_cast<std::size_t>(j * cloth.nx + i)];
            if (i + 1 < cloth.nx)
                lines.push_back({a, nodes[static_cast<std::size_t>(j * cloth.nx + i + 1)]});
            if (j + 1 < cloth.ny)
                lines.push_back({a, nodes[static_cast<std::size_t>((j + 1) * cloth.nx + i)]});
        }
    return lines;
}

void drawCloths(const Frame& f) {
    // The grid of structural neighbours, straight, in one drawLines call: a 64 × 64 cloth has
    // ~24,000 springs, and all of them as zig-zags a few pixels apart would be a grey blur.
    f.painter.setPen(f.pen(f.o.colors.cloth, 1.0));
    for (const Cloth& cloth : f.world.cloths()) f.painter.drawLines(clothMesh(f, cloth));
}

// Strain-like measure (L − L₀)/max(L, L₀), damping included through the tension. Dividing by
// the larger length keeps it finite for a spring of rest length 0, which is always stretched,
// and equal to the strain when compressed.
double springStrain(const World& world, int i, double length) {
    const Spring& s = world.springs()[i];
    const double scale = s.stiffness * std::max({s.restLength, length, 1e-9});
    return scale > 0.0 ? world.springTension(i) / scale : 0.0;
}

// A mount above the point it holds (apex down at the point): things hang from anchors and pins
// far more often than they stand on them, and the triangle then stays off the spring or cloth.
void addAnchor(QPainterPath& path, QPointF tip, double size) {
    path.moveTo(tip);
    path.lineTo(tip + QPointF(-0.6 * size, -size));
    path.lineTo(tip + QPointF(0.6 * size, -size));
    path.closeSubpath();
}

void drawSprings(const Frame& f) {
    const auto& springs = f.world.springs();
    int loose = 0;  // springs that are not part of a cloth
    for (const Spring& s : springs) loose += s.cloth < 0;
    // Past a few thousand springs the coils cost more than they tell.
    const bool zigzag = loose <= 2000;
    constexpr int kBuckets = 17;  // colour steps: one drawLines call per bucket
    std::array<QVector<QLineF>, kBuckets> buckets;
    QPainterPath anchors;
    const double amplitude = 5.0 * f.lw;
    for (int i = 0; i < static_cast<int>(springs.size()); ++i) {
        const Spring& s = springs[i];
        if (s.cloth >= 0) continue;
        const Vec2 wa = f.world.springEndPosition(s.a), wb = f.world.springEndPosition(s.b);
        const QPointF a = f.screen(wa), b = f.screen(wb);
        const QRectF reach = QRectF(a, b).normalized();
        if (!reach.adjusted(-amplitude, -amplitude, amplitude, amplitude).intersects(f.viewport))
            continue;
        for (const SpringEnd* end : {&s.a, &s.b})
            if (end->kind == SpringEnd::Kind::Anchor)
                addAnchor(anchors, end == &s.a ? a : b, 9.0 * f.lw);
        const double t = std::clamp(
            springStrain(f.world, i, (wb - wa).norm()) / SceneRenderer::kFullStrain, -1.0, 1.0);
        QVector<QLineF>& out =
            buckets[static_cast<std::size_t>(std::lround((t + 1.0) * 0.5 * (kBuckets - 1)))];
        const double length = lengthOf(b - a);
        if (!zigzag || length < 24.0 * f.lw) {
            out.push_back({a, b});
            continue;
        }
        // A fixed number of coils with a fixed width: a stretched spring opens up, a
        // compressed one closes, as on a lab bench.
        constexpr int kHalfCoils = 16;
        const QPointF u = (b - a) / length, n(-u.y(), u.x());
        const double lead = std::min(0.12 * length, 10.0 * f.lw);
        const double pitch = (length - 2.0 * lead) / kHalfCoils;
        QPointF previous = a + u * lead;
        out.push_back({a, previous});
        for (int k = 0; k < kHalfCoils; ++k) {
            const double along = lead + (k + 0.5) * pitch;
            const QPointF next = a + u * along + n * ((k % 2 ? -1.0 : 1.0) * amplitude);
            out.push_back({previous, next});
            previous = next;
        }
        out.push_back({previous, b - u * lead});
        out.push_back({b - u * lead, b});
    }
    QPainter& p = f.painter;
    for (int k = 0; k < kBuckets; ++k) {
        if (buckets[k].isEmpty()) continue;
        const double strain = (2.0 * k / (kBuckets - 1) - 1.0) * SceneRenderer::kFullStrain;
        p.setPen(f.pen(SceneRenderer::springColor(strain, f.o.colors), 1.5));
        p.drawLines(buckets[k]);
    }
    p.setPen(Qt::NoPen);
    p.setBrush(f.o.colors.anchor);
    p.drawPath(anchors);
}

// Joints (CONTRACT §6): a hinge is a pivot ring, a weld a small square, a rod a bar, a rope a
// cord that sags when slack, a pulley two wheels with the rope over them, a track its wire.
void drawJoints(const Frame& f) {
    const JointSolver* solver = f.world.jointSolver();
    if (!solver) return;
    QPainter& p = f.painter;
    const Vec& q = f.world.positions();
    const auto& joints = f.world.joints();
    QPainterPath anchors;
    const double ring = SceneRenderer::kPivotPixels * f.lw;
    for (int i = 0; i < static_cast<int>(joints.size()); ++i) {
        const Joint& j = joints[i];
        const QPointF a = f.screen(solver->pointA(i, q)), b = f.screen(solver->pointB(i, q));
        const bool toWorld = j.b.kind == JointBody::Kind::World;
        p.setBrush(Qt::NoBrush);
        if (selected(f.o, j.id)) {  // under the joint: a halo at its pivot and along its rod
            p.setPen(f.pen(f.o.colors.selection, 6.0));
            if (j.type == Joint::Type::Rod || j.type == Joint::Type::Rope)
                p.drawLine(a, b);
            else
                p.drawEllipse(a, 1.8 * ring, 1.8 * ring);
        }
        switch (j.type) {
            case Joint::Type::Hinge:
                if (toWorld) addAnchor(anchors, a, 10.0 * f.lw);
                p.setPen(f.pen(f.o.colors.joint, 1.5));
                p.setBrush(f.o.background);
                p.drawEllipse(a, ring, ring);
                p.setBrush(f.o.colors.joint);
                p.drawEllipse(a, 1.2 * f.lw, 1.2 * f.lw);
                break;
            case Joint::Type::Weld:
                p.setPen(f.pen(f.o.colors.joint, 1.5));
                p.setBrush(f.o.colors.joint);
                p.drawRect(QRectF(a - QPointF(ring, ring) * 0.7, a + QPointF(ring, ring) * 0.7));
                break;
            case Joint::Type::Rod:
                if (toWorld) addAnchor(anchors, b, 9.0 * f.lw);
                p.setPen(f.pen(f.o.colors.joint, 3.0));
                p.drawLine(a, b);
                break;
            case Joint::Type::Rope: {
                if (toWorld) addAnchor(anchors, b, 9.0 * f.lw);
                p.setPen(f.pen(f.o.colors.rope, 1.5));
                const double chord = (solver->pointA(i, q) - solver->pointB(i, q)).norm();
                if (chord >= j.length * (1.0 - 1e-3)) {
                    p.drawLine(a, b);
                    break;
                }
                // Slack: a parabola with the rope's length, sag s from c + 8s²/(3c) = L.
                const double sag = std::sqrt(3.0 * chord * (j.length - chord) / 8.0);
                const QPointF mid =
                    0.5 * (a + b) + QPointF(0.0, 2.0 * sag * f.view.pixelsPerMetre());
                QPainterPath cord(a);
                cord.quadTo(mid, b);
                p.drawPath(cord);
                break;
            }
            case Joint::Type::Pulley: {
                const QPointF ga = f.screen(j.groundA), gb = f.screen(j.groundB);
                p.setPen(f.pen(f.o.colors.rope, 1.5));
                p.drawLine(ga, a);
                p.drawLine(gb, b);
                p.drawLine(ga, gb);
                p.setPen(f.pen(f.o.colors.joint, 1.5));
                p.setBrush(f.o.background);
                for (const QPointF& g : {ga, gb}) {
                    p.drawEllipse(g, 2.0 * ring, 2.0 * ring);
                    addAnchor(anchors, g - QPointF(0.0, 2.0 * ring), 8.0 * f.lw);
                }
                break;
            }
            case Joint::Type::Track: {
                QPen wire = f.pen(f.o.colors.track, 2.0);
                p.setPen(wire);
                if (j.circle) {
                    const double r = j.radius * f.view.pixelsPerMetre();
                    p.drawEllipse(f.screen(j.center), r, r);
                } else {
                    QLineF line;
                    const QPointF d = QPointF(-j.lineNormal.y(), j.lineNormal.x());
                    const QPointF base = f.screen(j.linePoint);
                    if (clipLineToRect(base, QPointF(d.x(), -d.y()), f.viewport, line))
                        p.drawLine(line);
                }
                break;
            }
        }
    }
    p.setPen(Qt::NoPen);
    p.setBrush(f.o.colors.anchor);
    p.drawPath(anchors);
}

struct Disc {
    QPointF centre;
    double radius;  // pixels
};

// A pre-rendered antialiased disc with its border, per colour, radius (¼ px steps), device
// pixel ratio and line width. Blitting it at an integer position is a plain alpha blend with
// no rasterisation: bench_renderer draws 10,000 disks in about 5 ms this way and 100 ms as
// antialiased ellipses.
struct SpriteKey {
    QRgb rgb;
    int quarterPixels;
    double dpr, lw;
    bool operator==(const SpriteKey&) const = default;
};

const QImage& sprite(const SpriteKey& key, const QColor& colour) {
    thread_local std::vector<std::pair<SpriteKey, QImage>> cache;
    for (const auto& [k, image] : cache)
        if (k == key) return image;
    if (cache.size() >= 32) cache.clear();  // a zoom sweep makes many radii; keep a few
    const double radius = key.quarterPixels / 4.0;
    const int side = static_cast<int>(std::ceil(2.0 * radius + 2.0 * key.lw + 2.0));
    QImage image(QSize(side, side) * key.dpr, QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(key.dpr);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setPen(QPen(colour.darker(140), key.lw));
    p.setBrush(colour);
    p.drawEllipse(QPointF(0.5 * side, 0.5 * side), radius, radius);
    p.end();
    return cache.emplace_back(key, std::move(image)).second;
}

void drawDiscs(const Frame& f, const std::vector<Disc>& discs, const QColor& colour,
               bool useSprites) {
    QPainter& p = f.painter;
    p.setPen(QPen(colour.darker(140), f.lw));
    p.setBrush(colour);
    constexpr double kMaxSpritePixels = 64.0;  // few discs are that large on screen at once
    // Under the GL engine drawImage works too: it caches the sprite's texture by its key.
    const qreal dpr = p.device() ? p.device()->devicePixelRatioF() : 1.0;
    SpriteKey key{colour.rgba(), -1, dpr, f.lw};
    QImage image;  // shares the cached sprite's pixels
    double half = 0.0;
    for (const Disc& d : discs) {
        if (!useSprites || d.radius > kMaxSpritePixels) {
            p.drawEllipse(d.centre, d.radius, d.radius);
            continue;
        }
        if (const int quarters = static_cast<int>(std::lround(4.0 * d.radius));
            quarters != key.quarterPixels) {
            key.quarterPixels = quarters;
            image = sprite(key, colour);
            half = 0.5 * image.width() / dpr;
        }
        p.drawImage(QPointF(std::round(d.centre.x() - half), std::round(d.centre.y() - half)),
                    image);
    }
}

void drawParticles(const Frame& f) {
    const double ppm = f.view.pixelsPerMetre();
    const auto& particles = f.world.particles();
    std::vector<Disc> free, pinned, asleep;
    free.reserve(particles.size());
    QPainterPath anchors;
    int candidates = 0;
    for (int i = 0; i < static_cast<int>(particles.size()); ++i) {
        const Particle& particle = particles[i];
        const QPointF c = f.screen(f.world.particlePosition(i));
        // A cloth is its mesh: its nodes, thousands of them and often closer together than
        // their discs are wide, would hide it. Pinned nodes get small mounts, the rest nothing.
        const bool disc = particle.cloth < 0;
        candidates += disc;
        const double r = disc ? SceneRenderer::drawnRadius(particle, ppm) : 0.0;
        if (!f.visible(c, r + 12.0 * f.lw)) continue;
        if (particle.pinned) addAnchor(anchors, c - QPointF(0, r), (disc ? 8.0 : 5.0) * f.lw);
        if (disc) (particle.pinned ? pinned : particle.asleep ? asleep : free).push_back({c, r});
    }
    // The count of drawable discs, not of visible ones, picks the path: panning must not
    // switch the look back and forth.
    const bool useSprites = candidates > f.o.spriteThreshold;
    f.painter.setPen(Qt::NoPen);
    f.painter.setBrush(f.o.colors.anchor);
    f.painter.drawPath(anchors);
    drawDiscs(f, asleep, f.o.colors.sleepingParticle, useSprites);
    drawDiscs(f, free, f.o.colors.particle, useSprites);
    drawDiscs(f, pinned, f.o.colors.pinnedParticle, useSprites);
}

void addArrow(QVector<QLineF>& lines, QPointF from, QPointF to, double head) {
    const QPointF d = to - from;
    const double length = lengthOf(d);
    if (length < 2.0) return;
    lines.push_back({from, to});
    const QPointF u = d / length, n(-u.y(), u.x());
    const double h = std::min(head, 0.4 * length);
    lines.push_back({to, to - u * h + n * (0.45 * h)});
    lines.push_back({to, to - u * h - n * (0.45 * h)});
}

// One arrow per particle (cloth nodes excepted) and per box with a non-zero vector.
void drawVectors(const Frame& f, const std::vector<Vec2>& particles, const std::vector<Vec2>& boxes,
                 double metresPerUnit, const QColor& colour) {
    constexpr double kMaxArrowPixels = 400.0;  // a stiff spring's force must not cross the screen
    QVector<QLineF> lines;
    const auto add = [&](const Vec2& at, const Vec2& value) {
        QPointF v(f.view.toPixels(value.x() * metresPerUnit),
                  -f.view.toPixels(value.y() * metresPerUnit));
        const double length = lengthOf(v);
        if (length > kMaxArrowPixels) v *= kMaxArrowPixels / length;
        const QPointF c = f.screen(at);
        if (length > 0.0 && f.visible(c, lengthOf(v))) addArrow(lines, c, c + v, 8.0 * f.lw);
    };
    for (std::size_t i = 0; i < particles.size(); ++i)
        if (f.world.particles()[i].cloth < 0)
            add(f.world.particlePosition(static_cast<int>(i)), particles[i]);
    for (std::size_t i = 0; i < boxes.size(); ++i)
        add(f.world.bodyPosition(static_cast<int>(i)), boxes[i]);
    f.painter.setPen(f.pen(colour, 1.5));
    f.painter.drawLines(lines);
}

void drawArrows(const Frame& f) {
    const World& w = f.world;
    std::vector<Vec2> particles(w.particles().size(), Vec2::Zero());
    std::vector<Vec2> boxes(w.rigidBodies().size(), Vec2::Zero());
    if (f.o.velocityArrows) {
        // Fixed objects keep their setup velocity in the object: they are not moving.
        for (std::size_t i = 0; i < particles.size(); ++i)
            if (!w.particles()[i].pinned) particles[i] = w.particleVelocity(static_cast<int>(i));
        for (std::size_t i = 0; i < boxes.size(); ++i)
            if (!w.rigidBodies()[i].isStatic) boxes[i] = w.bodyVelocity(static_cast<int>(i));
        drawVectors(f, particles, boxes, f.o.velocityArrowSeconds, f.o.colors.velocity);
    }
    if (f.o.forceArrows) {
        std::fill(particles.begin(), particles.end(), Vec2::Zero());
        std::fill(boxes.begin(), boxes.end(), Vec2::Zero());
        for (int i = 0; i < static_cast<int>(w.springs().size()); ++i) {
            const Spring& s = w.springs()[i];
            const Vec2 d = w.springEndPosition(s.b) - w.springEndPosition(s.a);
            if (s.cloth >= 0 || d.norm() < 1e-12) continue;
            const Vec2 pull = w.springTension(i) * d.normalized();  // on a, toward b when stretched
            for (const auto& [end, force] : {std::pair{&s.a, pull}, std::pair{&s.b, Vec2(-pull)}}) {
                if (end->kind == SpringEnd::Kind::Particle) particles[end->index] += force;
                if (end->kind == SpringEnd::Kind::Rigid) boxes[end->index] += force;
            }
        }
        // The joints' constraint forces (CONTRACT §6), on each body they hold.
        if (w.jointSolver()) {
            for (int i = 0; i < static_cast<int>(w.joints().size()); ++i) {
                const Joint& j = w.joints()[i];
                for (const auto& [body, force] : {std::pair{&j.a, w.jointForceOn(i, false)},
                                                  std::pair{&j.b, w.jointForceOn(i, true)}}) {
                    if (body->kind == JointBody::Kind::Particle) particles[body->index] += force;
                    if (body->kind == JointBody::Kind::Rigid) boxes[body->index] += force;
                }
            }
        }
        drawVectors(f, particles, boxes, f.o.forceArrowMetresPerNewton, f.o.colors.force);
    }
}

void drawHighlights(const Frame& f) {
    const RenderOptions& o = f.o;
    if (o.selectedIds.empty() && o.hoveredId.empty()) return;
    QPainter& p = f.painter;
    p.setBrush(Qt::NoBrush);
    const World& w = f.world;
    const double ppm = f.view.pixelsPerMetre();
    // Hover first, selection over it: a selected object under the mouse shows as selected.
    for (const bool hover : {true, false}) {
        const auto marked = [&](const std::string& id) {
            return hover ? id == o.hoveredId : selected(o, id);
        };
        p.setPen(f.pen(hover ? o.colors.hover : o.colors.selection, hover ? 2.0 : 3.0));
        for (int i = 0; i < static_cast<int>(w.particles().size()); ++i)
            if (marked(w.particles()[i].id)) {
                const double r = SceneRenderer::drawnRadius(w.particles()[i], ppm) + 3.0 * f.lw;
                p.drawEllipse(f.screen(w.particlePosition(i)), r, r);
            }
        for (int i = 0; i < static_cast<int>(w.rigidBodies().size()); ++i)
            if (marked(w.rigidBodies()[i].id)) p.drawPolygon(boxPolygon(f, i));
        for (const Cloth& cloth : w.cloths())
            if (marked(cloth.id)) p.drawLines(clothMesh(f, cloth));
        for (const Spring& s : w.springs())
            if (marked(s.id))
                p.drawLine(f.screen(w.springEndPosition(s.a)), f.screen(w.springEndPosition(s.b)));
        QLineF border;
        for (const Plane& plane : w.planes())
            if (marked(plane.id) && planeBorder(f, plane, f.viewport, border)) p.drawLine(border);
    }
}

void drawLabels(const Frame& f) {
    QPainter& p = f.painter;
    p.setFont(labelFont(f.o, 11.0));
    p.setPen(f.o.colors.text);
    const World& w = f.world;
    int budget = SceneRenderer::kMaxLabels;
    // Centred on boxes, springs and planes; to the right of particles, clear of the disc.
    const auto label = [&](const std::string& id, QPointF at, double right) {
        if (budget-- <= 0 || !f.viewport.contains(at)) return;
        const QRectF box = right > 0.0 ? QRectF(at.x() + right, at.y() - 50.0, 400.0, 100.0)
                                       : QRectF(at.x() - 200.0, at.y() - 50.0, 400.0, 100.0);
        p.drawText(box, (right > 0.0 ? Qt::AlignLeft : Qt::AlignHCenter) | Qt::AlignVCenter,
                   QString::fromStdString(id));
    };
    for (int i = 0; i < static_cast<int>(w.rigidBodies().size()); ++i)
        label(w.rigidBodies()[i].id, f.screen(w.bodyPosition(i)), 0.0);
    for (int i = 0; i < static_cast<int>(w.particles().size()); ++i) {
        const Particle& particle = w.particles()[i];
        // Cloth nodes only when marked: thousands of "cloth[3,7]" would hide the cloth.
        if (particle.cloth < 0 || selected(f.o, particle.id) || particle.id == f.o.hoveredId)
            label(particle.id, f.screen(w.particlePosition(i)),
                  SceneRenderer::drawnRadius(particle, f.view.pixelsPerMetre()) + 3.0);
    }
    for (const Spring& s : w.springs())
        if (s.cloth < 0)
            label(s.id,
                  0.5 * (f.screen(w.springEndPosition(s.a)) + f.screen(w.springEndPosition(s.b))),
                  0.0);
    QLineF border;
    for (const Plane& plane : w.planes())
        if (planeBorder(f, plane, f.viewport.adjusted(40, 20, -40, -20), border))
            label(plane.id, border.center() + QPointF(plane.normal.x(), -plane.normal.y()) * 12.0,
                  0.0);
}

}  // namespace

// ---- SceneRenderer --------------------------------------------------------------------------

double SceneRenderer::gridSpacing(double pixelsPerMetre) {
    return ViewTransform({0.0, 0.0}, pixelsPerMetre, {1.0, 1.0}).niceLength(kGridMinPixels);
}

QColor SceneRenderer::springColor(double strain, const SceneColors& colors) {
    const double t = std::clamp(strain / kFullStrain, -1.0, 1.0);
    const QColor& end = t < 0.0 ? colors.springCompressed : colors.springStretched;
    const double a = std::abs(t);
    const auto mix = [&](int rest, int to) {
        return static_cast<int>(std::lround(rest + a * (to - rest)));
    };
    return QColor(mix(colors.springRest.red(), end.red()),
                  mix(colors.springRest.green(), end.green()),
                  mix(colors.springRest.blue(), end.blue()));
}

void SceneRenderer::paintEmpty(QPainter& painter, const ViewTransform& view, QSize viewportPixels,
                               const RenderOptions& options) {
    ViewTransform v = view;
    v.setWidgetSize(viewportPixels);
    painter.save();
    painter.fillRect(QRect(QPoint(0, 0), viewportPixels), options.background);
    if (options.grid) drawGrid(painter, v, viewportPixels, options);
    if (options.scaleBar) drawScaleBar(painter, v, viewportPixels, options);
    painter.restore();
}

void SceneRenderer::paint(QPainter& painter, const ViewTransform& view, QSize viewportPixels,
                          const World& world, const RenderOptions& options,
                          const TrailHistory* trails) {
    ViewTransform v = view;
    v.setWidgetSize(viewportPixels);
    painter.save();
    painter.fillRect(QRect(QPoint(0, 0), viewportPixels), options.background);
    if (options.grid) drawGrid(painter, v, viewportPixels, options);
    painter.setRenderHint(QPainter::Antialiasing, true);
    const Frame frame{painter, v,       QRectF(QPointF(0, 0), QSizeF(viewportPixels)),
                      world,   options, std::max(0.1, options.lineWidthScale)};
    drawPlanes(frame);
    if (options.trails && trails) drawTrails(frame, *trails);
    drawBoxes(frame);
    drawCloths(frame);
    drawSprings(frame);
    drawParticles(frame);
    drawJoints(frame);
    drawArrows(frame);
    drawHighlights(frame);
    if (options.labels) drawLabels(frame);
    if (options.scaleBar) drawScaleBar(painter, v, viewportPixels, options);
    painter.restore();
}

}  // namespace phasebox::ui
