#pragma once
// Impulses on the contact solver's body states and a two-point manifold's block, shared by its
// passes (ContactSolver.cpp, ContactBounce.cpp, ContactRows.cpp). Private to physics/contacts.

namespace phasebox::contact_impulse {

// Adds the impulse (px, py) at arm (rx, ry) to a body (a static one has zero inverse masses).
template <class State>
inline void applyImpulse(State& b, double rx, double ry, double px, double py) {
    b.vx += b.invMass * px;
    b.vy += b.invMass * py;
    b.w += b.invInertia * (rx * py - ry * px);
}
template <class State>
inline void removeImpulse(State& b, double rx, double ry, double px, double py) {
    b.vx -= b.invMass * px;
    b.vy -= b.invMass * py;
    b.w -= b.invInertia * (rx * py - ry * px);
}
// Relative velocity of the contact point along (dx, dy): (v_B + ω_B × r_B − v_A − ω_A × r_A)·d.
template <class State>
inline double relativeVelocity(const State& a, const State& b, double rAx, double rAy, double rBx,
                               double rBy, double dx, double dy) {
    const double vx = (b.vx - b.w * rBy) - (a.vx - a.w * rAy);
    const double vy = (b.vy + b.w * rBx) - (a.vy + a.w * rAx);
    return dx * vx + dy * vy;
}

// The normal rows' 2×2 mass matrix K of a two-point manifold, from the bodies' inverse masses
// and each point's arm crossed with the normal (rn1A = r₁A × n, ...), and whether it is well
// enough conditioned to be solved as a block (nearly coincident points make K singular: the
// sequential solve handles them).
struct PairBlock {
    double k11, k12, k22;
    bool blockable;
};
inline PairBlock pairBlock(double mA, double iA, double mB, double iB, double rn1A, double rn1B,
                           double rn2A, double rn2B) {
    PairBlock k;
    k.k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
    k.k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
    k.k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
    k.blockable = !(k.k11 * k.k11 >= 1000.0 * (k.k11 * k.k22 - k.k12 * k.k12));
    return k;
}

}  // namespace phasebox::contact_impulse
