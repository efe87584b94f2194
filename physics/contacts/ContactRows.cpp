// The step's contact rows: each contact's masses and stiffness once it is found (prepare), the
// rows built from them for the step's solve, the coloured ones straight into their lanes
// (ContactColours.cpp), and the lanes unpacked for the passes that read whole rows.
#include "physics/contacts/ContactChunks.h"
#include "physics/contacts/ContactImpulse.h"
#include "physics/contacts/ContactSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace phasebox {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();  // no last value yet

// A soft contact carries its load by sinking load/(m·ω²), g/ω² for a body lying on the floor:
// an absolute depth, whatever the body's size. A body much smaller than that depth's scale
// would rest sunk by a large share of its size and tilt by the difference of its corners'
// depths (a triangle's corners carry 2 : 1), then spin up as the manifold follows the tilt.
// Below kStiffHalfSize the contact stiffens as the smaller body's half-size falls, so that its
// rest depth keeps the same share of its size: ω² ∝ 1/size. The soft step is implicit, so a
// stiff contact stays stable; it answers like a rigid one, pushed out within a few sub-steps.
// (More sub-steps would do the same at a cost for the whole scene; a rigid answer below a
// size would make a small body's contacts behave unlike a large one's.)
constexpr double kStiffHalfSize = 5e-3;
constexpr double kMostSizeStiffness = 1000.0;
// A contact with anything fixed is twice as stiff (Box2D v3's static softness): it carries whole
// stacks. A contact between unequal masses is stiffened by √(heavy/light), but no further than
// that. Stiffer, the light body between a heavy one and the ground is driven past its sub-step's
// rate (a 100 kg box on a 1 kg one: 600 Hz at 240 sub-steps a second); the solve, not converged
// across the mass ratio, leaves the heavy body part of each push-out, and it bounced for ever:
// masses 50 to 200 times the light box's under every method uncapped, and at 4× still under
// symplectic and implicit Euler at dt 1/30 to 1/10. What is left of the light body's sink adds
// sub-steps (stackSubsteps(): a contact's own sink is bounded too).
constexpr double kFixedContactStiffness = 2.0;

double sizeStiffness(double deepOverlap) {
    const double halfSize = deepOverlap / ContactConstraint::kDeepOverlapFraction;
    if (!(halfSize > 0.0) || !(halfSize < kStiffHalfSize)) return 1.0;
    return std::min(std::sqrt(kStiffHalfSize / halfSize), kMostSizeStiffness);
}
}  // namespace

