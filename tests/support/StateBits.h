#pragma once
// A world's state as bits, with the clock and the energy ledger, for tests that ask "the same
// state, bit for bit" (a restored snapshot, a recorded frame, a replayed step): -0.0 and 0.0
// differ here, and so does any last-bit change a tolerance would hide.

#include "physics/world/World.h"
#include "physics/world/WorldSnapshot.h"

#include <bit>
#include <cstdint>
#include <vector>

namespace phasebox::testing {

inline std::vector<std::uint64_t> stateBits(const Vec& q, const Vec& u, double t,
                                            const EnergyLedger& e) {
    std::vector<std::uint64_t> bits;
    for (const Vec* v : {&q, &u})
        for (Eigen::Index i = 0; i < v->size(); ++i)
            bits.push_back(std::bit_cast<std::uint64_t>((*v)[i]));
    for (double v : {t, e.kinetic, e.potential, e.workNc, e.drift, e.correction, e.maxAbsDrift})
        bits.push_back(std::bit_cast<std::uint64_t>(v));
    return bits;
}

inline std::vector<std::uint64_t> stateBits(const World& w) {
    return stateBits(w.positions(), w.velocities(), w.time(), w.energy());
}

// Every body's state as the world reports it (a body asleep: its record) and whether it
// sleeps: what stateBits leaves out when bodies sleep (they are out of q and u).
// withSleep false: the state alone.
inline void appendBodyBits(const World& w, std::vector<std::uint64_t>& bits,
                           bool withSleep = true) {
    const auto add = [&](double v) { bits.push_back(std::bit_cast<std::uint64_t>(v)); };
    for (int i = 0; i < static_cast<int>(w.particles().size()); ++i) {
        for (const Vec2& v : {w.particlePosition(i), w.particleVelocity(i)}) {
            add(v.x());
            add(v.y());
        }
        if (withSleep) bits.push_back(w.particles()[static_cast<std::size_t>(i)].asleep);
    }
    for (int i = 0; i < static_cast<int>(w.rigidBodies().size()); ++i) {
        for (const Vec2& v : {w.bodyPosition(i), w.bodyVelocity(i)}) {
            add(v.x());
            add(v.y());
        }
        add(w.bodyAngle(i));
        add(w.bodyAngularVelocity(i));
        if (withSleep) bits.push_back(w.rigidBodies()[static_cast<std::size_t>(i)].asleep);
    }
}

inline std::vector<std::uint64_t> stateBits(const FrameState& f) {
    return stateBits(f.q, f.u, f.time, f.ledger);
}

}  // namespace phasebox::testing
