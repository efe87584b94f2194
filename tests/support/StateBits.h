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

inline std::vector<std::uint64_t> stateBits(const FrameState& f) {
    return stateBits(f.q, f.u, f.time, f.ledger);
}

}  // namespace phasebox::testing
