// The sweep-and-prune broad phase against brute force (every pair tested): random boxes spread
// out and clustered, from none to 2,000, over successive calls with the boxes moving a little
// (the persistent order repaired by insertion sort), far (the order scrambled), and with the
// count growing and shrinking (the order rebuilt). The pair lists must be equal, element by
// element. Once its buffers have grown, a call allocates nothing. A 10,000-box run prints its
// timing.

#include "physics/contacts/BroadPhase.h"
#include "physics/core/WorkerPool.h"

#include "../bench/AllocationCounter.h"

#include <QElapsedTimer>
#include <QTest>

#include <algorithm>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

using namespace phasebox;

namespace {

using Pairs = std::vector<std::pair<int, int>>;

Pairs bruteForce(const std::vector<Aabb>& boxes) {
    Pairs pairs;
    const int n = static_cast<int>(boxes.size());
    for (int i = 0; i < n; ++i) {
        for (int j = i + 1; j < n; ++j) {
            if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
        }
    }
    return pairs;
}

// Boxes of sizes up to maxSize, spread uniformly over a square of side `extent`, or gathered
// in a few tight clusters (many overlaps, many equal-looking lower x).
class BoxMaker {
public:
    BoxMaker(unsigned seed, double extent, double maxSize, int clusters)
        : rng_(seed), extent_(extent), maxSize_(maxSize) {
        std::uniform_real_distribution<double> where(0.0, extent);
        for (int k = 0; k < clusters; ++k) clusterCentres_.emplace_back(where(rng_), where(rng_));
    }

    Aabb make() {
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        Vec2 centre;
        if (clusterCentres_.empty()) {
            centre = {extent_ * unit(rng_), extent_ * unit(rng_)};
        } else {
            std::uniform_int_distribution<std::size_t> pick(0, clusterCentres_.size() - 1);
            std::normal_distribution<double> spread(0.0, 0.02 * extent_);
            centre = clusterCentres_[pick(rng_)] + Vec2(spread(rng_), spread(rng_));
        }
        const Vec2 half(0.5 * maxSize_ * unit(rng_), 0.5 * maxSize_ * unit(rng_));
        return {centre - half, centre + half};
    }

    std::vector<Aabb> make(int n) {
        std::vector<Aabb> boxes;
        for (int i = 0; i < n; ++i) boxes.push_back(make());
        return boxes;
    }

    // Moves every box by up to `step` in each direction (a step of a simulation).
    void move(std::vector<Aabb>& boxes, double step) {
        std::uniform_real_distribution<double> d(-step, step);
        for (Aabb& b : boxes) {
            const Vec2 shift(d(rng_), d(rng_));
            b.lower += shift;
            b.upper += shift;
        }
    }

    std::mt19937& rng() { return rng_; }

private:
    std::mt19937 rng_;
    double extent_, maxSize_;
    std::vector<Vec2> clusterCentres_;
};

struct Layout {
    const char* name;
    double extent, maxSize;
    int clusters;
};

const Layout kLayouts[] = {
    {"spread", 100.0, 2.0, 0},    {"spread, large boxes", 100.0, 20.0, 0},
    {"clustered", 100.0, 2.0, 4}, {"one tight cluster", 100.0, 1.0, 1},
    {"points", 10.0, 0.0, 0},
};

// The caps by their definition: the boxes in order of their lower bound on the sweep axis, each
// pair (i, j) of overlapping boxes with j after i taken in that order, and kept unless a
// capped side has reached its cap (a kApart box never meets another kApart box).
Pairs cappedReference(const std::vector<Aabb>& boxes, int axis, const PairCap& cap) {
    const int n = static_cast<int>(boxes.size());
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return boxes[a].lower[axis] < boxes[b].lower[axis]; });
    std::vector<int> overlapping(n, 0), near(n, 0);
    const auto& limited = *cap.limited;
    const auto& size = *cap.size;
    Pairs pairs;
    for (int k = 0; k < n; ++k) {
        const int i = order[k];
        for (int l = k + 1; l < n; ++l) {
            const int j = order[l];
            if (boxes[j].lower[axis] > boxes[i].upper[axis]) break;
            if (!boxes[i].overlaps(boxes[j])) continue;
            if (limited[i] == PairCap::kApart && limited[j] == PairCap::kApart) continue;
            if (limited[i] != PairCap::kFree && limited[j] != PairCap::kFree) {
                const Vec2 offset =
                    (boxes[j].lower + boxes[j].upper) - (boxes[i].lower + boxes[i].upper);
                const double reach = 2.0 * (size[i] + size[j]);
                std::vector<int>& taken = offset.squaredNorm() < reach * reach ? overlapping : near;
                const int most = &taken == &overlapping ? cap.perBox : cap.nearPerBox;
                const bool forI = size[j] >= 0.5 * size[i], forJ = size[i] >= 0.5 * size[j];
                if ((forI && taken[i] >= most) || (forJ && taken[j] >= most)) continue;
                taken[i] += forI;
                taken[j] += forJ;
            }
            pairs.emplace_back(std::min(i, j), std::max(i, j));
        }
    }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

