#pragma once
// Islands for sleeping (World, simulation.sleep): union-find over bodies, where two bodies share
// an island when a contact, a spring or a joint ties them. Static bodies, planes and the world
// never join one: two towers on one floor are two islands, and each sleeps on its own.
//
// The lower index becomes the root, so the partition and its roots do not depend on the order
// in which ties are added: the same scene sleeps the same way, bit for bit. Path halving keeps
// finds nearly constant; no rank is kept (the lower-index rule already decides).

#include "physics/core/Types.h"

#include <utility>
#include <vector>

namespace phasebox {

class Islands {
public:
    // count singletons; allocation-free once the buffer has grown to the scene's size.
    void reset(int count) {
        parent_.resize(static_cast<std::size_t>(count));
        for (int i = 0; i < count; ++i) parent_[i] = i;
    }
    int find(int i) {
        while (parent_[i] != i) {
            parent_[i] = parent_[parent_[i]];
            i = parent_[i];
        }
        return i;
    }
    void unite(int a, int b) {
        a = find(a);
        b = find(b);
        if (a == b) return;
        if (b < a) std::swap(a, b);
        parent_[b] = a;
    }

private:
    std::vector<int> parent_;
};

// The bodies asleep at one moment (World::sleepers()): which they are, the state their records
// keep while they sleep, and what of the ledger's energy they hold. Constant while the same
// islands sleep, so every recorded frame of that stretch shares one.
struct Sleepers {
    struct Body {
        bool rigid = false;
        int index = -1;  // in Bodies::particles or Bodies::rigidBodies
        Vec2 position{0.0, 0.0}, velocity{0.0, 0.0};
        double angle = 0.0, angularVelocity = 0.0;
    };
    std::vector<Body> bodies;  // particles first, then rigid bodies, each by index
    double kinetic = 0.0, potential = 0.0;
    std::size_t bytes() const { return sizeof(Sleepers) + bodies.size() * sizeof(Body); }
};

}  // namespace phasebox
