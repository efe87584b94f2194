// The contact solver's bounce passes: restitution applied at the impact, within the inner
// sub-step, before the soft solve (see ContactSolver.h for the whole step).

#include "physics/contacts/ContactImpulse.h"
#include "physics/contacts/ContactSolver.h"

#include <algorithm>
#include <limits>

namespace phasebox {

using namespace contact_impulse;

namespace {
constexpr int kMaxCollisionPasses = 32;
// A point's first bounces in an inner sub-step take its restitution, later ones none
// (Guendelman, Bridson & Fedkiw 2003: restitution for a few passes, then inelastic ones that
// converge). Bodies that overlap one another with e = 1 otherwise reflect among themselves
// for ever, positions being fixed during the passes: a pile of disks started at one point went
// through all the passes every sub-step, half of its step time. Four covers a cradle's wave
// (one bounce per contact) and a ball caught between two others.
constexpr int kElasticBounces = 4;
// A body held by its support holds against an impulse within 45° of the support's push.
constexpr double kSupportCosine = 0.7071;
}  // namespace

void ContactSolver::oneSidedTerms(BounceTerms& t, const BodyState& a, const BodyState& b) {
    // The masses of the row with a held body's inverse masses zero (buildRow()'s K, pairBlock());
    // no time-of-impact shift (that moves both).
    double rn[2][2] = {};
    for (int k = 0; k < t.pointCount; ++k) {
        const double* arm = t.arm[k];
        rn[k][0] = arm[0] * t.ny - arm[1] * t.nx;
        rn[k][1] = arm[2] * t.ny - arm[3] * t.nx;
        const double kn = a.invMass + b.invMass + a.invInertia * rn[k][0] * rn[k][0] +
                          b.invInertia * rn[k][1] * rn[k][1];
        t.normalMass[k] = kn > 0.0 ? 1.0 / kn : 0.0;
    }
    t.isolated = false;
    if (t.pointCount < 2) return;
    const PairBlock k = pairBlock(a.invMass, a.invInertia, b.invMass, b.invInertia, rn[0][0],
                                  rn[0][1], rn[1][0], rn[1][1]);
    t.k11 = k.k11;
    t.k12 = k.k12;
    t.k22 = k.k22;
    t.blockable = t.blockable && k.blockable;
}

bool ContactSolver::bounce(double h, int substeps, const ContactSettings& settings) {
    // Passes on the current velocities until no contact that meets within this inner sub-step
    // approaches faster than the threshold: v_n ← −e·v_n. Each application conserves energy
    // exactly when e = 1 whatever else touches the bodies, and the passes let a row of touching
    // balls hand an impact on ball by ball (Newton's cradle). Bouncing in the inner sub-steps
    // puts the impact within 1/kInnerRate s of its true time whatever the frame: the velocity
    // reflected is the one of the impact, not the end of a long step's (a ball dropped 1 m at
    // dt = 1 s would otherwise leave at 9.8 m/s and climb far above where it fell from).
    // A bounce is handed on through the contacts without restitution too, inelastically (e = 0:
    // v_n ← 0 where the bodies meet faster than the threshold), to the bodies it reaches.
    // Returns whether a body was moved to its time of impact (its separations changed).
    if (!bounces()) return false;
    std::fill(shifted_.begin(), shifted_.end(), 0);
    std::fill(bounces_.begin(), bounces_.end(), 0);
    // The separations, fixed for the call: gathered from the lanes where most rows bounce (a
    // pile), looked up row by row where few do.
    const double* separations =
        2 * bouncing_.size() >= rows_.size() ? gatherSeparations() : nullptr;
    const int world = static_cast<int>(bodies_.size());
    // A row whose bodies took no impulse since it was last looked at would decide as it did
    // then (its separation and smooth change are fixed for the call): it is skipped, so the
    // later passes cost what changes, not every row again.
    changedAt_.resize(bodies_.size() + 1);  // no allocation once warm
    std::fill(changedAt_.begin(), changedAt_.end(), 0u);
    std::uint32_t clock = 1;
    BodyState* state = state_.data();
    bool moved = false;
    bool any = false;        // an impulse in this pass
    bool supported = false;  // support_ is set for this call (at the first impulse)
    // A row looked at: its points that meet within the sub-step bounce. held: 1 or 2 where body
    // A or B is held by its support (below), and the impulse moves the other alone.
    const auto visit = [&](BounceRow& r, const BounceTerms& terms, int held) {
        const int i = r.row;
        r.checkedAt = clock;
        BodyState* pa = &state[r.a];
        BodyState* pb = &state[r.b];
        BodyState still{};
        BounceTerms oneSided;
        const BounceTerms* pt = &terms;
        if (held != 0) {
            // The held body as the static world, with its velocity: the other meets it as it moves.
            still = held == 1 ? *pa : *pb;
            still.invMass = still.invInertia = 0.0;
            (held == 1 ? pa : pb) = &still;
            oneSided = terms;
            oneSidedTerms(oneSided, *pa, *pb);
            pt = &oneSided;
        }
        const BounceTerms& t = *pt;
        const double ownRestitution = t.restitution;
        BodyState& a = *pa;
        BodyState& b = *pb;
        // A point's impact now: its approach at the moment the bodies meet (vi), the
        // restitution it takes, and whether it must bounce.
        double vi[2] = {0.0, 0.0}, e[2] = {0.0, 0.0}, sep[2] = {0.0, 0.0};
        bool hit[2] = {false, false};
        const auto measure = [&](int k) {
            const double* arm = t.arm[k];
            const double s = separations ? separations[2 * i + k] : separationOf(i, k);
            const double vn = relativeVelocity(a, b, arm[0], arm[1], arm[2], arm[3], t.nx, t.ny);
            sep[k] = s;
            hit[k] = false;
            // The threshold keeps resting contact quiet (gravity presses a box on the floor
            // at g·h per sub-step); it shrinks with 1 − e, so that e = 1 is exactly elastic
            // however slow the collision, as the lecture's e = 1 means.
            if (vn >= 0.0 || s + h * vn > 0.0) return;
            // The smooth forces' share of this sub-step, taken as a constant acceleration
            // a: the bodies meet at τ with v_i = v_n − a·(h − τ), slower than at the
            // sub-step's end, and leave at −e·v_i (without this a dropped ball rebounds up
            // to e·g·h faster than it hit: 2.7% too high at 240 sub-steps a second).
            const double smooth = t.smoothChange[k] / substeps;
            const double tau = s > 0.0 ? std::min(h, s / -vn) : 0.0;
            vi[k] = std::min(vn - smooth * (h - tau) / h, 0.0);
            e[k] = bounces_[2 * i + k] < kElasticBounces ? ownRestitution : 0.0;
            hit[k] = vi[k] < -settings.restitutionThreshold * (1.0 - e[k]);
        };
        for (int k = 0; k < t.pointCount; ++k) measure(k);
        // A point's impulse λ along the normal, and its positional twin (Time of impact:
        // the bodies meet s/|v_n| into the sub-step and separate for the rest of it, so
        // they end (1 + e)·s closer than moving by h·v_new from the sub-step's start
        // implies; without the shift every rebound would start early and rise (1 + e)·s too
        // high. Only for an isolated pair: shifting a body that touches others could push
        // it into them.)
        const auto apply = [&](int k, double lambda, double shift) {
            const double* arm = t.arm[k];
            removeImpulse(a, arm[0], arm[1], lambda * t.nx, lambda * t.ny);
            applyImpulse(b, arm[2], arm[3], lambda * t.nx, lambda * t.ny);
            any = true;
            ++bounces_[2 * i + k];
            ++clock;
            if (r.a != world && held != 1) changedAt_[r.a] = clock;
            if (r.b != world && held != 2) changedAt_[r.b] = clock;
            // Met by the static world or a held body: held in turn, along the impulse it took
            // (support_ is cleared at the call's first impulse).
            if (!handedOn_.empty()) {
                if (!supported) support_.assign(bodies_.size() + 1, Vec2::Zero());
                supported = true;
                if ((r.a == world || held == 1) && r.b != world) support_[r.b] = Vec2(t.nx, t.ny);
                if ((r.b == world || held == 2) && r.a != world) support_[r.a] = -Vec2(t.nx, t.ny);
            }
            if (!(shift > 0.0) || !t.isolated || shifted_[2 * i + k]) return;
            shifted_[2 * i + k] = 1;
            moved = true;
            const double sx = shift * t.nx, sy = shift * t.ny;
            const Vec2 rA(arm[0], arm[1]), rB(arm[2], arm[3]);
            // A positional impulse: moves the bodies without changing their velocities.
            if (r.a != world) {
                SolverBody& body = bodies_[r.a];
                body.timeShift += body.invMass * Vec2(sx, sy);
                body.angleTimeShift += body.invInertia * cross(rA, Vec2(sx, sy));
            }
            if (r.b != world) {
                SolverBody& body = bodies_[r.b];
                body.timeShift += body.invMass * Vec2(-sx, -sy);
                body.angleTimeShift += body.invInertia * cross(rB, Vec2(-sx, -sy));
            }
        };
        // Both points of a manifold hit at once (a box landing flat): one impulse pair
        // K·λ = −(1 + e)·v_i that ends both approaches together. Point by point, the first
        // point's impulse would turn the body and the second's turn it back with a bounce
        // left over: a box dropped flat with e = 0 left the floor spinning and toppled.
        if (hit[0] && hit[1] && t.blockable) {
            const double b0 = -(1.0 + e[0]) * vi[0], b1 = -(1.0 + e[1]) * vi[1];
            // The linear complementarity problem of the pair (as Box2D's block solver): both
            // points pushing, or one alone with the other leaving at least as fast as asked.
            // An impulse whose exact value is zero (a box landing on another's edge, the load
            // all through the point under its centre) comes out a rounding either side of it:
            // a tolerance of a relative 10⁻⁹ keeps it in the block.
            const double tol = 1e-9 * (b0 + b1);
            const double det = t.k11 * t.k22 - t.k12 * t.k12;
            double l0 = (t.k22 * b0 - t.k12 * b1) / det;
            double l1 = (t.k11 * b1 - t.k12 * b0) / det;
            bool solved = l0 >= -tol && l1 >= -tol;
            if (!solved && t.k12 * (b0 / t.k11) >= b1 - tol) {
                l0 = b0 / t.k11;  // the first alone
                l1 = 0.0;
                solved = true;
            } else if (!solved && t.k12 * (b1 / t.k22) >= b0 - tol) {
                l0 = 0.0;  // the second alone
                l1 = b1 / t.k22;
                solved = true;
            }
            if (solved) {
                l0 = std::max(l0, 0.0);
                l1 = std::max(l1, 0.0);
                // The shifts by the same block, so that a flat landing moves flat.
                const double d0 = (1.0 + e[0]) * std::max(sep[0], 0.0);
                const double d1 = (1.0 + e[1]) * std::max(sep[1], 0.0);
                double s0 = (t.k22 * d0 - t.k12 * d1) / det;
                double s1 = (t.k11 * d1 - t.k12 * d0) / det;
                if (s0 < 0.0 || s1 < 0.0) s0 = s1 = 0.0;
                apply(0, l0, s0);
                apply(1, l1, s1);
                return;
            }
        }
        // Point by point, each seeing what the one before did.
        for (int k = 0; k < t.pointCount; ++k) {
            if (k > 0) measure(k);
            if (!hit[k]) continue;
            const double normalMass = t.normalMass[k];
            apply(k, -normalMass * (1.0 + e[k]) * vi[k], (1.0 + e[k]) * sep[k] * normalMass);
        }
    };
    const auto unchanged = [&](const BounceRow& r) {
        return changedAt_[r.a] <= r.checkedAt && changedAt_[r.b] <= r.checkedAt;
    };
    bool handing = false;  // some bounce has reached the rows without restitution
    for (int pass = 0; pass < kMaxCollisionPasses; ++pass) {
        any = false;
        for (std::size_t n = 0; n < bouncing_.size(); ++n) {
            BounceRow& r = bouncing_[n];
            if (pass > 0 && unchanged(r)) continue;
            visit(r, bounceTerms_[n], 0);
        }
        // A body a bounce moved hands the impact on through its contacts without restitution,
        // inelastically: a tower landing on the floor stops box by box within the passes (as in
        // Guendelman, Bridson & Fedkiw's collision passes). Left to the soft solve, whose few
        // iterations cannot stop a column at once, the boxes sank into each other by centimetres
        // and were pushed apart: ten boxes dropped 3 m onto a floor of e = 0.5 sent the top one
        // up at 5.0 m/s, where the floor's restitution allows 3.8.
        // A fast row is looked at from the first pass, as one with restitution is.
        if (!handedOn_.empty() && (clock > 1 || (pass == 0 && !fastHanded_.empty()))) {
            if (!handing) {
                handing = true;
                for (BounceRow& r : handedOn_) r.checkedAt = 0;
            }
            const auto look = [&](std::size_t n) {
                BounceRow& r = handedOn_[n];
                if (!handedMade_[n]) {
                    handedMade_[n] = 1;
                    laneBounceTerms(static_cast<std::size_t>(r.row), handedTerms_[n]);
                }
                // Shock propagation (Guendelman, Bridson & Fedkiw): a body the static world or a
                // held body has just met (its support), pushed further into that support, does
                // not give way; the body meeting it takes its velocity, as a rigid stack landing
                // would. Pairwise, each inelastic hand-on up a tower halved the approach (the two
                // leave at their mean velocity), and three boxes up it fell below the threshold:
                // the boxes above sank into each other; a brick-bonded pyramid landing on a floor
                // of e = 0.5 was spread by the passes' pairwise pushes (its correction 370 J,
                // then 790 J). Only where that slows the other body: at each point the
                // two bodies' speeds along the normal sum to the held one's side (the impulse λ
                // on the other does work λ·(v + v')/2 ≤ 0). A domino still turning on the floor,
                // met by the next one, passed its turn on for nothing.
                const BounceTerms& t = handedTerms_[n];
                const Vec2 normal(t.nx, t.ny);
                const BodyState& a = state[r.a];
                const BodyState& b = state[r.b];
                double most = -std::numeric_limits<double>::infinity(), least = -most;
                for (int k = 0; k < t.pointCount; ++k) {
                    const double* arm = t.arm[k];
                    const double sum = t.nx * (a.vx - a.w * arm[1] + b.vx - b.w * arm[3]) +
                                       t.ny * (a.vy + a.w * arm[0] + b.vy + b.w * arm[2]);
                    most = std::max(most, sum);
                    least = std::min(least, sum);
                }
                const bool holdsA =
                    supported && support_[r.a].dot(normal) > kSupportCosine && most <= 0.0;
                const bool holdsB =
                    supported && support_[r.b].dot(normal) < -kSupportCosine && least >= 0.0;
                visit(r, t, holdsA == holdsB ? 0 : (holdsA ? 1 : 2));
            };
            if (pass == 0)
                for (const int n : fastHanded_) look(static_cast<std::size_t>(n));
            if (clock > 1)
                for (std::size_t n = 0; n < handedOn_.size(); ++n)
                    if (!unchanged(handedOn_[n])) look(n);
        }
        if (!any) break;
    }
    return moved;
}

}  // namespace phasebox