// Each box's kind for the caps and its shape's size: a twentieth free (static bodies), a fifth
// apart (particles that do not collide), the rest capped, sizes 0.1 to 1 (tight: none free,
// sizes 0.5 to 0.6, so that a box whose caps are full can take no further partner).
struct CapKinds {
    std::vector<unsigned char> limited;
    std::vector<double> size;
};
CapKinds randomCapKinds(BoxMaker& maker, std::size_t count, bool tight) {
    std::uniform_int_distribution<int> kind(tight ? 1 : 0, 19);
    std::uniform_real_distribution<double> radius(tight ? 0.5 : 0.1, tight ? 0.6 : 1.0);
    CapKinds kinds{std::vector<unsigned char>(count), std::vector<double>(count)};
    for (std::size_t i = 0; i < count; ++i) {
        const int k = kind(maker.rng());
        kinds.limited[i] = k == 0 ? PairCap::kFree : k < 5 ? PairCap::kApart : PairCap::kCapped;
        kinds.size[i] = radius(maker.rng());
    }
    return kinds;
}
}  // namespace

class TestBroadPhase : public QObject {
    Q_OBJECT

private slots:
    void matchesBruteForce_data();
    void matchesBruteForce();
    void touchingAndIdenticalBoxes();
    void countChangesBetweenCalls();
    void scrambledOrder();
    void noAllocationOnceWarm();
    void cappedFollowsTheSweepOrder();
    void grownBoundsKeepThePairs();
    void timing10000();
};

void TestBroadPhase::matchesBruteForce_data() {
    QTest::addColumn<int>("count");
    QTest::addColumn<int>("layout");
    for (const int n : {0, 1, 2, 3, 17, 200, 2000}) {
        for (int l = 0; l < static_cast<int>(std::size(kLayouts)); ++l) {
            QTest::addRow("%d %s", n, kLayouts[l].name) << n << l;
        }
    }
}

void TestBroadPhase::matchesBruteForce() {
    QFETCH(int, count);
    QFETCH(int, layout);
    const Layout& l = kLayouts[layout];
    BoxMaker maker(1000u + count * 7u + layout, l.extent, l.maxSize, l.clusters);
    std::vector<Aabb> boxes = maker.make(count);
    BroadPhase broadPhase;
    Pairs pairs;
    // Successive calls on one broad phase, as in a simulation: the first sorts from scratch,
    // the rest repair the kept order after every box moved by up to a tenth of the largest size.
    for (int step = 0; step < 12; ++step) {
        broadPhase.findPairs(boxes, pairs);
        QVERIFY2(pairs == bruteForce(boxes), qPrintable(QStringLiteral("step %1").arg(step)));
        maker.move(boxes, 0.1 * std::max(l.maxSize, 0.5));
    }
}

void TestBroadPhase::touchingAndIdenticalBoxes() {
    // Shared edges count as overlap (as in Aabb::overlaps), and many equal lower x must not
    // lose pairs.
    std::vector<Aabb> boxes;
    for (int i = 0; i < 50; ++i) boxes.push_back({{0.0, 0.0}, {1.0, 1.0}});
    for (int i = 0; i < 20; ++i) {
        boxes.push_back({{1.0 + i, 5.0}, {2.0 + i, 6.0}});  // a row touching end to end
    }
    boxes.push_back({{1.0, 1.0}, {1.0, 1.0}});  // a point on the first boxes' corner
    BroadPhase broadPhase;
    Pairs pairs;
    broadPhase.findPairs(boxes, pairs);
    QCOMPARE(pairs, bruteForce(boxes));
    QCOMPARE(pairs.size(), std::size_t(50 * 49 / 2 + 19 + 50));
}

