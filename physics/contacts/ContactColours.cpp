// The contact rows' graph colouring (Box2D v3's): the order the sweeps take, and the coloured rows
// built side by side kLanes at a time for the wide sweep (ContactWideLoop.inc), with what is fixed
// for the step in each lane (the phases' terms by ContactSolver::preparePhase).
#include "physics/contacts/ContactChunks.h"
#include "physics/contacts/ContactSolver.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <utility>

namespace phasebox {

using WideRow = ContactSolver::WideRow;
using WideCold = ContactSolver::WideCold;
using WideSetup = ContactSolver::WideSetup;

namespace {
// An unused lane: the static world joined to itself, every term zero (a colour's last wide row).
// An unused lane: its points' (the first only in a single wide row, whose block terms and
// second points no kernel reads).
void clearLane(WideRow& w, WideCold& u, WideSetup& S, int l, int world, int points) {
    w.a[l] = w.b[l] = world;
    u.points[l] = 0;
    for (double* lanes : {w.nx, w.ny, w.friction, w.iA, w.iB}) lanes[l] = 0.0;
    if (points == 2)
        for (double* lanes : {w.k11, w.k12, w.k22, w.i11, w.i12, w.i22, w.invA11, w.invA22})
            lanes[l] = 0.0;
    for (int k = 0; k < points; ++k) {
        WideRow::Point& q = w.p[k];
        for (double* lanes : {q.rnA, q.rnB, q.rtA, q.rtB, q.bias, q.effectiveMass, q.impulseScale,
                              q.tangentMass, q.normalImpulse, q.tangentImpulse})
            lanes[l] = 0.0;
        WideCold::Point& e = u.p[k];
        for (double* lanes : {e.rAx, e.rAy, e.rBx, e.rBy, e.heldNormal, e.heldTangent,
                              e.baseSeparation, e.separation})
            lanes[l] = 0.0;
        S.normalMass[k][l] = S.compliance[k][l] = 0.0;
    }
    for (double* lanes : {S.biasRate, S.massScale, S.impulseScale, S.deepOverlap, S.pushOutShare})
        lanes[l] = 0.0;
    S.blockable[l] = 0;
}
}  // namespace

static_assert(ContactSolver::kColours <= 64, "a body's colours are the bits of 64");

void ContactSolver::colourRows() {
    // Box2D v3's graph colouring: each row takes the first colour none of whose rows shares a
    // dynamic body with it (the static world is shared freely); rows no colour can take are
    // solved alone after the coloured ones. Colour by colour, in the constraints' order: the
    // sweep order is fixed, so the results are the same run to run.
    const std::size_t bodyCount = bodies_.size();
    const std::size_t rowCount = constraints_.size();
    const int world = static_cast<int>(bodyCount);
    const auto bodiesOf = [world](const ContactConstraint& c) {
        return std::pair<int, int>{c.bodyA >= 0 ? c.bodyA : world, c.bodyB >= 0 ? c.bodyB : world};
    };
    // The colouring is a function of the rows' bodies, in order, and of the body count alone: where
    // every row joins the same two bodies as the row of its index did at the last colouring (a
    // resting stack, step after step), that colouring stands, and only the lanes are built anew.
    const bool sameRows = [&] {
        if (rowCount == 0 || colouredPairs_.size() != rowCount || slot_.size() != rowCount ||
            !overflow_.empty() || colourMask_.size() != bodyCount + 1)
            return false;
        for (std::size_t i = 0; i < rowCount; ++i)
            if (bodiesOf(constraints_[i]) != colouredPairs_[i]) return false;
        return true;
    }();
    if (!sameRows) {
        // Per body the colours its rows have taken, a bit each (the static world takes none): a
        // row's colour is the lowest bit free in both of its bodies' sets.
        colourMask_.assign(bodyCount + 1, 0u);
        blockCount_.assign(static_cast<std::size_t>(kColours) * kBlocks, 0);
        slot_.resize(rowCount);
        colouredPairs_.resize(rowCount);
        overflow_.clear();
        constexpr std::uint64_t kAllColours =
            kColours == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << kColours) - 1;
        colours_ = 0;
        for (std::size_t i = 0; i < rowCount; ++i) {
            const auto [a, b] = colouredPairs_[i] = bodiesOf(constraints_[i]);
            const std::uint64_t free = ~(colourMask_[a] | colourMask_[b]) & kAllColours;
            if (free == 0) {
                slot_[i] = -1;
                overflow_.push_back(static_cast<int>(i));
                continue;
            }
            const int colour = std::countr_zero(free);
            colours_ = std::max(colours_, colour + 1);
            if (a != world) colourMask_[a] |= std::uint64_t{1} << colour;
            if (b != world) colourMask_[b] |= std::uint64_t{1} << colour;
            // The block of one of the row's bodies: the dynamic one beside the world, else the
            // lower or the higher by the parity of their sum. Always the lower would crowd the
            // first blocks where pairs are far apart in the order (a pile, a gas: the lower of two
            // random bodies is in the first half three times in four, and the first of two workers
            // would start with three rows in four); where they are near (a stack) either keeps the
            // row beside its bodies.
            const int pick = a == world         ? b
                             : b == world       ? a
                             : (a + b) % 2 == 0 ? std::min(a, b)
                                                : std::max(a, b);
            const auto at = static_cast<std::size_t>(pick);
            const int block = std::min(
                static_cast<int>(at * kBlocks / std::max<std::size_t>(bodyCount, 1)), kBlocks - 1);
            slot_[i] = colour * kBlocks + block;  // the colour and block for now, the lane below
            ++blockCount_[slot_[i]];
        }
        // Each colour starts a new wide row, its blocks follow one another in it; blockCount_
        // becomes each block's next slot. A wide row across two blocks belongs to the later one.
        int wideRows = 0;
        colourWide_.resize(kColours + 1);
        blockWide_.resize(static_cast<std::size_t>(kColours) * (kBlocks + 1));
        for (int colour = 0; colour < colours_; ++colour) {
            colourWide_[colour] = wideRows;
            int* starts = blockWide_.data() + colour * (kBlocks + 1);
            int offset = 0;
            for (int block = 0; block < kBlocks; ++block) {
                int& count = blockCount_[colour * kBlocks + block];
                starts[block] = wideRows + offset / kLanes;
                const int n = count;
                count = kLanes * wideRows + offset;
                offset += n;
            }
            wideRows += (offset + kLanes - 1) / kLanes;
            starts[kBlocks] = wideRows;
        }
        // The colours none took are empty, at the end (the passes stop at colours_).
        std::fill(colourWide_.begin() + colours_, colourWide_.end(), wideRows);
        for (std::size_t i = 0; i < rowCount; ++i) {
            if (slot_[i] < 0) continue;
            slot_[i] = blockCount_[slot_[i]]++;
        }
        wide_.resize(wideRows);
        wideCold_.resize(wideRows);
        wideClosing_.resize(wideRows);
        closingWide_.assign(wideRows, 0);
        singleWide_.resize(wideRows);
        wideSetup_.resize(wideRows);
        order_.assign(kLanes * wideRows, -1);
        // Slots past the end are forgotten: a row built again there later is built whole.
        laneKey_.resize(static_cast<std::size_t>(kLanes) * wideRows, kNoLane);
        for (std::size_t i = 0; i < rowCount; ++i)
            if (slot_[i] >= 0) order_[slot_[i]] = static_cast<int>(i);
    }
}