// Soft constraint coefficients (Box2D v3's b2MakeSoft): a spring-damper of frequency ω and
// damping ratio ζ, integrated implicitly over h, expressed as a bias rate and the scales of
// the effective mass and of the accumulated impulse.
ContactSolver::Softness ContactSolver::makeSoft(double hertz, double zeta, double h) {
    const double omega = 2.0 * std::numbers::pi * hertz;
    const double a1 = 2.0 * zeta + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

void ContactSolver::prepare() {
    double largestMassRatio = 1.0;  // in a register: the member's store would chain the divisions
    for (SolverBody& b : bodies_) {
        b.contactCount = 0;
        b.stepImpulse = Vec2::Zero();  // once per step: the stage calls prepare() after collide
        b.mass = 1.0 / b.invMass;
    }
    for (const ContactConstraint& c : constraints_) {
        if (c.bodyA >= 0) ++bodies_[c.bodyA].contactCount;
        if (c.bodyB >= 0) ++bodies_[c.bodyB].contactCount;
        if (c.bodyA >= 0 && c.bodyB >= 0) {
            const double mA = bodies_[c.bodyA].mass, mB = bodies_[c.bodyB].mass;
            largestMassRatio = std::max(largestMassRatio, std::max(mA, mB) / std::min(mA, mB));
        }
    }
    largestMassRatio_ = largestMassRatio;
    forChunks(constraints_.size(), kRowGrain, [&](std::size_t first, std::size_t end) {
        // Contacts one after another mostly join bodies of the same masses and sizes: the square
        // roots and their divisions are taken once for each new pair of arguments.
        double lastHeavy = kNaN, lastLight = kNaN, lastRoot = 0.0;
        double lastOverlap = kNaN, lastSize = 0.0;
        for (std::size_t i = first; i < end; ++i) {
            ContactConstraint& c = constraints_[i];
            if (c.kept) continue;  // the same bodies, anchors and normal as when last prepared
            const SolverBody* a = c.bodyA >= 0 ? &bodies_[c.bodyA] : nullptr;
            const SolverBody* b = c.bodyB >= 0 ? &bodies_[c.bodyB] : nullptr;
            const double mA = a ? a->invMass : 0.0, iA = a ? a->invInertia : 0.0;
            const double mB = b ? b->invMass : 0.0, iB = b ? b->invInertia : 0.0;
            // A contact's stiffness follows the heavier of its bodies: the spring that holds a
            // heavy box on a light one must be stiffer than for the light box, or the light one is
            // squashed in (its effective mass sets the soft constraint's spring); up to a fixed
            // contact's stiffness (kFixedContactStiffness).
            if (a && b) {
                const double heavy = std::max(a->mass, b->mass);
                const double light = std::min(a->mass, b->mass);
                if (!(heavy == lastHeavy && light == lastLight)) {
                    lastHeavy = heavy;
                    lastLight = light;
                    lastRoot = std::min(std::sqrt(heavy / light), kFixedContactStiffness);
                }
                c.stiffness = lastRoot;
            } else {
                c.stiffness = kFixedContactStiffness;
            }
            if (!(c.deepOverlap == lastOverlap)) {
                lastOverlap = c.deepOverlap;
                lastSize = sizeStiffness(lastOverlap);
            }
            c.stiffness *= lastSize;
            const Vec2 t = tangentOf(c.normal);
            for (int k = 0; k < c.pointCount; ++k) {
                ContactPoint& p = c.points[k];
                const double rnA = cross(p.anchorA, c.normal), rnB = cross(p.anchorB, c.normal);
                const double kn = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
                p.normalMass = kn > 0.0 ? 1.0 / kn : 0.0;
                const double rtA = cross(p.anchorA, t), rtB = cross(p.anchorB, t);
                const double kt = mA + mB + iA * rtA * rtA + iB * rtB * rtB;
                p.tangentMass = kt > 0.0 ? 1.0 / kt : 0.0;
            }
        }
    });
}

double ContactSolver::smoothNormalChange(const Row& c, const RowPoint& p) const {
    // The smooth step's change of the relative normal velocity at the point, over the whole step,
    // less what the held contact forces gave (they hold; they do not approach).
    const int world = static_cast<int>(bodies_.size());
    auto at = [&](int body, double rx, double ry) -> Vec2 {
        if (body == world) return Vec2::Zero();
        const SolverBody& b = bodies_[body];
        return (b.smoothDv - b.heldDv) + (b.smoothDw - b.heldDw) * Vec2(-ry, rx);
    };
    return Vec2(c.nx, c.ny).dot(at(c.b, p.rBx, p.rBy) - at(c.a, p.rAx, p.rAy));
}

ContactSolver::Softness ContactSolver::stepSoftness(const ContactConstraint& c,
                                                    const BuildTerms& terms, RowCache& cache) {
    // The softness and the push-out share, of a stiffness and a count most rows share with the
    // row before: their divisions once for each new value.
    const double hertz = c.stiffness * terms.hertz;
    if (!(hertz == cache.hertz)) {
        cache.hertz = hertz;
        cache.soft = makeSoft(hertz, terms.zeta, terms.h);
    }
    // The push-out speed is a body's, shared among its contacts: in a pile each contact's
    // push adds up along chains of bodies (200 boxes started at one point left at 20 m/s
    // with a whole 3 m/s per contact, 13 m/s shared).
    const int sharers = std::max({1, c.bodyA >= 0 ? bodies_[c.bodyA].contactCount : 1,
                                  c.bodyB >= 0 ? bodies_[c.bodyB].contactCount : 1});
    if (sharers != cache.sharers) {
        cache.sharers = sharers;
        cache.share = 1.0 / sharers;
    }
    return cache.soft;
}

void ContactSolver::buildRow(std::size_t i, Row& row, RowSetup& setup, const BuildTerms& terms,
                             RowCache& cache) {
    const int world = static_cast<int>(bodies_.size());
    const ContactConstraint& c = constraints_[i];
    const double h = terms.h, warmScale = terms.warmScale;
    row.a = c.bodyA >= 0 ? c.bodyA : world;
    row.b = c.bodyB >= 0 ? c.bodyB : world;
    row.pointCount = c.pointCount;
    row.nx = c.normal.x();
    row.ny = c.normal.y();
    row.friction = c.friction;
    const Softness soft = stepSoftness(c, terms, cache);
    setup.deepOverlap = c.deepOverlap;
    setup.pushOutShare = cache.share;
    setup.biasRate = soft.biasRate;
    setup.massScale = soft.massScale;
    setup.impulseScale = soft.impulseScale;
    for (int k = 0; k < 2; ++k) {
        RowPoint& r = row.p[k];
        if (k >= c.pointCount) {
            r = RowPoint{};
            setup.normalMass[k] = setup.compliance[k] = 0.0;
            separation_[2 * i + k] = 0.0;
            continue;
        }
        const ContactPoint& p = c.points[k];
        r.rAx = p.anchorA.x();
        r.rAy = p.anchorA.y();
        r.rBx = p.anchorB.x();
        r.rBy = p.anchorB.y();
        const double tx = row.ny, ty = -row.nx;
        r.rnA = r.rAx * row.ny - r.rAy * row.nx;
        r.rnB = r.rBx * row.ny - r.rBy * row.nx;
        r.rtA = r.rAx * ty - r.rAy * tx;
        r.rtB = r.rBx * ty - r.rBy * tx;
        separation_[2 * i + k] = r.baseSeparation = p.baseSeparation;
        setup.normalMass[k] = p.normalMass;
        r.tangentMass = p.tangentMass;
        // Converged, the soft update −m·s·(v_n + b) − r·λ = 0 is v_n + b + (r/(s·m))·λ = 0.
        setup.compliance[k] = soft.impulseScale / (soft.massScale * p.normalMass);
        // The warm start is the solve's own impulse of its last inner sub-step. What the
        // joined relax added after it (relaxJoined()) is an impulse for the whole step, through
        // the joints' inverse mass: warm-started here it acted in each inner sub-step on the free
        // bodies, and a ragdoll stopped on a stair with 16.6 and 19.0 N·s at two contacts took
        // them again in every inner sub-step of the next step, its torso and a forearm leaving
        // at 50 m/s (docs/robustness.md). The held forces still count it (forceOf()).
        r.normalImpulse = warmScale * p.solvedNormal;
        r.tangentImpulse = warmScale * p.solvedTangent;
        const Vec2 held = holding_ ? Vec2(h * Vec2(p.heldNormal, p.heldTangent)) : Vec2::Zero();
        r.heldNormal = held.x();
        r.heldTangent = held.y();
    }
    setup.blockable = false;
    row.k11 = row.k12 = row.k22 = 0.0;
    if (c.pointCount == 2) {
        const Vec2& n = c.normal;
        const BodyState& a = state_[row.a];
        const BodyState& b = state_[row.b];
        const double mA = a.invMass, iA = a.invInertia;
        const double mB = b.invMass, iB = b.invInertia;
        const double rn1A = cross(c.points[0].anchorA, n), rn1B = cross(c.points[0].anchorB, n);
        const double rn2A = cross(c.points[1].anchorA, n), rn2B = cross(c.points[1].anchorB, n);
        const contact_impulse::PairBlock k =
            contact_impulse::pairBlock(mA, iA, mB, iB, rn1A, rn1B, rn2A, rn2B);
        row.k11 = k.k11;
        row.k22 = k.k22;
        row.k12 = k.k12;
        setup.blockable = k.blockable;
    }
}

void ContactSolver::buildRows(double hertz, double zeta, double h, double warmScale) {
    // What does not change within the step, once: the rows' masses, the block's K and its
    // conditioning, the softness (each contact's stiffness multiplier: see prepare()).
    const int world = static_cast<int>(bodies_.size());
    lanesHold_ = instructions() > 0;  // the wide kernels are there (level 0: none)
    // Cleared first: rebuilt whole every step, so a growth copies nothing, and resize() writes
    // nothing (buildLanes() writes only the rows the scalar passes read).
    rows_.clear();
    setup_.clear();
    rows_.resize(constraints_.size());
    setup_.resize(constraints_.size());
    separation_.resize(2 * constraints_.size());
    // The rows with restitution, in order; their terms are filled where each row is built. Room
    // for all at once: a pile's tens of thousands would otherwise grow the arrays a doubling at a
    // time.
    bouncing_.clear();
    bouncing_.reserve(constraints_.size());
    handedOn_.clear();
    handedOn_.reserve(constraints_.size());
    bounceAt_.resize(constraints_.size());
    fastHanded_.clear();
    for (std::size_t i = 0; i < constraints_.size(); ++i) {
        const ContactConstraint& c = constraints_[i];
        const BounceRow row{static_cast<int>(i), c.bodyA >= 0 ? c.bodyA : world,
                            c.bodyB >= 0 ? c.bodyB : world, 0};
        if (c.restitution == 0.0) {
            bounceAt_[i] = -1;
            // Not through a jointed body: its impulse would move what the joints hold too, which
            // the passes do not see (a resting ragdoll's limbs were kicked into jitter).
            const bool jointed = (c.bodyA >= 0 && bodies_[c.bodyA].jointed) ||
                                 (c.bodyB >= 0 && bodies_[c.bodyB].jointed);
            if (jointed) continue;
            if (c.fast) fastHanded_.push_back(static_cast<int>(handedOn_.size()));
            handedOn_.push_back(row);
            continue;
        }
        bounceAt_[i] = static_cast<int>(bouncing_.size());
        bouncing_.push_back(row);
    }
    if (bouncing_.empty() && fastHanded_.empty()) handedOn_.clear();  // no impact to hand on
    bounceTerms_.clear();
    bounceTerms_.resize(bouncing_.size());
    handedTerms_.clear();
    handedTerms_.resize(handedOn_.size());
    handedMade_.assign(handedOn_.size(), 0);
    colourRows();
    const BuildTerms terms{hertz, zeta, h, warmScale};
    if (lanesHold_) {
        // The coloured rows straight into their lanes (a pyramid's rows_ were megabytes written
        // and read back once a step), the rest into rows_.
        buildLanes(terms);
        RowCache cache;
        for (const int i : overflow_) {
            const auto at = static_cast<std::size_t>(i);
            buildRow(at, rows_[at], setup_[at], terms, cache);
            if (bounceAt_[at] >= 0) fillBounce(at, rows_[at], setup_[at]);
        }
    } else {
        forChunks(constraints_.size(), kRowGrain, [&](std::size_t first, std::size_t end) {
            RowCache cache;
            for (std::size_t i = first; i < end; ++i) {
                buildRow(i, rows_[i], setup_[i], terms, cache);
                if (bounceAt_[i] >= 0) fillBounce(i, rows_[i], setup_[i]);
            }
        });
    }
    shifted_.resize(2 * rows_.size());
    bounces_.resize(2 * rows_.size());
    changedAt_.resize(bodies_.size() + 1);
}

void ContactSolver::fillBounce(std::size_t i, const Row& row, const RowSetup& setup) {
    fillBounceTerms(bounceTerms_[static_cast<std::size_t>(bounceAt_[i])],
                    constraints_[i].restitution, row, setup);
}

void ContactSolver::laneBounceTerms(std::size_t i, BounceTerms& t) const {
    const int at = lanesHold_ ? slot_[i] : -1;
    if (at < 0) {
        fillBounceTerms(t, constraints_[i].restitution, rows_[i], setup_[i]);
        return;
    }
    // The row as buildRow() made it, as far as the terms read it (unpackRows()'s reading).
    const WideRow& w = wide_[at / kLanes];
    const WideCold& u = wideCold_[at / kLanes];
    const WideSetup& S = wideSetup_[at / kLanes];
    const int l = at % kLanes;
    Row row{};
    RowSetup setup{};
    row.a = w.a[l];
    row.b = w.b[l];
    row.pointCount = u.points[l];
    row.nx = w.nx[l];
    row.ny = w.ny[l];
    if (row.pointCount == 2) {
        row.k11 = w.k11[l];
        row.k12 = w.k12[l];
        row.k22 = w.k22[l];
        setup.blockable = S.blockable[l] != 0;
    }
    for (int k = 0; k < row.pointCount; ++k) {
        RowPoint& p = row.p[k];
        p.rAx = u.p[k].rAx[l];
        p.rAy = u.p[k].rAy[l];
        p.rBx = u.p[k].rBx[l];
        p.rBy = u.p[k].rBy[l];
        setup.normalMass[k] = S.normalMass[k][l];
    }
    fillBounceTerms(t, constraints_[i].restitution, row, setup);
}

void ContactSolver::fillBounceTerms(BounceTerms& bounce, double restitution, const Row& row,
                                    const RowSetup& setup) const {
    const int world = static_cast<int>(bodies_.size());
    bounce.pointCount = row.pointCount;
    bounce.restitution = restitution;
    bounce.nx = row.nx;
    bounce.ny = row.ny;
    bounce.blockable = setup.blockable;
    bounce.k11 = row.k11;
    bounce.k12 = row.k12;
    bounce.k22 = row.k22;
    for (int k = 0; k < 2; ++k) {
        const bool used = k < row.pointCount;
        const RowPoint& p = row.p[k];
        bounce.smoothChange[k] = used ? smoothNormalChange(row, p) : 0.0;
        bounce.normalMass[k] = setup.normalMass[k];
        bounce.arm[k][0] = used ? p.rAx : 0.0;
        bounce.arm[k][1] = used ? p.rAy : 0.0;
        bounce.arm[k][2] = used ? p.rBx : 0.0;
        bounce.arm[k][3] = used ? p.rBy : 0.0;
    }
    bounce.isolated = (row.a == world || bodies_[row.a].contactCount == 1) &&
                      (row.b == world || bodies_[row.b].contactCount == 1);
}

void ContactSolver::unpackRows() {
    // Every coloured row as buildRow() made it, with the lanes' impulses: what relaxJoined()
    // reads of the rows.
    if (!lanesHold_) return;
    forChunks(rows_.size(), kRowGrain, [&](std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i) {
            const int at = slot_[i];
            if (at < 0) continue;
            Row& c = rows_[i];
            const WideRow& w = wide_[at / kLanes];
            const WideCold& u = wideCold_[at / kLanes];
            const int l = at % kLanes;
            c.a = w.a[l];
            c.b = w.b[l];
            c.pointCount = u.points[l];
            c.nx = w.nx[l];
            c.ny = w.ny[l];
            c.friction = w.friction[l];
            c.k11 = w.k11[l];
            c.k12 = w.k12[l];
            c.k22 = w.k22[l];
            for (int k = 0; k < 2; ++k) {
                RowPoint& p = c.p[k];
                if (k >= c.pointCount) {  // as buildRow() left it (a single row's lanes have none)
                    p = RowPoint{};
                    continue;
                }
                const WideRow::Point& q = w.p[k];
                const WideCold::Point& e = u.p[k];
                p.rAx = e.rAx[l];
                p.rAy = e.rAy[l];
                p.rBx = e.rBx[l];
                p.rBy = e.rBy[l];
                p.rnA = q.rnA[l];
                p.rnB = q.rnB[l];
                p.rtA = q.rtA[l];
                p.rtB = q.rtB[l];
                p.tangentMass = q.tangentMass[l];
                p.normalImpulse = q.normalImpulse[l];
                p.tangentImpulse = q.tangentImpulse[l];
                p.heldNormal = e.heldNormal[l];
                p.heldTangent = e.heldTangent[l];
                p.baseSeparation = e.baseSeparation[l];
            }
        }
    });
}

}  // namespace phasebox
