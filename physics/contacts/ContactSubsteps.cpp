// How many inner sub-steps the contact solver takes in a step: at least kInnerRate a second,
// and more for a deep stack, whose sag under its load (each contact sinks by its force over its
// stiffness, summed down the support chains) would otherwise pass kSagTarget, or where one
// contact would sink past its share of its bodies' size (kLoadedSinkShare).
#include "physics/contacts/ContactChunks.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>

namespace phasebox {

namespace {
// Σ over a contact's points of the force each carries over its spring's stiffness m·ω²: how far
// the contact sinks, summed (force(point) gives each point's force, in any unit the caller
// scales).
template <class Force>
double summedSink(const ContactConstraint& c, double omega, Force force) {
    double sink = 0.0;
    for (int k = 0; k < c.pointCount; ++k) {
        const ContactPoint& p = c.points[k];
        if (p.normalMass > 0.0) sink += force(p) / (p.normalMass * omega * omega);
    }
    return sink;
}
}  // namespace

int ContactSolver::innerSubsteps(double h, const ContactSettings& settings) {
    if (settings.substeps > 0) return settings.substeps;
    // At least kInnerRate sub-steps per second whatever the frame: a soft contact's stiffness
    // is bounded by a quarter of the sub-step rate, and a stack sags by load/(m·ω²), so the
    // rate is what holds a tower. The world's own sub-steps count towards it.
    const int n = static_cast<int>(std::ceil(h * kInnerRate - 1e-9));
    return std::clamp(n, 1, kMaxInnerSubsteps);
}

bool ContactSolver::sagDepths() {
    // Down the support chains: each body's depth is the deepest of its supports' depths plus
    // the sink into it (0 on none). The supports form chains up a stack, mostly, and the
    // contacts' order runs along them in no particular direction (a row's neighbours lean on
    // each other either way, the ground's contacts come last), so passes in that order took 10
    // to 233 on the 100-row pyramid. In the supports' topological order one pass does; a pass in
    // any order that changes nothing leaves the same depths, bit for bit (each the largest sum
    // over its supports of their final depth and its sink), so both ways agree on those.
    const std::size_t nodes = bodies_.size() + 1;
    depth_.assign(nodes, 0.0);
    height_.assign(nodes, 0.0);
    // The supports by their lower body (a counting sort), and how many rest under each body.
    supportStart_.assign(nodes + 1, 0);
    supportsUnder_.assign(nodes, 0);
    for (const Support& s : supports_) {
        if (s.upper < 0) continue;  // the contact carries no load
        ++supportStart_[s.lower + 1];
        ++supportsUnder_[s.upper];
    }
    for (std::size_t k = 0; k < nodes; ++k) supportStart_[k + 1] += supportStart_[k];
    supportOrder_.resize(static_cast<std::size_t>(supportStart_[nodes]));
    {
        // supportReady_ serves first as each lower body's next free place in supportOrder_.
        supportReady_.assign(supportStart_.begin(), supportStart_.end() - 1);
        for (std::size_t i = 0; i < supports_.size(); ++i)
            if (supports_[i].upper >= 0)
                supportOrder_[supportReady_[supports_[i].lower]++] = static_cast<int>(i);
    }
    // Kahn's order: a body once all that it rests on are done.
    supportReady_.clear();
    for (std::size_t k = 0; k < nodes; ++k)
        if (supportsUnder_[k] == 0) supportReady_.push_back(static_cast<int>(k));
    for (std::size_t next = 0; next < supportReady_.size(); ++next) {
        const int lower = supportReady_[next];
        for (int e = supportStart_[lower]; e < supportStart_[lower + 1]; ++e) {
            const Support& s = supports_[supportOrder_[e]];
            depth_[s.upper] = std::max(depth_[s.upper], depth_[lower] + s.sink);
            height_[s.upper] = std::max(height_[s.upper], height_[lower] + s.rise);
            if (--supportsUnder_[s.upper] == 0) supportReady_.push_back(s.upper);
        }
    }
    if (supportReady_.size() == nodes) return true;
    std::fill(height_.begin(), height_.end(), 0.0);
    // A cycle (bodies resting on each other round a ring): passes in the contacts' order, as
    // many as the cap allows (the depths on the ring grow with every pass).
    std::fill(depth_.begin(), depth_.end(), 0.0);
    bool changed = true;
    for (int pass = 0; changed && pass < kMaxSagPasses; ++pass) {
        changed = false;
        for (const Support& s : supports_) {
            if (s.upper < 0) continue;
            const double d = depth_[s.lower] + s.sink;
            if (d > depth_[s.upper]) {
                depth_[s.upper] = d;
                changed = true;
            }
        }
    }
    return false;
}

void ContactSolver::depthsInOrder() {
    std::fill(depth_.begin(), depth_.end(), 0.0);
    for (const int lower : supportReady_)
        for (int e = supportStart_[lower]; e < supportStart_[lower + 1]; ++e) {
            const Support& s = supports_[supportOrder_[e]];
            depth_[s.upper] = std::max(depth_[s.upper], depth_[lower] + s.sink);
        }
}

double ContactSolver::weightSinks(double h, double omega) {
    // No impulses yet: each contact carries the weight pressed onto it, from the top of each
    // stack down (the bodies in reverse of the supports' order): a body's own smooth push and
    // all that rests on it, shared evenly among the supports under it, and among a contact's
    // points. Returns the deepest sink over the most a contact may sink (stackSubsteps()).
    const std::size_t nodes = bodies_.size() + 1;
    const int world = static_cast<int>(bodies_.size());
    load_.assign(nodes, 0.0);
    supportsUnder_.assign(nodes, 0);
    for (const Support& s : supports_)
        if (s.upper >= 0) ++supportsUnder_[s.upper];
    double worst = 0.0;
    for (auto it = supportReady_.rbegin(); it != supportReady_.rend(); ++it) {
        const int lower = *it;
        if (lower < world && bodies_[lower].invMass > 0.0) {
            const SolverBody& b = bodies_[lower];
            load_[lower] += b.mass * (b.smoothDv - b.heldDv).norm() / h;
        }
        for (int e = supportStart_[lower]; e < supportStart_[lower + 1]; ++e) {
            Support& s = supports_[supportOrder_[e]];
            const ContactConstraint& c = constraints_[supportOrder_[e]];
            // The upper body's load is whole: everything on it came before it.
            const double carried = load_[s.upper] / supportsUnder_[s.upper];
            load_[lower] += carried;
            const double perPoint = carried / c.pointCount;
            s.sink =
                summedSink(c, omega * c.stiffness, [&](const ContactPoint&) { return perPoint; }) /
                c.pointCount;
            worst = std::max(worst, s.sink / (kLoadedSinkShare * c.deepOverlap));
        }
    }
    return worst;
}

int ContactSolver::stackSubsteps(double h, int base, const ContactSettings& settings) {
    predictedSag_ = 0.0;
    // The first solve has no last step's impulses: the loads are the weights pressed down the
    // stacks (weightSinks()), and the count they need is taken at once. A scene starts at rest
    // or in free flight, not in an impact, and a stack started on too soft a support would sink
    // into it and be pushed back out over the steps the count takes to rise (a 40-box tower
    // 19 cm; a 200-box one flew apart; a 1,000 kg box on a 1 kg one bounced 2.5 cm deep for half
    // a second).
    const bool fromWeights = !(lastInnerH_ > 0.0);
    // A soft contact of frequency ω carries a force F by sinking F/(m·ω²); a body sinks by what
    // its supports sink plus its own contact's share. Which body rests on which: the smooth
    // forces of the step (less the held contact forces) press the upper one into the lower one. The
    // warm-start impulses are per inner sub-step of the last step, so F = λ/h_last.
    const double baseHertz = std::min(settings.hertz, 0.25 * base / h);
    const double omega = 2.0 * std::numbers::pi * baseHertz;
    const int world = static_cast<int>(bodies_.size());
    // Each contact once, in a shared loop (its divisions were a serial tenth of a millisecond
    // on the 100-row pyramid): which body rests on which, and by how much the upper one sinks.
    // The deepest contact's sink over the most it may sink is a maximum, the same in any order.
    supports_.resize(constraints_.size());
    std::atomic<double> worst{0.0};
    // The walk also keeps each point's force of the last step as the bound of the next held
    // force (ContactPoint::lastNormal; its own held force was set at the last step's end), so
    // that the step starts with one walk over the constraints, not two.
    const bool lengthsKnown = lastInnerH_ > 0.0 && lastStepH_ > 0.0;
    const double perSubstep = lengthsKnown ? 1.0 / lastInnerH_ : 0.0;
    const double perStep = lengthsKnown ? 1.0 / lastStepH_ : 0.0;
    forChunks(constraints_.size(), kRowGrain, [&](std::size_t first, std::size_t end) {
        double worstSink = 0.0;
        for (std::size_t i = first; i < end; ++i) {
            ContactConstraint& c = constraints_[i];
            for (int k = 0; k < c.pointCount; ++k) {
                ContactPoint& p = c.points[k];
                const Vec2 force = forceOf(p, perSubstep, perStep);
                p.lastNormal = static_cast<float>(force.x());
                p.lastTangent = static_cast<float>(force.y());
            }
            Support& s = supports_[i];
            s.upper = -1;
            const double w = omega * c.stiffness;
            double sink = 0.0;
            if (!fromWeights) {
                sink = summedSink(c, w, [](const ContactPoint& p) { return p.normalImpulse; });
                if (c.pointCount == 0 || !(sink > 0.0)) continue;
                sink /= c.pointCount * lastInnerH_;
                worstSink = std::max(worstSink, sink / (kLoadedSinkShare * c.deepOverlap));
            } else if (c.pointCount == 0) {
                continue;
            }
            const int a = c.bodyA >= 0 ? c.bodyA : world;
            const int b = c.bodyB >= 0 ? c.bodyB : world;
            // The normal points from A to B: B rests on A when its smooth push is against n.
            // The rise: from the lower body's centre (the ground's: the contact) up to the upper
            // one's, against the upper one's push, through the first point.
            const ContactPoint& p = c.points[0];
            const auto rise = [&](int upper, const Vec2& upperArm, const Vec2& lowerArm) {
                const Vec2 push = bodies_[upper].smoothDv - bodies_[upper].heldDv;
                const Vec2 between =
                    (upper == a ? b : a) == world ? Vec2(-upperArm) : Vec2(lowerArm - upperArm);
                return -between.dot(push) / push.norm();
            };
            if (b < world && c.normal.dot(bodies_[b].smoothDv - bodies_[b].heldDv) < 0.0)
                s = {b, a, sink, rise(b, p.anchorB, p.anchorA)};
            else if (a < world && c.normal.dot(bodies_[a].smoothDv - bodies_[a].heldDv) > 0.0)
                s = {a, b, sink, rise(a, p.anchorA, p.anchorB)};
        }
        for (double seen = worst.load(); worstSink > seen;)
            if (worst.compare_exchange_weak(seen, worstSink)) break;
    });
    const bool ordered = sagDepths();
    double worstSink = worst.load();
    if (fromWeights) {
        // A ring of bodies resting on each other has no top to start the weights from.
        if (!ordered) return base;
        worstSink = weightSinks(h, omega);
        depthsInOrder();
    }
    double sagRatio = 0.0;
    for (std::size_t k = 0; k < depth_.size(); ++k) {
        predictedSag_ = std::max(predictedSag_, depth_[k]);
        sagRatio = std::max(sagRatio, depth_[k] / allowedSag(height_[k]));
    }
    if (settings.substeps > 0) return base;
    // How far past its bound the worse of the two goes: the stack's sag, or a contact's own.
    const double depthRatio = std::max(sagRatio, worstSink);
    // A change of stiffness moves a resting stack to a new rest, so the count follows the
    // load, not an impact: it rises when the sag has been predicted too deep for a while (by
    // the least of those predictions) and falls when fewer have sufficed for longer.
    const int held = std::clamp(lastSubsteps_, base, kMaxInnerSubsteps);
    const auto needed = [&](double ratio) {
        if (!(ratio > 1.0)) return base;
        // The sag falls with the square of the rate (the stiffness rises with it).
        const double factor = std::sqrt(ratio);
        return std::min(kMaxInnerSubsteps, static_cast<int>(std::ceil(base * factor)));
    };
    const int wanted = needed(depthRatio);
    if (fromWeights) return std::max(base, wanted);
    if (wanted > held) {
        stepsWantingFewer_ = 0;
        leastDepthRatio_ =
            stepsWantingMore_ == 0 ? depthRatio : std::min(leastDepthRatio_, depthRatio);
        if (++stepsWantingMore_ < kStepsBeforeMore) return held;
        stepsWantingMore_ = 0;
        return std::max(held, needed(leastDepthRatio_));
    }
    stepsWantingMore_ = 0;
    if (wanted == held || ++stepsWantingFewer_ < kStepsBeforeFewer) return held;
    stepsWantingFewer_ = 0;
    return wanted;
}

}  // namespace phasebox
