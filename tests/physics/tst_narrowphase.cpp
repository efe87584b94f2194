// The narrow phase against hand-computed answers: every pair type (disk–disk, plane–disk,
// box–disk, plane–box, box–box) in simple configurations whose separations, normals and points
// follow from a sketch, then the properties the solver relies on: the speculative margin, feature
// ids that survive tiny motions, the normal always from A to B, no NaN for degenerate input, and
// randomized invariants of the box–box clipping (points on both surfaces, symmetry in A and B).

#include "physics/contacts/Geometry.h"

#include <QString>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

using namespace phasebox;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTol = 1e-12;

#define VERIFY_NEAR(actual, expected, tol)                         \
    do {                                                           \
        const double actual_ = (actual), expected_ = (expected);   \
        QVERIFY2(std::abs(actual_ - expected_) <= (tol),           \
                 qPrintable(QStringLiteral("%1 = %2, expected %3") \
                                .arg(#actual)                      \
                                .arg(actual_, 0, 'g', 17)          \
                                .arg(expected_, 0, 'g', 17)));     \
    } while (false)

#define VERIFY_VEC_NEAR(actual, expected, tol)                                 \
    do {                                                                       \
        const Vec2 actual_ = (actual), expected_ = (expected);                 \
        QVERIFY2((actual_ - expected_).norm() <= (tol),                        \
                 qPrintable(QStringLiteral("%1 = (%2, %3), expected (%4, %5)") \
                                .arg(#actual)                                  \
                                .arg(actual_.x(), 0, 'g', 17)                  \
                                .arg(actual_.y(), 0, 'g', 17)                  \
                                .arg(expected_.x(), 0, 'g', 17)                \
                                .arg(expected_.y(), 0, 'g', 17)));             \
    } while (false)

// The manifold point at a position, whatever order the points came in.
const ManifoldPoint* pointAt(const Manifold& m, const Vec2& position, double tol = 1e-9) {
    for (int k = 0; k < m.pointCount; ++k) {
        if ((m.points[k].position - position).norm() <= tol) return &m.points[k];
    }
    return nullptr;
}

bool finite(const Manifold& m) {
    if (!m.normal.allFinite()) return false;
    for (int k = 0; k < m.pointCount; ++k) {
        if (!m.points[k].position.allFinite() || !std::isfinite(m.points[k].separation)) {
            return false;
        }
    }
    return true;
}

// How far p is outside the box (negative inside): zero exactly on its boundary.
double signedDistanceToBox(const OrientedBox& box, const Vec2& p) {
    const Vec2 local = rotation(box.angle).transpose() * (p - box.center);
    const Vec2 d = local.cwiseAbs() - box.halfExtents;
    return d.cwiseMax(0.0).norm() + std::min(std::max(d.x(), d.y()), 0.0);
}

// Independent separating-axis test by projection intervals onto box's two axes: how far
// `other` lies beyond box's faces at best (negative when they overlap along both axes).
double faceSeparation(const OrientedBox& box, const OrientedBox& other) {
    const Mat2 r = rotation(box.angle), ro = rotation(other.angle);
    double best = -std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 2; ++axis) {
        const Vec2 u = r.col(axis);
        const double reach = other.halfExtents.x() * std::abs(u.dot(ro.col(0))) +
                             other.halfExtents.y() * std::abs(u.dot(ro.col(1)));
        best = std::max(best,
                        std::abs(u.dot(other.center - box.center)) - box.halfExtents[axis] - reach);
    }
    return best;
}

double satSeparation(const OrientedBox& a, const OrientedBox& b) {
    return std::max(faceSeparation(a, b), faceSeparation(b, a));
}

}  // namespace

class TestNarrowPhase : public QObject {
    Q_OBJECT

private slots:
    void boundingBoxes();
    void disksOverlapping();
    void disksSeparated();
    void disksCoincident();
    void diskOnPlane();
    void diskOnTiltedPlane();
    void diskAgainstEachBoxFace();
    void diskCentreInsideBox();
    void diskAgainstBoxCorners();
    void boxFlatOnPlane();
    void boxFlatOnTiltedPlane();
    void boxTiltedOnPlane();
    void boxOnBoxFlat();
    void boxOnBoxOverhanging();
    void boxOnBoxRotatedFrame();
    void boxOnBoxCorner45();
    void speculativeMargin();
    void featureIdsStable();
    void degenerateInputs();
    void largeCoordinates();
    void randomizedBoxInvariants();
};

