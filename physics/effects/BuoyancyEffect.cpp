#include "physics/effects/BuoyancyEffect.h"

#include "physics/core/Bodies.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace phasebox {

BuoyancyEffect::BuoyancyEffect(double fluidDensity, double surfaceY, double drag, double gravity)
    : Effect(effectName::buoyancy),
      density_(fluidDensity),
      surfaceY_(surfaceY),
      drag_(drag),
      gravity_(gravity) {}

void BuoyancyEffect::bind(const EffectWorldView& view) {
    Effect::bind(view);
    const StateLayout& layout = *view.layout;
    diskRadius_.assign(static_cast<std::size_t>(layout.dynamicParticles), 0.0);
    boxHalfSize_.assign(static_cast<std::size_t>(layout.dynamicRigidBodies), Vec2::Zero());
    rigidDiskRadius_.assign(static_cast<std::size_t>(layout.dynamicRigidBodies), 0.0);
    rigidPolygon_.assign(static_cast<std::size_t>(layout.dynamicRigidBodies), nullptr);
    rigidPolygonArea_.assign(static_cast<std::size_t>(layout.dynamicRigidBodies), 0.0);
    // Right after addEffect() the world binds with its old layout, before the commit that binds
    // again; a dof outside the current layout is stale then and is skipped, not written past.
    if (view.particles)
        for (const Particle& p : *view.particles)
            if (p.dof >= 0 && p.dof < layout.rigidBase()) diskRadius_[p.dof / 2] = p.radius;
    if (view.rigidBodies)
        for (const RigidBody& b : *view.rigidBodies) {
            const int k = (b.dof - layout.rigidBase()) / 3;
            if (b.dof >= layout.rigidBase() && k < layout.dynamicRigidBodies) {
                boxHalfSize_[k] = 0.5 * b.size;
                if (b.shape == RigidShape::Disk) rigidDiskRadius_[k] = b.radius;
                if (b.shape == RigidShape::Polygon) {
                    rigidPolygon_[k] = &b;
                    double twiceArea = 0.0;
                    for (std::size_t i = 0; i < b.vertices.size(); ++i)
                        twiceArea += cross(b.vertices[i], b.vertices[(i + 1) % b.vertices.size()]);
                    rigidPolygonArea_[k] = 0.5 * twiceArea;
                }
            }
        }
}

SubmergedPart BuoyancyEffect::submergedDisk(double radius, double depth) {
    SubmergedPart part;
    if (!(radius > 0.0)) return part;
    // The part of the disk below the chord at height c·r from its centre: the segment of area
    // r²·(π/2 + asin c + c·√(1 − c²)) and first moment ∫ y dA = −(2/3)·r³·(1 − c²)^{3/2}.
    const double c = std::clamp(depth / radius, -1.0, 1.0);
    const double root = std::sqrt(std::max(0.0, 1.0 - c * c));
    part.area = radius * radius * (std::numbers::pi / 2.0 + std::asin(c) + c * root);
    if (!(part.area > 0.0)) return SubmergedPart{};
    const double moment = -(2.0 / 3.0) * radius * radius * radius * root * root * root;
    part.centroid = {0.0, moment / part.area};
    if (std::abs(c) < 1.0) {
        part.waterlineFrom = -radius * root;
        part.waterlineTo = radius * root;
    }
    return part;
}

namespace {
// The part of a convex polygon (corners counter-clockwise, relative to its centre, already
// turned) below the line y = depth: Sutherland–Hodgman against that one line (a convex polygon
// of n corners cut by a line leaves at most n + 1), then area and centroid by the shoelace.
template <std::size_t N>
SubmergedPart clipBelow(const std::array<Vec2, N>& corners, int n, double depth) {
    SubmergedPart part;
    std::array<Vec2, N + 2> clipped;
    int count = 0;
    double wetFrom = 0.0, wetTo = 0.0;
    int crossings = 0;
    for (int i = 0; i < n; ++i) {
        const Vec2& a = corners[i];
        const Vec2& b = corners[(i + 1) % n];
        const bool aIn = a.y() <= depth, bIn = b.y() <= depth;
        if (aIn) clipped[count++] = a;
        if (aIn != bIn) {
            const double s = (depth - a.y()) / (b.y() - a.y());
            const Vec2 cut(a.x() + s * (b.x() - a.x()), depth);
            clipped[count++] = cut;
            (crossings++ == 0 ? wetFrom : wetTo) = cut.x();
        }
    }
    double twiceArea = 0.0;
    Vec2 moment = Vec2::Zero();
    for (int i = 0; i < count; ++i) {
        const Vec2& a = clipped[i];
        const Vec2& b = clipped[(i + 1) % count];
        const double w = cross(a, b);
        twiceArea += w;
        moment += w * (a + b);
    }
    if (!(twiceArea > 0.0)) return part;
    part.area = 0.5 * twiceArea;
    part.centroid = moment / (3.0 * twiceArea);
    if (crossings == 2) {
        part.waterlineFrom = std::min(wetFrom, wetTo);
        part.waterlineTo = std::max(wetFrom, wetTo);
    }
    return part;
}
}  // namespace

