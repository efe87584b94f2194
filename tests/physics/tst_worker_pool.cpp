// The worker pool (physics/core/WorkerPool.h) against what it promises: every index of a range
// runs exactly once, in chunks cut by count and grain alone; results assembled per chunk are
// bit-identical for 1, 2, 3, 4 and 8 workers; empty ranges run nothing; the exception of the
// lowest chunk reaches the caller whatever the number of workers, and the pool still works after
// it; pools start, change size and stop cleanly, also with loops never run.

#include "physics/core/WorkerPool.h"

#include <QTest>

#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

using namespace phasebox;

namespace {

const std::vector<int> kWorkerCounts = {1, 2, 3, 4, 8};

// A value per index whose sum in another order gives other bits.
double term(int i) {
    return 1.0 / (1.0 + 0.37 * i) + std::sin(0.001 * i);
}

// Per-chunk sums, added in chunk order: the pool's deterministic reduction.
double chunkedSum(WorkerPool& pool, int count, int grain) {
    std::vector<double> partial(static_cast<std::size_t>(WorkerPool::chunkCount(count, grain)));
    pool.parallelFor(count, grain, [&](int begin, int end, int) {
        double s = 0.0;
        for (int i = begin; i < end; ++i) s += term(i);
        partial[static_cast<std::size_t>(begin / grain)] = s;
    });
    double total = 0.0;
    for (double s : partial) total += s;
    return total;
}

}  // namespace

class TestWorkerPool : public QObject {
    Q_OBJECT

private slots:
    void coversEveryIndexOnceInFixedChunks_data() {
        QTest::addColumn<int>("count");
        QTest::addColumn<int>("grain");
        QTest::newRow("one item") << 1 << 16;
        QTest::newRow("one chunk") << 16 << 16;
        QTest::newRow("a short last chunk") << 1001 << 64;
        QTest::newRow("items one by one") << 777 << 1;
        QTest::newRow("many chunks") << 100003 << 97;
        QTest::newRow("fewer chunks than workers") << 100 << 40;
        QTest::newRow("grain below one is one") << 50 << 0;
    }
    void coversEveryIndexOnceInFixedChunks() {
        QFETCH(int, count);
        QFETCH(int, grain);
        const int step = grain < 1 ? 1 : grain;
        for (int workers : kWorkerCounts) {
            WorkerPool pool(workers);
            QCOMPARE(pool.workers(), workers);
            std::vector<std::atomic<int>> visits(static_cast<std::size_t>(count));
            std::vector<std::atomic<int>> chunkEnd(
                static_cast<std::size_t>(WorkerPool::chunkCount(count, grain)));
            std::atomic<int> badWorker{0}, badChunk{0};
            for (int repeat = 0; repeat < 3; ++repeat)
                pool.parallelFor(count, grain, [&](int begin, int end, int worker) {
                    if (worker < 0 || worker >= workers) ++badWorker;
                    if (begin % step != 0 || end - begin > step || end <= begin) ++badChunk;
                    chunkEnd[static_cast<std::size_t>(begin / step)] = end;
                    for (int i = begin; i < end; ++i) ++visits[static_cast<std::size_t>(i)];
                });
            QCOMPARE(badWorker.load(), 0);
            QCOMPARE(badChunk.load(), 0);
            for (int i = 0; i < count; ++i) QCOMPARE(visits[static_cast<std::size_t>(i)].load(), 3);
            // The cut is count and grain alone: chunk c ends at min((c + 1)·grain, count).
            for (std::size_t c = 0; c < chunkEnd.size(); ++c)
                QCOMPARE(chunkEnd[c].load(), std::min(static_cast<int>(c + 1) * step, count));
        }
    }

    void resultsAreBitIdenticalForAnyNumberOfWorkers() {
        const int count = 200000, grain = 333;
        WorkerPool one(1);
        const double reference = chunkedSum(one, count, grain);
        std::vector<double> perItem(count);
        one.parallelFor(count, grain, [&](int begin, int end, int) {
            for (int i = begin; i < end; ++i) perItem[static_cast<std::size_t>(i)] = term(i) * i;
        });
        for (int workers : kWorkerCounts) {
            WorkerPool pool(workers);
            for (int repeat = 0; repeat < 5; ++repeat) {
                const double sum = chunkedSum(pool, count, grain);
                QCOMPARE(std::bit_cast<std::uint64_t>(sum),
                         std::bit_cast<std::uint64_t>(reference));
                std::vector<double> out(count, 0.0);
                pool.parallelFor(count, grain, [&](int begin, int end, int) {
                    for (int i = begin; i < end; ++i)
                        out[static_cast<std::size_t>(i)] = term(i) * i;
                });
                QVERIFY(out == perItem);
            }
        }
    }

    void sharesOnlyLoopsOfSeveralChunks() {
        WorkerPool pool(2);
        pool.parallelFor(10, 10, [](int, int, int) {});
        pool.parallelFor(0, 10, [](int, int, int) {});
        QCOMPARE(pool.sharedLoops(), 0LL);
        pool.parallelFor(20, 10, [](int, int, int) {});
        QCOMPARE(pool.sharedLoops(), 1LL);
        WorkerPool single(1);
        single.parallelFor(1000, 1, [](int, int, int) {});
        QCOMPARE(single.sharedLoops(), 0LL);
    }

