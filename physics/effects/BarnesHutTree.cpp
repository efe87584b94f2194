#include "physics/effects/BarnesHutTree.h"

#include "physics/core/WorkerPool.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace phasebox {

namespace {
// Spreads the low 32 bits of v to the even bits of the result.
std::uint64_t spreadBits(std::uint64_t v) {
    v &= 0xFFFFFFFFull;
    v = (v | (v << 16)) & 0x0000FFFF0000FFFFull;
    v = (v | (v << 8)) & 0x00FF00FF00FF00FFull;
    v = (v | (v << 4)) & 0x0F0F0F0F0F0F0F0Full;
    v = (v | (v << 2)) & 0x3333333333333333ull;
    v = (v | (v << 1)) & 0x5555555555555555ull;
    return v;
}

// A walk pushes at most the 4 children of each of the kLevels + 1 levels it descends through,
// less the one it pops: this bounds the explicit stack.
constexpr int kStackSize = 4 * (BarnesHutTree::kLevels + 2);
}  // namespace

bool BarnesHutTree::build(const double* positions, const double* massPerDof, int count,
                          double theta) {
    theta_ = theta;
    nodes_.clear();
    if (count <= 0) return true;
    for (int i = 0; i < 2 * count; ++i)
        if (!std::isfinite(positions[i])) return false;
    double minX = positions[0], maxX = minX, minY = positions[1], maxY = minY;
    for (int i = 1; i < count; ++i) {
        minX = std::min(minX, positions[2 * i]);
        maxX = std::max(maxX, positions[2 * i]);
        minY = std::min(minY, positions[2 * i + 1]);
        maxY = std::max(maxY, positions[2 * i + 1]);
    }
    // The root square covers every body with a margin, and is never of zero size (all bodies in
    // one point would otherwise divide by zero).
    const double extent = std::max(maxX - minX, maxY - minY);
    const double size = extent > 0.0 ? extent * (1.0 + 1e-9) : 1.0;
    constexpr double kCells = static_cast<double>((1u << kLevels) - 1);
    const double scale = kCells / size;

    order_.resize(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        const auto ix =
            static_cast<std::uint64_t>(std::min(kCells, (positions[2 * i] - minX) * scale));
        const auto iy =
            static_cast<std::uint64_t>(std::min(kCells, (positions[2 * i + 1] - minY) * scale));
        order_[i] = {spreadBits(ix) | (spreadBits(iy) << 1), i};
    }
    // Bodies move little between evaluations, so the order is nearly the last one; std::sort
    // works in place (no allocation) and the index breaks ties, so the tree is deterministic.
    std::sort(order_.begin(), order_.end());
    keys_.resize(order_.size());
    x_.resize(order_.size());
    y_.resize(order_.size());
    m_.resize(order_.size());
    original_.resize(order_.size());
    for (int s = 0; s < count; ++s) {
        const int i = order_[s].second;
        keys_[s] = order_[s].first;
        x_[s] = positions[2 * i];
        y_[s] = positions[2 * i + 1];
        m_[s] = massPerDof[2 * i];
        original_[s] = i;
    }
    nodes_.emplace_back();
    buildNode(0, 0, count, 0, minX, minY, size);
    return true;
}

void BarnesHutTree::buildNode(int node, int begin, int end, int level, double x0, double y0,
                              double size) {
    nodes_[node].begin = begin;
    nodes_[node].end = end;
    // Mass, first moments, and second moments Σm·x², Σm·x·y, Σm·y² about the origin; the
    // quadrupole about the centre of mass follows from them (parallel axes) below.
    double mass = 0.0, mx = 0.0, my = 0.0, mxx = 0.0, mxy = 0.0, myy = 0.0;
    if (end - begin <= kLeafSize || level == kLevels) {
        for (int s = begin; s < end; ++s) {
            mass += m_[s];
            mx += m_[s] * x_[s];
            my += m_[s] * y_[s];
            mxx += m_[s] * x_[s] * x_[s];
            mxy += m_[s] * x_[s] * y_[s];
            myy += m_[s] * y_[s] * y_[s];
        }
    } else {
        // The two key bits of this level select the quadrant (x in the low bit); the bodies of
        // each quadrant are a contiguous run of the sorted keys.
        const int shift = 2 * (kLevels - 1 - level);
        int bounds[5] = {begin, 0, 0, 0, end};
        for (int d = 1; d < 4; ++d) {
            bounds[d] = static_cast<int>(
                std::partition_point(
                    keys_.begin() + bounds[d - 1], keys_.begin() + end,
                    [&](std::uint64_t key) { return static_cast<int>((key >> shift) & 3) < d; }) -
                keys_.begin());
        }
        int children = 0;
        for (int d = 0; d < 4; ++d) children += bounds[d + 1] > bounds[d] ? 1 : 0;
        const int first = static_cast<int>(nodes_.size());
        nodes_[node].firstChild = first;
        nodes_[node].childCount = children;
        nodes_.resize(nodes_.size() + static_cast<std::size_t>(children));  // may move nodes_
        const double half = 0.5 * size;
        int child = first;
        for (int d = 0; d < 4; ++d) {
            if (bounds[d + 1] == bounds[d]) continue;
            buildNode(child, bounds[d], bounds[d + 1], level + 1, x0 + (d & 1) * half,
                      y0 + (d >> 1) * half, half);
            const Node& c = nodes_[child];
            mass += c.mass;
            mx += c.mass * c.comX;
            my += c.mass * c.comY;
            mxx += c.qxx + c.mass * c.comX * c.comX;
            mxy += c.qxy + c.mass * c.comX * c.comY;
            myy += c.qyy + c.mass * c.comY * c.comY;
            ++child;
        }
    }
    Node& n = nodes_[node];
    n.mass = mass;
    n.comX = mass > 0.0 ? mx / mass : x0 + 0.5 * size;
    n.comY = mass > 0.0 ? my / mass : y0 + 0.5 * size;
    n.qxx = mxx - mass * n.comX * n.comX;
    n.qxy = mxy - mass * n.comX * n.comY;
    n.qyy = myy - mass * n.comY * n.comY;
    const double offset = std::hypot(n.comX - (x0 + 0.5 * size), n.comY - (y0 + 0.5 * size));
    const double reach = size / theta_ + offset;
    n.open2 = reach * reach;
}