SubmergedPart BuoyancyEffect::submergedBox(const Vec2& halfSize, double angle, double depth) {
    SubmergedPart part;
    const double cosA = std::cos(angle), sinA = std::sin(angle);
    // Half the box's vertical extent: the clip is skipped for a box wholly above or below.
    const double extent = halfSize.x() * std::abs(sinA) + halfSize.y() * std::abs(cosA);
    if (!(depth > -extent)) return part;  // dry (and a non-finite state feels nothing)
    if (depth >= extent) {
        part.area = 4.0 * halfSize.x() * halfSize.y();
        return part;
    }
    const Mat2 r = rotation(angle);
    const std::array<Vec2, 4> corners = {
        Vec2(r * Vec2(-halfSize.x(), -halfSize.y())), Vec2(r * Vec2(halfSize.x(), -halfSize.y())),
        Vec2(r * Vec2(halfSize.x(), halfSize.y())), Vec2(r * Vec2(-halfSize.x(), halfSize.y()))};
    return clipBelow(corners, 4, depth);
}

SubmergedPart BuoyancyEffect::submergedPolygon(const std::vector<Vec2>& vertices, double area,
                                               double angle, double depth) {
    const Mat2 r = rotation(angle);
    std::array<Vec2, kMaxVertices> corners;
    const int n = std::min(static_cast<int>(vertices.size()), kMaxVertices);
    double lowest = 0.0, highest = 0.0;
    for (int i = 0; i < n; ++i) {
        corners[i] = r * vertices[i];
        lowest = std::min(lowest, corners[i].y());
        highest = std::max(highest, corners[i].y());
    }
    SubmergedPart part;
    if (!(depth > lowest)) return part;  // dry (and a non-finite state feels nothing)
    if (depth >= highest) {
        part.area = area;  // the centroid is the body's own
        return part;
    }
    return clipBelow(corners, n, depth);
}

template <typename Fn>
void BuoyancyEffect::forEachBody(const Vec& q, Fn&& fn) const {
    const StateLayout& layout = *view_.layout;
    for (int k = 0; k < layout.dynamicParticles; ++k) {
        const int dof = layout.particleDof(k);
        const double radius = diskRadius_[k];
        const double depth = surfaceY_ - q[dof + 1];
        const SubmergedPart part = submergedDisk(radius, depth);
        const double full = std::numbers::pi * radius * radius;
        const double fraction = full > 0.0 ? part.area / full : (depth > 0.0 ? 1.0 : 0.0);
        fn(dof, false, part, fraction);
    }
    for (int k = 0; k < layout.dynamicRigidBodies; ++k) {
        const int dof = layout.rigidDof(k);
        const double depth = surfaceY_ - q[dof + 1];
        if (const double radius = rigidDiskRadius_[k]; radius > 0.0) {
            // A disk's submerged segment is symmetric about its centre's vertical: no torque.
            const SubmergedPart part = submergedDisk(radius, depth);
            fn(dof, true, part, part.area / (std::numbers::pi * radius * radius));
            continue;
        }
        if (const RigidBody* polygon = rigidPolygon_[k]) {
            const double area = rigidPolygonArea_[k];
            const SubmergedPart part = submergedPolygon(polygon->vertices, area, q[dof + 2], depth);
            fn(dof, true, part, part.area / area);
            continue;
        }
        const Vec2& half = boxHalfSize_[k];
        const SubmergedPart part = submergedBox(half, q[dof + 2], depth);
        fn(dof, true, part, part.area / (4.0 * half.x() * half.y()));
    }
}

