#pragma once
// Impulses on the contact solver's body states, shared by its passes (ContactSolver.cpp,
// ContactBounce.cpp). Private to physics/contacts.

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

}  // namespace phasebox::contact_impulse
