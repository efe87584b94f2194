// The contact rows' graph colouring (Box2D v3's): the order the sweeps take, and the coloured rows
// side by side four at a time for the wide sweep (ContactWideLoop.inc), with what is fixed for the
// step in each lane (the phases' terms by ContactSolver::prepareWide, ContactLanes.cpp).
#include "physics/contacts/ContactSolver.h"

#include <algorithm>
#include <cstdint>

namespace phasebox {

using WideRow = ContactSolver::WideRow;

void ContactSolver::colourRows() {
    // Box2D v3's graph colouring: each row takes the first colour none of whose rows shares a
    // dynamic body with it (the static world is shared freely); rows no colour can take are
    // solved alone after the coloured ones. Colour by colour, in the constraints' order: the
    // sweep order is fixed, so the results are the same run to run.
    const std::size_t bodyCount = bodies_.size();
    const int world = static_cast<int>(bodyCount);
    const std::size_t words = (bodyCount + 63) / 64;
    colourBits_.assign(kColours * words, 0);
    colourCount_.assign(kColours + 1, 0);
    slot_.resize(rows_.size());
    overflow_.clear();
    auto taken = [&](int colour, int body) {
        return body != world && (colourBits_[colour * words + body / 64] >> (body % 64) & 1u) != 0;
    };
    auto take = [&](int colour, int body) {
        if (body != world)
            colourBits_[colour * words + body / 64] |= std::uint64_t{1} << (body % 64);
    };
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        const Row& c = rows_[i];
        int colour = 0;
        while (colour < kColours && (taken(colour, c.a) || taken(colour, c.b))) ++colour;
        if (colour == kColours) {
            slot_[i] = -1;
            overflow_.push_back(static_cast<int>(i));
            continue;
        }
        take(colour, c.a);
        take(colour, c.b);
        slot_[i] = colour;  // the colour for now, the lane below
        ++colourCount_[colour];
    }
    // Each colour starts a new wide row; colourCount_ becomes each colour's next slot.
    int wideRows = 0;
    colourWide_.resize(kColours + 1);
    for (int colour = 0; colour < kColours; ++colour) {
        const int n = colourCount_[colour];
        colourCount_[colour] = 4 * wideRows;
        colourWide_[colour] = wideRows;
        wideRows += (n + 3) / 4;
    }
    colourWide_[kColours] = wideRows;
    wide_.resize(wideRows);
    wideSetup_.resize(4 * static_cast<std::size_t>(wideRows));
    order_.assign(4 * wideRows, -1);
    for (WideRow& w : wide_) {
        w = WideRow{};
        for (int l = 0; l < 4; ++l) w.a[l] = w.b[l] = world;
    }
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        if (slot_[i] < 0) continue;
        const int at = colourCount_[slot_[i]]++;
        slot_[i] = at;
        order_[at] = static_cast<int>(i);
        WideRow& w = wide_[at / 4];
        const int l = at % 4;
        const Row& c = rows_[i];
        const BodyState& a = state_[c.a];
        const BodyState& b = state_[c.b];
        w.a[l] = c.a;
        w.b[l] = c.b;
        w.nx[l] = c.nx;
        w.ny[l] = c.ny;
        w.friction[l] = c.friction;
        w.mA[l] = a.invMass;
        w.iA[l] = a.invInertia;
        w.mB[l] = b.invMass;
        w.iB[l] = b.invInertia;
        w.k11[l] = c.k11;
        w.k12[l] = c.k12;
        w.k22[l] = c.k22;
        for (int k = 0; k < 2; ++k) {
            const RowPoint& p = c.p[k];
            WideRow::Point& q = w.p[k];
            q.rAx[l] = p.rAx;
            q.rAy[l] = p.rAy;
            q.rBx[l] = p.rBx;
            q.rBy[l] = p.rBy;
            q.tangentMass[l] = p.tangentMass;
            q.normalImpulse[l] = p.normalImpulse;
            q.tangentImpulse[l] = p.tangentImpulse;
            q.heldNormal[l] = p.heldNormal;
            q.heldTangent[l] = p.heldTangent;
            q.baseSeparation[l] = q.separation[l] = p.baseSeparation;
        }
        w.points[l] = c.pointCount;
        wideSetup_[at] = setup_[i];
    }
}

}  // namespace phasebox