double BuoyancyEffect::addForces(double, const Vec& q, const Vec& u, Vec& force) {
    const double lift = density_ * gravity_;
    const Vec& m = *view_.mass;
    double power = 0.0;
    forEachBody(q, [&](int dof, bool isRigid, const SubmergedPart& part, double fraction) {
        force[dof + 1] += lift * part.area;
        if (isRigid) force[dof + 2] += lift * part.area * part.centroid.x();  // r × (0, F)
        if (!(drag_ > 0.0 && fraction > 0.0)) return;
        const double c = drag_ * fraction;
        force[dof] -= c * u[dof];
        force[dof + 1] -= c * u[dof + 1];
        power -= c * (u[dof] * u[dof] + u[dof + 1] * u[dof + 1]);
        if (isRigid) {
            const double spin = c * m[dof + 2] / m[dof];
            force[dof + 2] -= spin * u[dof + 2];
            power -= spin * u[dof + 2] * u[dof + 2];
        }
    });
    return power;
}

double BuoyancyEffect::nonConservativePower(double, const Vec& q, const Vec& u) {
    if (!(drag_ > 0.0)) return 0.0;
    const Vec& m = *view_.mass;
    double power = 0.0;
    forEachBody(q, [&](int dof, bool isRigid, const SubmergedPart&, double fraction) {
        const double c = drag_ * fraction;
        power -= c * (u[dof] * u[dof] + u[dof + 1] * u[dof + 1]);
        if (isRigid) power -= c * m[dof + 2] / m[dof] * u[dof + 2] * u[dof + 2];
    });
    return power;
}

void BuoyancyEffect::addJacobians(double, const Vec& q, const Vec&, ForceJacobians& jac) {
    // With L the waterline's length, x_m its midpoint and ∫x² its second moment (all from the
    // centre), moving the body up by dY uncovers L·dY of area and turning it by dθ uncovers
    // x·dθ per unit of waterline:
    //   ∂A/∂Y = −L,  ∂A/∂θ = −L·x_m,  ∂M/∂Y = −L·x_m,  ∂M/∂θ = −A·ȳ − ∫x²
    // for the area A and the moment M = ∫_sub (x − X) dA that gives the torque ρ·|g|·M.
    // Every body writes its entries, zero or not, so the sparsity pattern never changes.
    const double lift = density_ * gravity_;
    const Vec& m = *view_.mass;
    forEachBody(q, [&](int dof, bool isRigid, const SubmergedPart& part, double fraction) {
        const double length = part.waterlineLength();
        const double kyy = -lift * length;
        jac.addStiffness(dof + 1, dof + 1, kyy);
        if (isRigid) {
            const double mid = 0.5 * (part.waterlineFrom + part.waterlineTo);
            const double from = part.waterlineFrom, to = part.waterlineTo;
            const double secondMoment = (to * to * to - from * from * from) / 3.0;
            const double kyt = kyy * mid;
            double ktt = lift * (-part.area * part.centroid.y() - secondMoment);
            // An upright box that is unstable (a square log) has ktt > 0: the lift's Hessian is
            // then indefinite. Where the solver needs a definite matrix, the block is projected:
            // ktt ≤ kyt²/kyy makes [kyy kyt; kyt ktt] negative semi-definite.
            if (jac.definite) ktt = std::min(ktt, length > 0.0 ? kyt * kyt / kyy : 0.0);
            jac.addStiffness(dof + 1, dof + 2, kyt);
            jac.addStiffness(dof + 2, dof + 1, kyt);
            jac.addStiffness(dof + 2, dof + 2, ktt);
        }
        if (!(drag_ > 0.0)) return;
        const double c = -drag_ * fraction;
        jac.addDamping(dof, dof, c);
        jac.addDamping(dof + 1, dof + 1, c);
        if (isRigid) jac.addDamping(dof + 2, dof + 2, c * m[dof + 2] / m[dof]);
    });
}

double BuoyancyEffect::potentialEnergy(const Vec& q) const {
    // U = ρ·|g|·A_sub·(surface_y − ȳ_sub) = ρ·|g|·A_sub·(depth − centroid.y), see the header.
    double energy = 0.0;
    forEachBody(q, [&](int dof, bool, const SubmergedPart& part, double) {
        energy += part.area * (surfaceY_ - q[dof + 1] - part.centroid.y());
    });
    return density_ * gravity_ * energy;
}

}  // namespace phasebox