void ContactSolver::buildLanes(const BuildTerms& terms) {
    const int world = static_cast<int>(bodies_.size());
    // The lanes, wide row by wide row (each written by one chunk: shared by the workers).
    forColours([&](std::size_t first, std::size_t end) {
        RowCache cache;
        for (std::size_t r = first; r < end; ++r) {
            WideRow& w = wide_[r];
            WideCold& u = wideCold_[r];
            WideSetup& S = wideSetup_[r];
            // The next wide row's constraints are scattered over the constraints' megabytes (a
            // pile's): their lines are asked for now, while this one's are built.
            if (r + 1 < end)
                for (int l = 0; l < kLanes; ++l) {
                    const int i = order_[kLanes * (r + 1) + l];
                    if (i < 0) continue;
                    const char* constraint = reinterpret_cast<const char*>(&constraints_[i]);
                    for (std::size_t at = 0; at < sizeof(ContactConstraint); at += 64)
                        __builtin_prefetch(constraint + at);
                    __builtin_prefetch(constraint + sizeof(ContactConstraint) - 1);
                }
            // A wide row none of whose lanes has a second point: the kernels read neither the
            // second points nor the block terms, so they are not written (half the lines).
            bool single = true;
            for (int l = 0; l < kLanes; ++l) {
                const int i = order_[kLanes * r + l];
                single = single && (i < 0 || constraints_[i].pointCount < 2);
            }
            singleWide_[r] = single;
            const int points = single ? 1 : 2;
            if (sameLanes(r)) {
                refreshLanes(r, terms, cache);
                continue;
            }
            for (int l = 0; l < kLanes; ++l) {
                const int i = order_[kLanes * r + l];
                laneKey_[kLanes * r + l] =
                    i < 0 || !constraints_[i].kept ? kNoLane : constraints_[i].key;
            }
            for (int l = 0; l < kLanes; ++l) {
                const int i = order_[kLanes * r + l];
                if (i < 0) {
                    clearLane(w, u, S, l, world, points);
                    continue;
                }
                // On the stack: the scalar passes read only the overflow's rows (a bounce
                // reads its terms, made here).
                const auto at = static_cast<std::size_t>(i);
                Row c;
                RowSetup setup;
                buildRow(at, c, setup, terms, cache);
                if (bounceAt_[at] >= 0) fillBounce(at, c, setup);
                const BodyState& a = state_[c.a];
                const BodyState& b = state_[c.b];
                w.a[l] = c.a;
                w.b[l] = c.b;
                w.nx[l] = c.nx;
                w.ny[l] = c.ny;
                w.friction[l] = c.friction;
                w.iA[l] = a.invInertia;
                w.iB[l] = b.invInertia;
                if (!single) {
                    w.k11[l] = c.k11;
                    w.k12[l] = c.k12;
                    w.k22[l] = c.k22;
                }
                for (int k = 0; k < points; ++k) {
                    const RowPoint& p = c.p[k];
                    WideRow::Point& q = w.p[k];
                    WideCold::Point& e = u.p[k];
                    e.rAx[l] = p.rAx;
                    e.rAy[l] = p.rAy;
                    e.rBx[l] = p.rBx;
                    e.rBy[l] = p.rBy;
                    q.rnA[l] = p.rnA;
                    q.rnB[l] = p.rnB;
                    q.rtA[l] = p.rtA;
                    q.rtB[l] = p.rtB;
                    q.tangentMass[l] = p.tangentMass;
                    q.normalImpulse[l] = p.normalImpulse;
                    q.tangentImpulse[l] = p.tangentImpulse;
                    e.heldNormal[l] = p.heldNormal;
                    e.heldTangent[l] = p.heldTangent;
                    e.baseSeparation[l] = e.separation[l] = p.baseSeparation;
                }
                u.points[l] = c.pointCount;
                S.biasRate[l] = setup.biasRate;
                S.massScale[l] = setup.massScale;
                S.impulseScale[l] = setup.impulseScale;
                for (int k = 0; k < points; ++k) {
                    S.normalMass[k][l] = setup.normalMass[k];
                    S.compliance[k][l] = setup.compliance[k];
                }
                S.deepOverlap[l] = setup.deepOverlap;
                S.pushOutShare[l] = setup.pushOutShare;
                S.blockable[l] = setup.blockable ? -1LL : 0LL;
            }
        }
    });
}

