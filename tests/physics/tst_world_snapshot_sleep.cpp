// Snapshots and recorded frames with simulation.sleep on (WorldSnapshot, FrameState): the
// 20-row pyramid with a box that slides into its apex after it fell asleep, so that a run holds
// every change of layout (awake, all 210 asleep, woken by the slider, asleep again). A snapshot
// restored anywhere in it and stepped on gives the same bits as the run that was never
// interrupted, whatever the world slept like when it was restored; a recorded frame shown in a
// world of any layout is that moment's whole state, the bodies asleep then included.

#include "../bench/SleepScenes.h"
#include "physics/scene/BuildWorld.h"
#include "physics/world/World.h"
#include "physics/world/WorldSnapshot.h"
#include "tests/support/StateBits.h"

#include <QTest>

#include <bit>
#include <cstdint>
#include <vector>

using namespace phasebox;

namespace {

constexpr int kBoxes = 210;
constexpr double kEnd = 12.0;  // s: the slider has woken the apex and it slept again

// The state as bits (testing::stateBits: the awake bodies' state, the clock, the ledger), the
// step count, and every body's state and sleep as the world reports it.
std::vector<std::uint64_t> bitsOf(const World& w) {
    std::vector<std::uint64_t> bits = testing::stateBits(w);
    bits.push_back(static_cast<std::uint64_t>(w.stepCount()));
    bits.push_back(static_cast<std::uint64_t>(w.sleepingBodies()));
    testing::appendBodyBits(w, bits);
    return bits;
}

struct Run {
    std::unique_ptr<World> world = buildWorld(sleep_scenes::pyramidAndSlider(true)).world;
    std::vector<std::vector<std::uint64_t>> reference;  // after step k (k = 0: the start)
    std::vector<FrameState> frames;
    std::vector<WorldSnapshot> snapshots;
    std::vector<long long> snapshotSteps;
    long long asleepAt = -1, wokenAt = -1, asleepAgainAt = -1;

    Run() {
        world->commit();
        reference.push_back(bitsOf(*world));
        frames.push_back(FrameState::of(*world));
        while (world->time() < kEnd) {
            const long long k = world->stepCount();
            // Snapshots awake, asleep, and just after the wake.
            if (k == 60 || (asleepAt >= 0 && k == asleepAt + 30) ||
                (wokenAt >= 0 && k == wokenAt + 2)) {
                snapshots.push_back(WorldSnapshot::take(*world));
                snapshotSteps.push_back(k);
            }
            if (!world->step()) return;
            const int asleep = world->sleepingBodies();
            if (asleepAt < 0 && asleep >= kBoxes) asleepAt = world->stepCount();
            if (asleepAt >= 0 && wokenAt < 0 && asleep < kBoxes) wokenAt = world->stepCount();
            if (wokenAt >= 0 && asleepAgainAt < 0 && asleep >= kBoxes)
                asleepAgainAt = world->stepCount();
            reference.push_back(bitsOf(*world));
            frames.push_back(FrameState::of(*world));
        }
    }
};

}  // namespace

class TestWorldSnapshotSleep : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        run_ = std::make_unique<Run>();
        QVERIFY2(run_->asleepAt > 0, "the pyramid did not fall asleep");
        QVERIFY2(run_->wokenAt > run_->asleepAt, "the slider did not wake the pyramid");
        QVERIFY2(run_->asleepAgainAt > run_->wokenAt, "the pyramid did not fall asleep again");
        QCOMPARE(run_->snapshots.size(), std::size_t{3});
        qInfo("asleep at step %lld, woken at %lld, asleep again at %lld", run_->asleepAt,
              run_->wokenAt, run_->asleepAgainAt);
    }

    // Each snapshot restored into the world as it ended (asleep) and stepped to the end
    // retraces the run bit for bit, through every fall asleep and wake after it.
    void restoredRunIsBitIdentical() {
        Run& r = *run_;
        for (std::size_t s = 0; s < r.snapshots.size(); ++s) {
            QVERIFY(r.snapshots[s].restoreInto(*r.world));
            long long k = r.snapshotSteps[s];
            QCOMPARE(r.world->stepCount(), k);
            QVERIFY(bitsOf(*r.world) == r.reference[static_cast<std::size_t>(k)]);
            while (k + 1 < static_cast<long long>(r.reference.size())) {
                QVERIFY(r.world->step());
                ++k;
                QVERIFY2(bitsOf(*r.world) == r.reference[static_cast<std::size_t>(k)],
                         qPrintable(QStringLiteral("step %1 after the restore at %2 differs")
                                        .arg(k)
                                        .arg(r.snapshotSteps[s])));
            }
        }
        // And from the end (asleep) back into the awake stretch, then stepped a while.
        QVERIFY(r.snapshots[0].restoreInto(*r.world));
        for (int i = 0; i < 30; ++i) QVERIFY(r.world->step());
        QVERIFY(bitsOf(*r.world) == r.reference[static_cast<std::size_t>(r.snapshotSteps[0] + 30)]);
    }

    // Every frame of the stretch in which the same islands sleep shares one record of them,
    // and a frame shown in a world of another layout is that moment's whole state.
    void framesAcrossLayouts() {
        Run& r = *run_;
        const auto& asleep = r.frames[static_cast<std::size_t>(r.asleepAt)];
        QVERIFY(asleep.sleepers);
        QCOMPARE(asleep.sleepers->bodies.size(), std::size_t{kBoxes});
        QCOMPARE(asleep.q.size(), Eigen::Index{3});  // the slider alone is awake
        QVERIFY(r.frames[static_cast<std::size_t>(r.asleepAt + 20)].sleepers == asleep.sleepers);
        QVERIFY(!r.frames[10].sleepers);
        auto viewer = buildWorld(sleep_scenes::pyramidAndSlider(true)).world;
        viewer->commit();
        for (long long k : {r.asleepAt + 5, 10LL, r.wokenAt, r.asleepAgainAt + 3, r.asleepAt,
                            r.wokenAt - 1, 0LL, r.asleepAt - 1}) {
            const FrameState& f = r.frames[static_cast<std::size_t>(k)];
            QVERIFY(WorldSnapshot::show(*viewer, f));
            QVERIFY2(bitsOf(*viewer) == r.reference[static_cast<std::size_t>(k)],
                     qPrintable(QStringLiteral("frame %1 shown differs").arg(k)));
            for (int i = 0; i < kBoxes; ++i)
                QCOMPARE(viewer->rigidBodies()[static_cast<std::size_t>(i)].asleep,
                         f.sleepers != nullptr);
        }
    }

    // A snapshot of other objects is still refused, and leaves the world as it was.
    void otherObjectsAreRefused() {
        auto other = buildWorld(sleep_scenes::pyramid(true)).world;
        other->step();
        const auto before = bitsOf(*other);
        QVERIFY(!run_->snapshots[1].restoreInto(*other));
        QVERIFY(bitsOf(*other) == before);
    }

private:
    std::unique_ptr<Run> run_;
};

QTEST_GUILESS_MAIN(TestWorldSnapshotSleep)
#include "tst_world_snapshot_sleep.moc"