void TestNarrowPhase::boundingBoxes() {
    const Aabb d = boundingBox(Disk{{1.0, -2.0}, 0.5});
    VERIFY_VEC_NEAR(d.lower, Vec2(0.5, -2.5), kTol);
    VERIFY_VEC_NEAR(d.upper, Vec2(1.5, -1.5), kTol);

    // Half extents (2, 1) turned by 30°: x reach 2·cos + 1·sin, y reach 2·sin + 1·cos.
    const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
    const Aabb b = boundingBox(OrientedBox{{1.0, 1.0}, kPi / 6, {2.0, 1.0}});
    VERIFY_VEC_NEAR(b.lower, Vec2(1.0 - 2 * c - s, 1.0 - 2 * s - c), kTol);
    VERIFY_VEC_NEAR(b.upper, Vec2(1.0 + 2 * c + s, 1.0 + 2 * s + c), kTol);
    // Negative angles and half turns reach as far.
    const Aabb flipped = boundingBox(OrientedBox{{1.0, 1.0}, kPi / 6 - kPi, {2.0, 1.0}});
    VERIFY_VEC_NEAR(flipped.lower, b.lower, kTol);
    VERIFY_VEC_NEAR(flipped.upper, b.upper, kTol);
}

void TestNarrowPhase::disksOverlapping() {
    Manifold m;
    QVERIFY(collideDisks({{0.0, 0.0}, 1.0}, {{1.5, 0.0}, 1.0}, 0.0, m));
    QCOMPARE(m.pointCount, 1);
    VERIFY_VEC_NEAR(m.normal, Vec2(1.0, 0.0), kTol);
    VERIFY_NEAR(m.points[0].separation, -0.5, kTol);
    // A's surface at x = 1, B's at x = 0.5.
    VERIFY_VEC_NEAR(m.points[0].position, Vec2(0.75, 0.0), kTol);

    // Centres 1.5 apart along a 3-4-5 direction, radii 0.9 and 0.8.
    QVERIFY(collideDisks({{1.0, 1.0}, 0.9}, {{1.9, 2.2}, 0.8}, 0.0, m));
    VERIFY_VEC_NEAR(m.normal, Vec2(0.6, 0.8), kTol);
    VERIFY_NEAR(m.points[0].separation, -0.2, kTol);
    // A's surface 0.9 along n, B's 0.7: midway 0.8.
    VERIFY_VEC_NEAR(m.points[0].position, Vec2(1.0 + 0.8 * 0.6, 1.0 + 0.8 * 0.8), kTol);

    // Swapped: the normal turns around, the rest stays.
    QVERIFY(collideDisks({{1.9, 2.2}, 0.8}, {{1.0, 1.0}, 0.9}, 0.0, m));
    VERIFY_VEC_NEAR(m.normal, Vec2(-0.6, -0.8), kTol);
    VERIFY_NEAR(m.points[0].separation, -0.2, kTol);
    VERIFY_VEC_NEAR(m.points[0].position, Vec2(1.0 + 0.8 * 0.6, 1.0 + 0.8 * 0.8), kTol);
}

void TestNarrowPhase::disksSeparated() {
    Manifold m;
    QVERIFY(!collideDisks({{0.0, 0.0}, 1.0}, {{2.5, 0.0}, 1.0}, 0.0, m));
    QCOMPARE(m.pointCount, 0);
    QVERIFY(!collideDisks({{0.0, 0.0}, 1.0}, {{2.5, 0.0}, 1.0}, 0.5, m));  // 0.5 < 0.5 fails
    QVERIFY(collideDisks({{0.0, 0.0}, 1.0}, {{2.5, 0.0}, 1.0}, 0.6, m));
    QCOMPARE(m.pointCount, 1);
    VERIFY_NEAR(m.points[0].separation, 0.5, kTol);
    VERIFY_VEC_NEAR(m.points[0].position, Vec2(1.25, 0.0), kTol);
}

void TestNarrowPhase::disksCoincident() {
    Manifold m;
    QVERIFY(collideDisks({{3.0, 4.0}, 1.0}, {{3.0, 4.0}, 0.5}, 0.0, m));
    QVERIFY(finite(m));
    VERIFY_VEC_NEAR(m.normal, Vec2(0.0, 1.0), 0.0);
    VERIFY_NEAR(m.points[0].separation, -1.5, kTol);
    // A's surface 1 above the centre, B's 0.5 below it.
    VERIFY_VEC_NEAR(m.points[0].position, Vec2(3.0, 4.25), kTol);

    // Nearly coincident (a subnormal offset) still gives a unit normal.
    QVERIFY(collideDisks({{0.0, 0.0}, 1.0}, {{1e-310, 0.0}, 1.0}, 0.0, m));
    QVERIFY(finite(m));
    VERIFY_NEAR(m.normal.norm(), 1.0, kTol);
}

