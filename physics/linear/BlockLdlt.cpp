#include "physics/linear/BlockLdlt.h"

#include <algorithm>
#include <iterator>
#include <tuple>
#include <utility>

namespace phasebox {

// ---- the symbolic part -----------------------------------------------------------------------

void BlockLdltPattern::analyse(std::vector<std::set<int>> graph, const std::vector<char>& late) {
    const int m = static_cast<int>(graph.size());
    // Minimum-fill elimination (ties: the smaller degree, then the node that has waited
    // longest): each eliminated node's remaining neighbours become a clique (the fill), and
    // they are the later nodes its column of L couples. The joint graph of a chain or tree of
    // bodies is chordal, so a joint whose neighbours already form a clique (fill 0) always
    // exists and the order makes no fill at all; minimum degree alone can miss it in a tree.
    // The longest wait first takes a chain from both its ends in turn (a tree from all its
    // leaves), so the factorization's and the solves' recurrences run as independent chains
    // that the processor overlaps: by the smaller index, a 100-hinge chain was one recurrence
    // from its root, and the solves were a fifth of the whip's time.
    std::vector<std::vector<int>> later(m);
    const auto fillOf = [&](int k) {
        const long long degree = static_cast<long long>(graph[k].size());
        if (degree > kCountedDegree) return degree * (degree - 1) / 2;
        long long fill = 0;
        for (auto x = graph[k].begin(); x != graph[k].end(); ++x)
            for (auto y = std::next(x); y != graph[k].end(); ++y) fill += !graph[*x].count(*y);
        return fill;
    };
    using Key = std::tuple<int, long long, int, int, int>;  // late, fill, degree, since, node
    std::set<Key> queue;
    std::vector<Key> key(m);
    const auto isLate = [&](int k) { return late.empty() ? 0 : static_cast<int>(late[k] != 0); };
    for (int k = 0; k < m; ++k) {
        key[k] = {isLate(k), fillOf(k), static_cast<int>(graph[k].size()), 0, k};
        queue.insert(key[k]);
    }
    order_.clear();
    position_.assign(m, -1);
    while (!queue.empty()) {
        const int k = std::get<4>(*queue.begin());
        queue.erase(queue.begin());
        position_[k] = static_cast<int>(order_.size());
        order_.push_back(k);
        const std::vector<int> neighbours(graph[k].begin(), graph[k].end());
        later[k] = neighbours;
        for (int x : neighbours) graph[x].erase(k);
        bool filled = false;
        for (std::size_t s = 0; s < neighbours.size(); ++s)
            for (std::size_t t = s + 1; t < neighbours.size(); ++t)
                if (graph[neighbours[s]].insert(neighbours[t]).second) {
                    graph[neighbours[t]].insert(neighbours[s]);
                    filled = true;
                }
        // The fill of the neighbours may have changed, and where edges were added that of
        // their neighbours too (a node's fill counts the missing edges among its neighbours:
        // without new edges, only the neighbours' own adjacency changed).
        std::set<int> touched(neighbours.begin(), neighbours.end());
        if (filled)
            for (int x : neighbours) touched.insert(graph[x].begin(), graph[x].end());
        const int now = static_cast<int>(order_.size());
        for (int x : touched) {
            const long long fill = fillOf(x);
            const int degree = static_cast<int>(graph[x].size());
            if (fill == std::get<1>(key[x]) && degree == std::get<2>(key[x])) continue;
            queue.erase(key[x]);
            key[x] = {isLate(x), fill, degree, now, x};
            queue.insert(key[x]);
        }
    }
    upperStart_.assign(m + 1, 0);
    upper_.clear();
    for (int p = 0; p < m; ++p) {
        std::vector<int> list;
        for (int x : later[order_[p]]) list.push_back(position_[x]);
        std::sort(list.begin(), list.end());
        upper_.insert(upper_.end(), list.begin(), list.end());
        upperStart_[p + 1] = static_cast<int>(upper_.size());
    }
    updateStart_.assign(m + 1, 0);
    updates_.clear();
    for (int p = 0; p < m; ++p) {
        for (int t1 = upperStart_[p]; t1 < upperStart_[p + 1]; ++t1)
            for (int t2 = upperStart_[p]; t2 < upperStart_[p + 1]; ++t2) {
                const int i = upper_[t1], j = upper_[t2];
                if (i == j)
                    updates_.push_back({t1, t2, -1});
                else if (j < i)
                    updates_.push_back({t1, t2, blockIndex(j, i)});
            }
        updateStart_[p + 1] = static_cast<int>(updates_.size());
    }
}

int BlockLdltPattern::blockIndex(int p, int i) const {
    const auto begin = upper_.begin() + upperStart_[p], end = upper_.begin() + upperStart_[p + 1];
    return static_cast<int>(std::lower_bound(begin, end, i) - upper_.begin());
}

// ---- the numeric part ------------------------------------------------------------------------

template <int B>
void BlockLdlt<B>::factor(const BlockLdltPattern& pattern) {
    const int m = pattern.size();
    const std::vector<int>& upperStart = pattern.upperStart();
    const std::vector<int>& upper = pattern.upper();
    const std::vector<int>& updateStart = pattern.updateStart();
    const std::vector<BlockLdltPattern::Update>& updates = pattern.updates();
    for (int p = 0; p < m; ++p) {
        dinv_[p] = diag_[p].inverse();
        for (int t = upperStart[p]; t < upperStart[p + 1]; ++t) l_[t] = off_[t] * dinv_[p];
        for (int s = updateStart[p]; s < updateStart[p + 1]; ++s) {
            const BlockLdltPattern::Update& up = updates[s];
            if (up.target < 0)
                diag_[upper[up.t1]] -= l_[up.t1] * off_[up.t1].transpose();
            else
                off_[up.target] -= l_[up.t1] * off_[up.t2].transpose();
        }
    }
}

template class BlockLdlt<2>;
template class BlockLdlt<3>;

}  // namespace phasebox