bool ContactSolver::sameLanes(std::size_t r) const {
    // Every lane holds the contact it held last step, kept as it was (ContactConstraint::kept:
    // the same anchors, normal, masses and stiffness), and none bounces (its bounce terms are
    // made with the row).
    for (int l = 0; l < kLanes; ++l) {
        const std::size_t slot = kLanes * r + static_cast<std::size_t>(l);
        const int i = order_[slot];
        if (i < 0) return false;
        const ContactConstraint& c = constraints_[static_cast<std::size_t>(i)];
        if (!c.kept || c.restitution != 0.0 || laneKey_[slot] != c.key) return false;
    }
    return true;
}

void ContactSolver::refreshLanes(std::size_t r, const BuildTerms& terms, RowCache& cache) {
    // What buildRow() makes anew each step, the rest standing in the lanes: the bodies' indices
    // (numbered as the contacts come), the warm start at this step's sub-step, the held forces,
    // the separations back to where the contacts were found, the softness and the push-out share.
    const int world = static_cast<int>(bodies_.size());
    WideRow& w = wide_[r];
    WideCold& u = wideCold_[r];
    WideSetup& S = wideSetup_[r];
    for (int l = 0; l < kLanes; ++l) {
        const auto i = static_cast<std::size_t>(order_[kLanes * r + static_cast<std::size_t>(l)]);
        const ContactConstraint& c = constraints_[i];
        w.a[l] = c.bodyA >= 0 ? c.bodyA : world;
        w.b[l] = c.bodyB >= 0 ? c.bodyB : world;
        const Softness soft = stepSoftness(c, terms, cache);
        S.biasRate[l] = soft.biasRate;
        S.massScale[l] = soft.massScale;
        S.impulseScale[l] = soft.impulseScale;
        S.pushOutShare[l] = cache.share;
        for (int k = 0; k < 2; ++k) {
            if (k >= c.pointCount) {
                separation_[2 * i + static_cast<std::size_t>(k)] = 0.0;
                continue;
            }
            const ContactPoint& p = c.points[k];
            WideRow::Point& q = w.p[k];
            WideCold::Point& e = u.p[k];
            separation_[2 * i + static_cast<std::size_t>(k)] = p.baseSeparation;
            e.separation[l] = p.baseSeparation;
            S.compliance[k][l] = soft.impulseScale / (soft.massScale * p.normalMass);
            q.normalImpulse[l] = terms.warmScale * p.solvedNormal;  // as buildRow()'s
            q.tangentImpulse[l] = terms.warmScale * p.solvedTangent;
            const Vec2 held =
                holding_ ? Vec2(terms.h * Vec2(p.heldNormal, p.heldTangent)) : Vec2::Zero();
            e.heldNormal[l] = held.x();
            e.heldTangent[l] = held.y();
        }
    }
}

}  // namespace phasebox