void TestNarrowPhase::diskOnPlane() {
    Manifold m;
    const HalfPlane ground{{0.0, 0.0}, {0.0, 1.0}};
    QVERIFY(collidePlaneDisk(ground, {{2.0, 0.9}, 1.0}, 0.0, m));
    QCOMPARE(m.pointCount, 1);
    VERIFY_VEC_NEAR(m.normal, Vec2(0.0, 1.0), kTol);
    VERIFY_NEAR(m.points[0].separation, -0.1, kTol);
    VERIFY_VEC_NEAR(m.points[0].position, Vec2(2.0, -0.05), kTol);

    QVERIFY(!collidePlaneDisk(ground, {{2.0, 1.05}, 1.0}, 0.0, m));
    QVERIFY(collidePlaneDisk(ground, {{2.0, 1.05}, 1.0}, 0.1, m));
    VERIFY_NEAR(m.points[0].separation, 0.05, kTol);
    VERIFY_VEC_NEAR(m.points[0].position, Vec2(2.0, 0.025), kTol);
}

void TestNarrowPhase::diskOnTiltedPlane() {
    // A 30° slope through (1, 1); the disk sits 3 along it with its centre 0.8 above.
    const Vec2 n(-std::sin(kPi / 6), std::cos(kPi / 6));
    const Vec2 t(n.y(), -n.x());
    const Vec2 p(1.0, 1.0);
    Manifold m;
    QVERIFY(collidePlaneDisk({p, n}, {p + 0.8 * n + 3.0 * t, 1.0}, 0.0, m));
    VERIFY_VEC_NEAR(m.normal, n, kTol);
    VERIFY_NEAR(m.points[0].separation, -0.2, kTol);
    VERIFY_VEC_NEAR(m.points[0].position, Vec2(p + 3.0 * t - 0.1 * n), kTol);
}

