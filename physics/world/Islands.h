#pragma once
// Islands for sleeping (World, simulation.sleep): union-find over bodies, where two bodies share
// an island when a contact, a spring or a joint ties them. Static bodies, planes and the world
// never join one: two towers on one floor are two islands, and each sleeps on its own.
//
// The lower index becomes the root, so the partition and its roots do not depend on the order
// in which ties are added: the same scene sleeps the same way, bit for bit. Path halving keeps
// finds nearly constant; no rank is kept (the lower-index rule already decides).

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

}  // namespace phasebox