    void emptyRangesRunNothing() {
        for (int workers : kWorkerCounts) {
            WorkerPool pool(workers);
            int calls = 0;
            for (int count : {0, -1, -1000})
                pool.parallelFor(count, 4, [&](int, int, int) { ++calls; });
            QCOMPARE(calls, 0);
            QCOMPARE(WorkerPool::chunkCount(0, 4), 0);
            QCOMPARE(WorkerPool::chunkCount(-3, 4), 0);
        }
    }

    void theLowestChunksExceptionReachesTheCaller() {
        for (int workers : kWorkerCounts) {
            WorkerPool pool(workers);
            std::atomic<int> ran{0};
            try {
                pool.parallelFor(64, 4, [&](int begin, int, int) {
                    ++ran;
                    if (begin == 12 || begin == 40 || begin == 60)
                        throw std::runtime_error(std::to_string(begin));
                });
                QFAIL("no exception reached the caller");
            } catch (const std::runtime_error& e) {
                // Serially the loop stops at the first throw; shared, every chunk runs.
                QCOMPARE(QString::fromStdString(e.what()), QStringLiteral("12"));
            }
            QVERIFY(ran.load() >= 4);
            // And the pool goes on working.
            std::atomic<int> sum{0};
            pool.parallelFor(100, 3, [&](int begin, int end, int) { sum += end - begin; });
            QCOMPARE(sum.load(), 100);
        }
    }

    void nestedLoopsRunOnTheirThread() {
        WorkerPool pool(4);
        std::vector<std::atomic<int>> visits(40 * 50);
        std::atomic<int> notOnTheirThread{0};
        pool.parallelFor(40, 2, [&](int begin, int end, int) {
            for (int i = begin; i < end; ++i)
                pool.parallelFor(50, 5, [&](int b, int e, int worker) {
                    if (worker != 0) ++notOnTheirThread;
                    for (int k = b; k < e; ++k) ++visits[static_cast<std::size_t>(i * 50 + k)];
                });
        });
        QCOMPARE(notOnTheirThread.load(), 0);
        for (const auto& v : visits) QCOMPARE(v.load(), 1);
    }

    void startsResizesAndStopsCleanly() {
        // Never used, used once, resized between loops, destroyed right after a loop.
        { WorkerPool idle(8); }
        for (int round = 0; round < 20; ++round) {
            auto pool = std::make_unique<WorkerPool>(1 + round % 4);
            std::atomic<long long> total{0};
            pool->parallelFor(1000, 7, [&](int begin, int end, int) {
                for (int i = begin; i < end; ++i) total += i;
            });
            QCOMPARE(total.load(), 999LL * 1000 / 2);
            pool->setWorkers(1 + (round + 1) % 4);
            QCOMPARE(pool->workers(), 1 + (round + 1) % 4);
            total = 0;
            pool->parallelFor(1000, 7, [&](int begin, int end, int) {
                for (int i = begin; i < end; ++i) total += i;
            });
            QCOMPARE(total.load(), 999LL * 1000 / 2);
        }
        WorkerPool all;
        QCOMPARE(all.workers(), WorkerPool::allCores());
        all.setWorkers(0);
        QCOMPARE(all.workers(), WorkerPool::allCores());
        QVERIFY(WorkerPool::allCores() >= 1);
    }

    void manySmallLoopsInARow() {
        // The step's pattern: thousands of short loops back to back, helpers spinning or asleep.
        WorkerPool pool(3);
        std::vector<int> out(256);
        long long expected = 0, seen = 0;
        for (int loop = 0; loop < 5000; ++loop) {
            pool.parallelFor(256, 16, [&](int begin, int end, int) {
                for (int i = begin; i < end; ++i) out[static_cast<std::size_t>(i)] = i + loop;
            });
            for (int v : out) seen += v;
            expected += 256LL * 255 / 2 + 256LL * loop;
        }
        QCOMPARE(seen, expected);
    }

    void loopsOfChangingSizesInARow() {
        // Each worker's share of a loop is cut anew from its chunk count: a helper that finishes
        // one loop late must not take a chunk of the next one twice, or miss one, whether the
        // next has more chunks than workers, as many, or fewer.
        for (int workers : kWorkerCounts) {
            WorkerPool pool(workers);
            std::vector<std::atomic<int>> visits(512);
            for (int loop = 0; loop < 3000; ++loop) {
                const int count = 1 + (loop * 37) % 512;
                const int grain = 1 + (loop * 13) % 64;
                pool.parallelFor(count, grain, [&](int begin, int end, int) {
                    for (int i = begin; i < end; ++i) ++visits[static_cast<std::size_t>(i)];
                });
                for (int i = 0; i < 512; ++i) {
                    const int seen = visits[static_cast<std::size_t>(i)].exchange(0);
                    if (seen != (i < count ? 1 : 0))
                        QFAIL(qPrintable(QStringLiteral("loop %1 (%2 items in chunks of %3), %4 "
                                                        "workers: item %5 ran %6 times")
                                             .arg(loop)
                                             .arg(count)
                                             .arg(grain)
                                             .arg(workers)
                                             .arg(i)
                                             .arg(seen)));
                }
            }
        }
    }
};

QTEST_APPLESS_MAIN(TestWorkerPool)
#include "tst_worker_pool.moc"