void TestBroadPhase::countChangesBetweenCalls() {
    BoxMaker maker(77u, 50.0, 2.0, 0);
    std::vector<Aabb> boxes = maker.make(300);
    BroadPhase broadPhase;
    Pairs pairs;
    std::uniform_int_distribution<int> change(-40, 40);
    for (int step = 0; step < 60; ++step) {
        broadPhase.findPairs(boxes, pairs);
        QVERIFY2(pairs == bruteForce(boxes), qPrintable(QStringLiteral("step %1").arg(step)));
        maker.move(boxes, 0.1);
        // Every third step boxes come or go (removed from anywhere, added at the end), down to
        // none and back.
        if (step % 3 == 0) {
            const int delta = step == 30 ? -static_cast<int>(boxes.size()) : change(maker.rng());
            if (delta > 0) {
                for (int k = 0; k < delta; ++k) boxes.push_back(maker.make());
            } else {
                for (int k = 0; k < -delta && !boxes.empty(); ++k) {
                    std::uniform_int_distribution<std::size_t> at(0, boxes.size() - 1);
                    boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(at(maker.rng())));
                }
            }
        }
    }
}

void TestBroadPhase::scrambledOrder() {
    // Same count but every box somewhere else: the kept order is useless and insertion sort
    // has the most to do; the answer must still be exact.
    BoxMaker maker(5u, 100.0, 3.0, 0);
    BroadPhase broadPhase;
    Pairs pairs;
    for (int round = 0; round < 5; ++round) {
        const std::vector<Aabb> boxes = maker.make(800);
        broadPhase.findPairs(boxes, pairs);
        QCOMPARE(pairs, bruteForce(boxes));
    }
}

void TestBroadPhase::noAllocationOnceWarm() {
    using namespace phasebox::bench;
    BoxMaker maker(31u, 60.0, 2.0, 0);
    std::vector<Aabb> boxes = maker.make(1000);
    BroadPhase broadPhase;
    Pairs pairs;
    broadPhase.findPairs(boxes, pairs);
    pairs.reserve(4 * pairs.size() + 64);  // room for the pairs that motion adds
    startCountingAllocations();
    for (int step = 0; step < 20; ++step) {
        maker.move(boxes, 0.05);
        broadPhase.findPairs(boxes, pairs);
    }
    const AllocationCounts counts = stopCountingAllocations();
    QCOMPARE(pairs, bruteForce(boxes));
    if (!kCountsAllocations)
        qInfo("allocations are not counted under AddressSanitizer; the release build checks them");
    QCOMPARE(counts.total(), 0LL);
}

void TestBroadPhase::cappedFollowsTheSweepOrder() {
    // Caps that bind (a few partners a box) on clustered boxes of mixed sizes, some free (a
    // static body), some apart (particles that do not collide), a few wide enough to cross
    // many bands of the sweep's other axis: the pairs kept are those of the definition, on one
    // thread and shared among workers, as the boxes move from call to call.
    // Seed 8: one tight cluster of boxes all capped and of nearly one size, where a box whose
    // caps are full can take no further partner (the sweep stops early).
    for (const unsigned seed : {5u, 6u, 7u, 8u}) {
        const bool tight = seed == 8u;
        BoxMaker maker(seed, tight ? 20.0 : 100.0, 2.0, seed == 5u ? 0 : tight ? 1 : 6);
        std::vector<Aabb> boxes = maker.make(2000);
        for (int w = 0; w < 8; ++w) {
            const Vec2 at(12.0 * w, 10.0 * (w % 3));
            boxes.push_back({at, at + (w % 2 ? Vec2(30.0, 1.0) : Vec2(1.0, 30.0))});
        }
        const CapKinds kinds = randomCapKinds(maker, boxes.size(), tight);
        const PairCap cap{&kinds.limited, &kinds.size, 3, 4};
        for (const int workers : {1, 2, 4}) {
            WorkerPool pool(workers);
            BroadPhase broadPhase;
            Pairs pairs;
            std::vector<Aabb> moving = boxes;
            for (int step = 0; step < 4; ++step) {
                broadPhase.findPairs(moving, pairs, cap, &pool);
                QVERIFY2(pairs == cappedReference(moving, broadPhase.axis(), cap),
                         qPrintable(QStringLiteral("seed %1, %2 workers, step %3")
                                        .arg(seed)
                                        .arg(workers)
                                        .arg(step)));
                maker.move(moving, 0.3);
            }
        }
    }
}