void TestNarrowPhase::diskAgainstEachBoxFace() {
    // A 4×2 box turned by 0.3 rad; the disk (radius 0.5) sits 0.3 out from each face's plane,
    // 0.5 along the face, so it overlaps by 0.2 and the normal is that face's normal.
    const OrientedBox box{{1.0, 2.0}, 0.3, {2.0, 1.0}};
    const Mat2 r = rotation(box.angle);
    const Vec2 localNormals[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    for (const Vec2& local : localNormals) {
        const double half = std::abs(local.dot(box.halfExtents));
        const Vec2 along(-local.y(), local.x());
        const Vec2 centre = box.center + r * (local * (half + 0.3) + 0.5 * along);
        Manifold m;
        QVERIFY(collideBoxDisk(box, {centre, 0.5}, 0.0, m));
        QCOMPARE(m.pointCount, 1);
        VERIFY_VEC_NEAR(m.normal, Vec2(r * local), kTol);
        VERIFY_NEAR(m.points[0].separation, -0.2, kTol);
        // Box surface at half, disk surface at half − 0.2: midway half − 0.1.
        VERIFY_VEC_NEAR(m.points[0].position,
                        Vec2(box.center + r * (local * (half - 0.1) + 0.5 * along)), kTol);
    }
}

void TestNarrowPhase::diskCentreInsideBox() {
    // Centre 0.2 inside the right face and 0.9 inside the top: out through the right face.
    const OrientedBox box{{0.0, 0.0}, 0.0, {2.0, 1.0}};
    Manifold m;
    QVERIFY(collideBoxDisk(box, {{1.8, 0.1}, 0.5}, 0.0, m));
    VERIFY_VEC_NEAR(m.normal, Vec2(1.0, 0.0), kTol);
    VERIFY_NEAR(m.points[0].separation, -0.7, kTol);
    // Box surface x = 2, disk surface x = 1.3.
    VERIFY_VEC_NEAR(m.points[0].position, Vec2(1.65, 0.1), kTol);

    // Near the bottom-left instead: out through the bottom face.
    QVERIFY(collideBoxDisk(box, {{-1.0, -0.9}, 0.25}, 0.0, m));
    VERIFY_VEC_NEAR(m.normal, Vec2(0.0, -1.0), kTol);
    VERIFY_NEAR(m.points[0].separation, -0.35, kTol);

    // Exactly at the centre of a square box: some face normal, nothing undefined.
    QVERIFY(collideBoxDisk({{5.0, 5.0}, 0.7, {1.0, 1.0}}, {{5.0, 5.0}, 0.1}, 0.0, m));
    QVERIFY(finite(m));
    VERIFY_NEAR(m.normal.norm(), 1.0, kTol);
    VERIFY_NEAR(m.points[0].separation, -1.1, kTol);
}

void TestNarrowPhase::diskAgainstBoxCorners() {
    // Beyond each corner of a turned 2×1 box, 1 away along a 3-4-5 direction pointing away
    // from the box; radius 1.5 overlaps by 0.5 and the normal is that direction.
    const OrientedBox box{{-1.0, 0.5}, -0.4, {1.0, 0.5}};
    const Mat2 r = rotation(box.angle);
    for (const Vec2& sign : {Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}) {
        const Vec2 corner = box.center + r * sign.cwiseProduct(box.halfExtents);
        const Vec2 direction = r * sign.cwiseProduct(Vec2(0.6, 0.8));
        Manifold m;
        QVERIFY(collideBoxDisk(box, {corner + direction, 1.5}, 0.0, m));
        VERIFY_VEC_NEAR(m.normal, direction, kTol);
        VERIFY_NEAR(m.points[0].separation, -0.5, kTol);
        VERIFY_VEC_NEAR(m.points[0].position, Vec2(corner - 0.25 * direction), kTol);
        // Out of reach without a margin, found with one.
        QVERIFY(!collideBoxDisk(box, {corner + direction, 0.9}, 0.0, m));
        QVERIFY(collideBoxDisk(box, {corner + direction, 0.9}, 0.2, m));
        VERIFY_NEAR(m.points[0].separation, 0.1, kTol);
    }
}

void TestNarrowPhase::boxFlatOnPlane() {
    // A 2×1 box sunk 0.01 into the ground: its two bottom corners (0 and 1).
    const HalfPlane ground{{0.0, 0.0}, {0.0, 1.0}};
    Manifold m;
    QVERIFY(collidePlaneBox(ground, {{3.0, 0.49}, 0.0, {1.0, 0.5}}, 0.02, m));
    QCOMPARE(m.pointCount, 2);
    VERIFY_VEC_NEAR(m.normal, Vec2(0.0, 1.0), kTol);
    const ManifoldPoint* left = pointAt(m, {2.0, -0.005});
    const ManifoldPoint* right = pointAt(m, {4.0, -0.005});
    QVERIFY(left && right);
    VERIFY_NEAR(left->separation, -0.01, kTol);
    VERIFY_NEAR(right->separation, -0.01, kTol);
    QCOMPARE(left->id, 0u);
    QCOMPARE(right->id, 1u);

    // Upside down the same face is made of corners 2 and 3.
    QVERIFY(collidePlaneBox(ground, {{3.0, 0.49}, kPi, {1.0, 0.5}}, 0.02, m));
    QCOMPARE(m.pointCount, 2);
    QVERIFY(m.points[0].id != m.points[1].id);
    QVERIFY(m.points[0].id >= 2 && m.points[1].id >= 2);
    VERIFY_NEAR(m.points[0].separation, -0.01, kTol);
    VERIFY_NEAR(m.points[1].separation, -0.01, kTol);

    QVERIFY(!collidePlaneBox(ground, {{3.0, 0.53}, 0.0, {1.0, 0.5}}, 0.02, m));
    QCOMPARE(m.pointCount, 0);
}

void TestNarrowPhase::boxFlatOnTiltedPlane() {
    // The same box turned with a 20° slope, its bottom face 0.01 into it, 2 along.
    const double angle = 20.0 * kPi / 180.0;
    const Vec2 n(-std::sin(angle), std::cos(angle));
    const Vec2 t(n.y(), -n.x());
    const Vec2 p(-1.0, 2.0);
    const OrientedBox box{p + 0.49 * n + 2.0 * t, angle, {1.0, 0.5}};
    Manifold m;
    QVERIFY(collidePlaneBox({p, n}, box, 0.0, m));
    QCOMPARE(m.pointCount, 2);
    VERIFY_VEC_NEAR(m.normal, n, kTol);
    const ManifoldPoint* lower = pointAt(m, p + 1.0 * t - 0.005 * n);
    const ManifoldPoint* upper = pointAt(m, p + 3.0 * t - 0.005 * n);
    QVERIFY(lower && upper);
    VERIFY_NEAR(lower->separation, -0.01, kTol);
    VERIFY_NEAR(upper->separation, -0.01, kTol);
    QCOMPARE(lower->id, 0u);
    QCOMPARE(upper->id, 1u);
}

void TestNarrowPhase::boxTiltedOnPlane() {
    // Turned by 30°, corner 0 = R·(−1, −0.5) is lowest, at y = −sin30 − 0.5·cos30 below the
    // centre; the next (corner 3) is cos30 higher, far beyond the margin.
    const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
    const Vec2 corner(-c + 0.5 * s, -s - 0.5 * c);
    const Vec2 centre(0.7, -corner.y() - 0.01);
    Manifold m;
    QVERIFY(collidePlaneBox({{0.0, 0.0}, {0.0, 1.0}}, {centre, kPi / 6, {1.0, 0.5}}, 0.02, m));
    QCOMPARE(m.pointCount, 1);
    QCOMPARE(m.points[0].id, 0u);
    VERIFY_NEAR(m.points[0].separation, -0.01, kTol);
    VERIFY_VEC_NEAR(m.points[0].position, Vec2(0.7 + corner.x(), -0.005), kTol);
}

void TestNarrowPhase::boxOnBoxFlat() {
    // A 1×1 box B sunk 0.1 into the top of a 2×2 box A, well inside A's top face: B's bottom
    // corners, midway between A's top (y = 1) and B's bottom (y = 0.9).
    const OrientedBox a{{0.0, 0.0}, 0.0, {1.0, 1.0}};
    const OrientedBox b{{0.2, 1.4}, 0.0, {0.5, 0.5}};
    for (const bool swapped : {false, true}) {
        Manifold m;
        QVERIFY(swapped ? collideBoxes(b, a, 0.0, m) : collideBoxes(a, b, 0.0, m));
        QCOMPARE(m.pointCount, 2);
        VERIFY_VEC_NEAR(m.normal, Vec2(0.0, swapped ? -1.0 : 1.0), kTol);
        const ManifoldPoint* left = pointAt(m, {-0.3, 0.95});
        const ManifoldPoint* right = pointAt(m, {0.7, 0.95});
        QVERIFY(left && right);
        VERIFY_NEAR(left->separation, -0.1, kTol);
        VERIFY_NEAR(right->separation, -0.1, kTol);
        QVERIFY(left->id != right->id);
    }
}

void TestNarrowPhase::boxOnBoxOverhanging() {
    // B hangs over A's right edge (B spans x ∈ [0.3, 1.3], A ends at 1): clipping keeps the
    // part over the other's face, the same two points from either side.
    const OrientedBox a{{0.0, 0.0}, 0.0, {1.0, 1.0}};
    const OrientedBox b{{0.8, 1.45}, 0.0, {0.5, 0.5}};
    for (const bool swapped : {false, true}) {
        Manifold m;
        QVERIFY(swapped ? collideBoxes(b, a, 0.0, m) : collideBoxes(a, b, 0.0, m));
        QCOMPARE(m.pointCount, 2);
        VERIFY_VEC_NEAR(m.normal, Vec2(0.0, swapped ? -1.0 : 1.0), kTol);
        const ManifoldPoint* left = pointAt(m, {0.3, 0.975});
        const ManifoldPoint* right = pointAt(m, {1.0, 0.975});
        QVERIFY(left && right);
        VERIFY_NEAR(left->separation, -0.05, kTol);
        VERIFY_NEAR(right->separation, -0.05, kTol);
    }
}

void TestNarrowPhase::boxOnBoxRotatedFrame() {
    // boxOnBoxFlat seen from a frame turned by 0.7 rad and moved: everything turns with it.
    const Mat2 r = rotation(0.7);
    const Vec2 shift(-3.0, 5.0);
    const OrientedBox a{shift, 0.7, {1.0, 1.0}};
    const OrientedBox b{shift + r * Vec2(0.2, 1.4), 0.7 + kPi / 2, {0.5, 0.5}};  // a square
    Manifold m;
    QVERIFY(collideBoxes(a, b, 0.0, m));
    QCOMPARE(m.pointCount, 2);
    VERIFY_VEC_NEAR(m.normal, Vec2(r * Vec2(0.0, 1.0)), kTol);
    for (const Vec2& local : {Vec2(-0.3, 0.95), Vec2(0.7, 0.95)}) {
        const ManifoldPoint* p = pointAt(m, shift + r * local);
        QVERIFY(p);
        VERIFY_NEAR(p->separation, -0.1, kTol);
    }
}

void TestNarrowPhase::boxOnBoxCorner45() {
    // A 1×1 box turned 45° stands on a corner, 0.05 into a wide slab whose top is y = 0.5.
    // Only the corner is within reach; the slab's top is the reference face whichever box is A.
    const OrientedBox slab{{0.0, 0.0}, 0.0, {2.0, 0.5}};
    const OrientedBox diamond{{0.3, 0.5 + std::sqrt(0.5) - 0.05}, kPi / 4, {0.5, 0.5}};
    for (const bool swapped : {false, true}) {
        Manifold m;
        QVERIFY(swapped ? collideBoxes(diamond, slab, 0.02, m)
                        : collideBoxes(slab, diamond, 0.02, m));
        QCOMPARE(m.pointCount, 1);
        VERIFY_VEC_NEAR(m.normal, Vec2(0.0, swapped ? -1.0 : 1.0), kTol);
        VERIFY_NEAR(m.points[0].separation, -0.05, kTol);
        VERIFY_VEC_NEAR(m.points[0].position, Vec2(0.3, 0.475), kTol);
    }
}

void TestNarrowPhase::speculativeMargin() {
    // Every pair type 0.01 apart: reported at separation 0.01 with a 0.02 margin, not at 0.005.
    Manifold m;
    const Disk disk{{0.0, 0.0}, 1.0};
    const OrientedBox box{{0.0, 0.0}, 0.0, {1.0, 1.0}};
    const HalfPlane ground{{0.0, -1.01}, {0.0, 1.0}};
    const Disk diskAbove{{0.0, 2.01}, 1.0};
    const OrientedBox boxAbove{{0.2, 2.01}, 0.0, {1.0, 1.0}};

    QVERIFY(collideDisks(disk, diskAbove, 0.02, m));
    VERIFY_NEAR(m.points[0].separation, 0.01, kTol);
    QVERIFY(!collideDisks(disk, diskAbove, 0.005, m));
    QVERIFY(collidePlaneDisk(ground, disk, 0.02, m));
    VERIFY_NEAR(m.points[0].separation, 0.01, kTol);
    QVERIFY(!collidePlaneDisk(ground, disk, 0.005, m));
    QVERIFY(collideBoxDisk(box, diskAbove, 0.02, m));
    VERIFY_NEAR(m.points[0].separation, 0.01, kTol);
    QVERIFY(!collideBoxDisk(box, diskAbove, 0.005, m));
    QVERIFY(collidePlaneBox(ground, box, 0.02, m));
    QCOMPARE(m.pointCount, 2);
    VERIFY_NEAR(m.points[0].separation, 0.01, kTol);
    VERIFY_NEAR(m.points[1].separation, 0.01, kTol);
    QVERIFY(!collidePlaneBox(ground, box, 0.005, m));

    QVERIFY(collideBoxes(box, boxAbove, 0.02, m));
    QCOMPARE(m.pointCount, 2);
    VERIFY_VEC_NEAR(m.normal, Vec2(0.0, 1.0), kTol);
    for (int k = 0; k < 2; ++k) {
        VERIFY_NEAR(m.points[k].separation, 0.01, kTol);
        VERIFY_NEAR(m.points[k].position.y(), 1.005, kTol);
    }
    QVERIFY(!collideBoxes(box, boxAbove, 0.005, m));
    QCOMPARE(m.pointCount, 0);
}

void TestNarrowPhase::featureIdsStable() {
    // Resting contacts jitter by round-off and solver noise; the ids must not notice, or the
    // warm-started impulses are thrown away every step.
    const OrientedBox a{{0.0, 0.0}, 0.0, {1.0, 1.0}};
    const OrientedBox configurations[] = {
        {{0.2, 1.4}, 0.0, {0.5, 0.5}},        // flat, inside A's face
        {{0.8, 1.45}, 0.0, {0.5, 0.5}},       // flat, overhanging (one end clipped)
        {{-0.1, 1.98}, kPi / 2, {1.0, 1.0}},  // same size, turned a quarter
        {{0.1, 1.52}, 0.1, {0.5, 0.5}},       // tilted, one corner in
    };
    const Vec2 moves[] = {{1e-6, 0.0}, {-1e-6, 0.0}, {0.0, 1e-6}, {0.0, -1e-6}, {1e-6, -1e-6}};
    for (const OrientedBox& b : configurations) {
        for (const bool swapped : {false, true}) {
            Manifold before;
            QVERIFY(swapped ? collideBoxes(b, a, 0.02, before) : collideBoxes(a, b, 0.02, before));
            for (const Vec2& move : moves) {
                for (const double turn : {0.0, 1e-6, -1e-6}) {
                    const OrientedBox moved{b.center + move, b.angle + turn, b.halfExtents};
                    Manifold after;
                    QVERIFY(swapped ? collideBoxes(moved, a, 0.02, after)
                                    : collideBoxes(a, moved, 0.02, after));
                    QCOMPARE(after.pointCount, before.pointCount);
                    for (int k = 0; k < before.pointCount; ++k) {
                        QCOMPARE(after.points[k].id, before.points[k].id);
                    }
                    if (before.pointCount == 2) QVERIFY(after.points[0].id != after.points[1].id);
                }
            }
        }
    }
}

void TestNarrowPhase::degenerateInputs() {
    Manifold m;
    const OrientedBox unit{{0.0, 0.0}, 0.3, {1.0, 1.0}};
    const OrientedBox point{{0.0, 0.0}, 0.3, {0.0, 0.0}};
    const OrientedBox segment{{0.2, 0.1}, 1.1, {1.0, 0.0}};
    // Coincident identical boxes, boxes of zero size, a box inside another.
    const std::pair<OrientedBox, OrientedBox> boxPairs[] = {
        {unit, unit},       {point, point},  {unit, point},   {point, unit},
        {segment, segment}, {segment, unit}, {unit, segment}, {point, segment},
    };
    for (const auto& [a, b] : boxPairs) {
        collideBoxes(a, b, 0.01, m);
        QVERIFY(finite(m));
        if (m.pointCount > 0) VERIFY_NEAR(m.normal.norm(), 1.0, kTol);
    }
    // Identical boxes overlap by their full size along every axis.
    QVERIFY(collideBoxes(unit, unit, 0.0, m));
    QCOMPARE(m.pointCount, 2);
    VERIFY_NEAR(m.points[0].separation, -2.0, kTol);
    VERIFY_NEAR(m.points[1].separation, -2.0, kTol);

    const Disk dot{{0.0, 0.0}, 0.0};
    QVERIFY(!collideDisks(dot, dot, 0.0, m));  // touching is not < 0
    QVERIFY(collideDisks(dot, dot, 0.01, m));
    QVERIFY(finite(m));
    VERIFY_NEAR(m.points[0].separation, 0.0, 0.0);
    QVERIFY(collideBoxDisk(point, dot, 0.01, m));
    QVERIFY(finite(m));
    VERIFY_NEAR(m.normal.norm(), 1.0, kTol);
    QVERIFY(collidePlaneBox({{0.0, 0.0}, {0.0, 1.0}}, point, 0.01, m));
    QVERIFY(finite(m));
    QVERIFY(collidePlaneDisk({{0.0, 0.0}, {0.0, 1.0}}, dot, 0.01, m));
    QVERIFY(finite(m));
}

void TestNarrowPhase::largeCoordinates() {
    // Far from the origin the answers are those near it, to the precision of the coordinates
    // (an ulp of 1e8 is 1.5e-8).
    const Vec2 far(1e8, -3e8);
    const OrientedBox a{{0.0, 0.0}, 0.2, {1.0, 1.0}};
    const OrientedBox b{{0.3, 1.55}, 0.25, {0.5, 0.5}};
    Manifold nearM, farM;
    QVERIFY(collideBoxes(a, b, 0.02, nearM));
    QVERIFY(collideBoxes({a.center + far, a.angle, a.halfExtents},
                         {b.center + far, b.angle, b.halfExtents}, 0.02, farM));
    QCOMPARE(farM.pointCount, nearM.pointCount);
    VERIFY_VEC_NEAR(farM.normal, nearM.normal, 1e-7);
    for (int k = 0; k < nearM.pointCount; ++k) {
        QCOMPARE(farM.points[k].id, nearM.points[k].id);
        VERIFY_NEAR(farM.points[k].separation, nearM.points[k].separation, 1e-7);
        VERIFY_VEC_NEAR(Vec2(farM.points[k].position - far), nearM.points[k].position, 1e-6);
    }

    QVERIFY(collideDisks({far, 1.0}, {far + Vec2(0.6, 0.8), 0.5}, 0.0, farM));
    VERIFY_VEC_NEAR(farM.normal, Vec2(0.6, 0.8), 1e-7);
    VERIFY_NEAR(farM.points[0].separation, -0.5, 1e-7);
    QVERIFY(collideBoxDisk({far, 0.2, {1.0, 1.0}}, {far + Vec2(0.0, 1.5), 0.5}, 0.0, farM));
    QVERIFY(finite(farM));
}

void TestNarrowPhase::randomizedBoxInvariants() {
    // For random pairs: normals are unit vectors; each point lies with its surfaces, i.e.
    // position ∓ separation/2 · normal on A's and B's boundary; with no margin, overlapping
    // boxes give at least one point and no point with positive separation; no point is deeper
    // than the separating-axis separation; and swapping A and B turns the normal around and
    // keeps the points, whenever the reference face is not a near-tie (where the bias picks A
    // in both orders, by design).
    std::mt19937 rng(20240611);
    std::uniform_real_distribution<double> position(-2.0, 2.0), angle(-kPi, kPi), size(0.05, 1.5),
        unit(0.0, 1.0);
    int overlapping = 0, symmetric = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const OrientedBox a{{position(rng), position(rng)}, angle(rng), {size(rng), size(rng)}};
        const OrientedBox b{{position(rng), position(rng)}, angle(rng), {size(rng), size(rng)}};
        const double margin = unit(rng) < 0.5 ? 0.0 : 0.05;
        const double sat = satSeparation(a, b);
        Manifold m;
        const bool hit = collideBoxes(a, b, margin, m);
        QCOMPARE(hit, m.pointCount > 0);
        QVERIFY(finite(m));
        if (sat >= margin + 1e-12) QVERIFY(!hit);
        if (sat < -1e-12) {
            ++overlapping;
            QVERIFY2(
                hit,
                qPrintable(QStringLiteral("trial %1: overlap %2 not found").arg(trial).arg(sat)));
        }
        if (!hit) continue;
        VERIFY_NEAR(m.normal.norm(), 1.0, 1e-12);
        for (int k = 0; k < m.pointCount; ++k) {
            const ManifoldPoint& p = m.points[k];
            QVERIFY(p.separation < margin);
            QVERIFY(p.separation >= sat - 1e-3 - 1e-9);  // the reference bias at most
            if (sat < 0.0 && margin == 0.0) QVERIFY(p.separation <= 1e-12);
            const Vec2 onA = p.position - 0.5 * p.separation * m.normal;
            const Vec2 onB = p.position + 0.5 * p.separation * m.normal;
            VERIFY_NEAR(signedDistanceToBox(a, onA), 0.0, 1e-9);
            VERIFY_NEAR(signedDistanceToBox(b, onB), 0.0, 1e-9);
        }
        if (m.pointCount == 2) QVERIFY(m.points[0].id != m.points[1].id);

        // Symmetry, where the choice of reference face is clear-cut and no point sits on the
        // margin's edge.
        Manifold swapped;
        collideBoxes(b, a, margin, swapped);
        bool nearMargin = false;
        for (const Manifold* mm : {&m, &swapped}) {
            for (int k = 0; k < mm->pointCount; ++k) {
                nearMargin = nearMargin || std::abs(mm->points[k].separation - margin) < 1e-9;
            }
        }
        if (std::abs(faceSeparation(a, b) - faceSeparation(b, a)) < 1e-2 || nearMargin) continue;
        ++symmetric;
        QCOMPARE(swapped.pointCount, m.pointCount);
        VERIFY_VEC_NEAR(swapped.normal, Vec2(-m.normal), 1e-12);
        for (int k = 0; k < m.pointCount; ++k) {
            const ManifoldPoint* twin = pointAt(swapped, m.points[k].position);
            QVERIFY2(
                twin,
                qPrintable(
                    QStringLiteral("trial %1: point %2 missing when swapped").arg(trial).arg(k)));
            VERIFY_NEAR(twin->separation, m.points[k].separation, 1e-9);
        }
    }
    // The sample must actually exercise both branches.
    QVERIFY(overlapping > 1000);
    QVERIFY(symmetric > 1000);
}

QTEST_APPLESS_MAIN(TestNarrowPhase)
#include "tst_narrowphase.moc"
