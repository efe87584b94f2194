#include "physics/effects/FlockingEffect.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace phasebox {

namespace {
// The grid cell of a coordinate. Clamped so that a boid flung very far (or a non-finite one,
// whose forces come out non-finite anyway and are reported by the world) cannot overflow the
// conversion to an integer.
std::int64_t cellOf(double x, double inverseCell) {
    const double c = std::floor(x * inverseCell);
    if (!std::isfinite(c)) return 0;
    return static_cast<std::int64_t>(std::clamp(c, -1e15, 1e15));
}

// Below this fraction of the radius two boids are taken to coincide: separation has no
// direction to push them apart along.
constexpr double kCoincident = 1e-9;
}  // namespace

void FlockingEffect::bind(const EffectWorldView& view) {
    Effect::bind(view);
    const auto boids = static_cast<std::uint32_t>(view.layout->dynamicParticles);
    // About two slots per boid keeps the chains short; a power of two makes the slot a mask.
    const std::uint32_t slots = std::bit_ceil(std::max<std::uint32_t>(2 * boids, 16));
    slotMask_ = slots - 1;
    slotStart_.assign(slots + 1, 0);
    slotOfBoid_.assign(boids, 0);
    boidsBySlot_.assign(boids, 0);
    scratch_.setZero(view.layout->dimension());
}

std::uint32_t FlockingEffect::slotOf(std::int64_t cellX, std::int64_t cellY) const {
    // Unsigned arithmetic: the multiplications wrap instead of overflowing.
    std::uint64_t h = static_cast<std::uint64_t>(cellX) * 0x9E3779B97F4A7C15ull ^
                      static_cast<std::uint64_t>(cellY) * 0xC2B2AE3D27D4EB4Full;
    h ^= h >> 29;
    return static_cast<std::uint32_t>(h) & slotMask_;
}

void FlockingEffect::buildGrid(const Vec& q) {
    // A counting sort of the boids by slot: count, prefix-sum to the end of each slot, then
    // place the boids from the last down, which leaves slotStart_[s] at the start of slot s
    // and keeps each slot in ascending boid order (the result does not depend on history).
    const int boids = view_.layout->dynamicParticles;
    const double inverseCell = 1.0 / parameters_.radius;
    std::fill(slotStart_.begin(), slotStart_.end(), 0u);
    for (int i = 0; i < boids; ++i) {
        const std::uint32_t slot =
            slotOf(cellOf(q[2 * i], inverseCell), cellOf(q[2 * i + 1], inverseCell));
        slotOfBoid_[i] = slot;
        ++slotStart_[slot];
    }
    const std::size_t slots = slotStart_.size() - 1;
    for (std::size_t s = 1; s < slots; ++s) slotStart_[s] += slotStart_[s - 1];
    slotStart_[slots] = static_cast<std::uint32_t>(boids);
    for (int i = boids - 1; i >= 0; --i) boidsBySlot_[--slotStart_[slotOfBoid_[i]]] = i;
}

double FlockingEffect::steer(const Vec& q, const Vec& u, Vec& force) {
    const FlockingParameters& p = parameters_;
    const double radius = p.radius, radius2 = radius * radius, inverseCell = 1.0 / radius;
    const double separationRadius = kSeparationFraction * radius;
    const double speedRate = 2.0 * p.maxSpeed / radius;
    const Vec& mass = *view_.mass;
    const int boids = view_.layout->dynamicParticles;
    double power = 0.0;
    for (int i = 0; i < boids; ++i) {
        const Vec2 pi = q.segment<2>(2 * i), vi = u.segment<2>(2 * i);
        const std::int64_t cx = cellOf(pi.x(), inverseCell), cy = cellOf(pi.y(), inverseCell);
        Vec2 separation = Vec2::Zero(), towardCentre = Vec2::Zero(), towardVelocity = Vec2::Zero();
        double weight = 0.0;
        // Two of the nine cells may hash to one slot: each slot is visited once, or its boids
        // would count twice. (Boids of far cells sharing a slot fail the distance test.)
        std::uint32_t visited[9];
        int visitedCount = 0;
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const std::uint32_t slot = slotOf(cx + dx, cy + dy);
                if (std::find(visited, visited + visitedCount, slot) != visited + visitedCount)
                    continue;
                visited[visitedCount++] = slot;
                for (std::uint32_t k = slotStart_[slot]; k < slotStart_[slot + 1]; ++k) {
                    const int j = boidsBySlot_[k];
                    if (j == i) continue;
                    const Vec2 d = pi - q.segment<2>(2 * j);
                    const double r2 = d.squaredNorm();
                    if (!(r2 < radius2)) continue;
                    const double r = std::sqrt(r2);
                    const double w = 1.0 - r / radius;
                    if (r < separationRadius && r > kCoincident * radius)
                        separation += ((separationRadius / r - 1.0) / r) * d;
                    weight += w;
                    towardCentre -= w * d;
                    towardVelocity += w * (u.segment<2>(2 * j) - vi);
                }
            }
        }
        const double norm = 1.0 / std::max(weight, 1.0);
        Vec2 a = p.separation * separation +
                 norm * (p.cohesion * towardCentre + p.alignment * towardVelocity);
        const double speed = vi.norm();
        if (speed > p.maxSpeed) a -= (speedRate * (speed - p.maxSpeed) / speed) * vi;
        const Vec2 f = mass[2 * i] * a;
        force.segment<2>(2 * i) += f;
        power += f.dot(vi);
    }
    return power;
}

double FlockingEffect::addForces(double, const Vec& q, const Vec& u, Vec& force) {
    buildGrid(q);
    return steer(q, u, force);
}

double FlockingEffect::nonConservativePower(double, const Vec& q, const Vec& u) {
    buildGrid(q);
    scratch_.setZero();
    return steer(q, u, scratch_);
}

}  // namespace phasebox