void TestBroadPhase::grownBoundsKeepThePairs() {
    // ContactStage keeps the pairs of bounds grown by a margin while the bounds stay inside the
    // grown ones, and takes as a frame's pairs those kept pairs whose own bounds overlap. That is
    // the sweep's answer exactly when the caps chose nothing (capBound() false): checked here on
    // moving boxes, free, apart and capped, with caps too large to bind; with caps that bind,
    // capBound() says so.
    BoxMaker maker(11u, 60.0, 2.0, 6);
    const std::vector<Aabb> boxes = maker.make(1500);
    const CapKinds kinds = randomCapKinds(maker, boxes.size(), false);
    const PairCap loose{&kinds.limited, &kinds.size, 1000, 1000};
    const PairCap tight{&kinds.limited, &kinds.size, 3, 4};
    constexpr double kMargin = 0.2;
    std::vector<Aabb> grown = boxes;
    for (Aabb& b : grown) {
        b.lower -= Vec2::Constant(kMargin);
        b.upper += Vec2::Constant(kMargin);
    }
    BroadPhase broadPhase, fresh;
    Pairs kept, pairs;
    broadPhase.findPairs(grown, kept, loose);
    QVERIFY(!broadPhase.capBound());
    QVERIFY(kept.size() > boxes.size());  // a real test: many pairs, more than the frames' own
    std::vector<Aabb> moving = boxes;
    for (int frame = 0; frame < 6; ++frame) {
        Pairs filtered;
        for (const auto& [i, j] : kept)
            if (moving[i].overlaps(moving[j])) filtered.emplace_back(i, j);
        fresh.findPairs(moving, pairs, loose);
        QVERIFY(!fresh.capBound());
        QVERIFY2(filtered == pairs, qPrintable(QStringLiteral("frame %1").arg(frame)));
        QVERIFY(filtered.size() < kept.size());
        // Each box moves by less than the margin in all, so it stays inside its grown bounds.
        maker.move(moving, kMargin / 8.0);
    }
    fresh.findPairs(moving, pairs, tight);
    QVERIFY(fresh.capBound());
    QVERIFY(pairs == cappedReference(moving, fresh.axis(), tight));
    fresh.findPairs(moving, pairs);  // no caps at all
    QVERIFY(!fresh.capBound());
}

void TestBroadPhase::timing10000() {
    // A sanity print, not an assertion: 10,000 boxes of size ≤ 1 over 100×100 (a quarter of the
    // area covered, most boxes touching a neighbour or two), the first call sorting and then
    // steps that move every box a little.
    BoxMaker maker(10000u, 100.0, 1.0, 0);
    std::vector<Aabb> boxes = maker.make(10000);
    BroadPhase broadPhase;
    Pairs pairs;
    QElapsedTimer timer;
    timer.start();
    broadPhase.findPairs(boxes, pairs);
    const double firstMs = timer.nsecsElapsed() * 1e-6;
    QCOMPARE(pairs, bruteForce(boxes));

    constexpr int kSteps = 50;
    double stepsMs = 0.0;
    for (int step = 0; step < kSteps; ++step) {
        maker.move(boxes, 0.02);
        timer.restart();
        broadPhase.findPairs(boxes, pairs);
        stepsMs += timer.nsecsElapsed() * 1e-6;
    }
    QCOMPARE(pairs, bruteForce(boxes));
    qInfo("10,000 boxes, %zu pairs: first call %.3f ms, then %.3f ms per step", pairs.size(),
          firstMs, stepsMs / kSteps);
}

QTEST_APPLESS_MAIN(TestBroadPhase)
#include "tst_broadphase.moc"