template <typename Far, typename Near>
void BarnesHutTree::walk(int s, Far&& far, Near&& near) const {
    int stack[kStackSize];
    int top = 0;
    stack[top++] = 0;
    const double px = x_[s], py = y_[s];
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        const double dx = px - n.comX, dy = py - n.comY;
        const double d2 = dx * dx + dy * dy;
        if (d2 > n.open2) {
            far(dx, dy, d2, n);
        } else if (n.firstChild < 0) {
            near(n.begin, n.end);
        } else {
            assert(top + n.childCount <= kStackSize);
            for (int c = 0; c < n.childCount; ++c) stack[top++] = n.firstChild + c;
        }
    }
}

void BarnesHutTree::addForces(double G, double softening2, double* force, WorkerPool* pool) const {
    const int count = static_cast<int>(x_.size());
    if (nodes_.empty()) return;
    if (pool) {
        pool->parallelFor(count, kWalkGrain, [&](int begin, int end, int) {
            addForcesOf(begin, end, G, softening2, force);
        });
    } else {
        addForcesOf(0, count, G, softening2, force);
    }
}

void BarnesHutTree::addForcesOf(int first, int last, double G, double softening2,
                                double* force) const {
    for (int s = first; s < last; ++s) {
        // −a/G: Σ M·r/(‖r‖² + ε²)^{3/2} with r = p_s − (the cell or body), and the cells'
        // quadrupole terms.
        double ax = 0.0, ay = 0.0;
        const double px = x_[s], py = y_[s];
        walk(
            s,
            [&](double dx, double dy, double d2, const Node& n) {
                // The softened potential's expansion about the cell's centre of mass,
                // −G·(M/s + ½·(3·rᵀQr/s⁵ − tr Q/s³)) with s² = ‖r‖² + ε², has the gradient
                // G·[M·r/s³ − 3·Q·r/s⁵ − (3·tr Q/(2s⁵) − 15·rᵀQr/(2s⁷))·r].
                const double inv1 = 1.0 / std::sqrt(d2 + softening2);  // one division
                const double inv2 = inv1 * inv1;
                const double inv3 = inv2 * inv1;
                const double inv5 = inv3 * inv2;
                const double qrx = n.qxx * dx + n.qxy * dy, qry = n.qxy * dx + n.qyy * dy;
                const double rqr = dx * qrx + dy * qry;
                const double radial =
                    n.mass * inv3 - (1.5 * (n.qxx + n.qyy) - 7.5 * rqr * inv2) * inv5;
                ax += radial * dx - 3.0 * inv5 * qrx;
                ay += radial * dy - 3.0 * inv5 * qry;
            },
            [&](int begin, int end) {
                for (int j = begin; j < end; ++j) {
                    if (j == s) continue;
                    const double dx = px - x_[j], dy = py - y_[j];
                    const double s2 = dx * dx + dy * dy + softening2;
                    if (!(s2 > 0.0)) continue;  // two bodies in one point, unsoftened
                    const double w = m_[j] / (s2 * std::sqrt(s2));
                    ax += w * dx;
                    ay += w * dy;
                }
            });
        const int i = original_[s];
        const double gm = G * m_[s];
        force[2 * i] -= gm * ax;
        force[2 * i + 1] -= gm * ay;
    }
}

double BarnesHutTree::potentialEnergy(double G, double softening2) const {
    const int count = static_cast<int>(x_.size());
    if (nodes_.empty()) return 0.0;
    double energy = 0.0;
    for (int s = 0; s < count; ++s) {
        double phi = 0.0;  // −φ/G: Σ M/√(‖r‖² + ε²) and the quadrupole terms
        const double px = x_[s], py = y_[s];
        walk(
            s,
            [&](double dx, double dy, double d2, const Node& n) {
                // M/s + ½·(3·rᵀQr/s⁵ − tr Q/s³): the expansion the forces use.
                const double inv1 = 1.0 / std::sqrt(d2 + softening2);
                const double inv2 = inv1 * inv1, inv3 = inv2 * inv1;
                const double rqr = n.qxx * dx * dx + 2.0 * n.qxy * dx * dy + n.qyy * dy * dy;
                phi += n.mass * inv1 + 0.5 * (3.0 * rqr * inv3 * inv2 - (n.qxx + n.qyy) * inv3);
            },
            [&](int begin, int end) {
                for (int j = begin; j < end; ++j) {
                    if (j == s) continue;
                    const double dx = px - x_[j], dy = py - y_[j];
                    const double s2 = dx * dx + dy * dy + softening2;
                    if (s2 > 0.0) phi += m_[j] / std::sqrt(s2);
                }
            });
        energy += m_[s] * phi;
    }
    return -0.5 * G * energy;
}

}  // namespace phasebox
