#pragma once
// A fixed set of worker threads for the step's data-parallel loops (CONTRACT §4: every output
// but the timings is bit-identical for any number of workers).
//
// parallelFor(count, grain, fn) cuts [0, count) into chunks of grain items, the last one shorter.
// The cut depends on count and grain only, never on the number of workers, and every chunk runs
// exactly once, as fn(begin, end, worker), on the calling thread (worker 0) or on a helper
// (1 … workers() − 1). A loop whose chunks write only their own items, or per-chunk partials
// reduced afterwards in chunk order, therefore gives the same bits for 1 worker and for 64;
// `worker` is only for choosing a scratch buffer, never for what is computed.
//
// The loop runs on the calling thread, chunk after chunk in order, when there is one worker, one
// chunk, or when it is called from inside another parallelFor (no nesting). A caller picks grain
// so that a chunk costs well above the hand-off (about a microsecond when the helpers are
// spinning, tens when they have to be woken): a loop of a few chunks is not worth sharing.
//
// Each worker starts on its own contiguous share of the chunks (worker w of W: chunks
// [w·n/W, (w+1)·n/W)) and takes from the others' shares only when its own is done. Passes over
// the same range with the same grain thus give a worker the same items again while it keeps up,
// so rows and bodies stay in its core's cache instead of moving between cores every pass, and
// neighbouring items (ordered in space by the callers) share fewer cache lines across cores.
// Who runs a chunk never changes what it computes.
//
// No allocation per call and one indirect call per chunk, not per item. Helpers spin a short
// while after a loop (the step's next loop usually follows within microseconds), then sleep on
// a futex until the next one. Threads start at the first loop that shares work, so a world
// that never has a large loop never starts any.
//
// An exception thrown by fn is caught per chunk; the remaining chunks still run, and the one
// of the lowest chunk is rethrown on the calling thread once all have finished (the same one
// for any number of workers). One thread calls parallelFor on a pool at a time.

#include <atomic>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace phasebox {

class WorkerPool {
public:
    // workers ≥ 1 (less is taken as 1); 0 and the default mean every core.
    explicit WorkerPool(int workers = 0);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    // The number of threads that run a loop, the calling one included. Setting it stops the
    // helpers (they restart lazily); 0 means every core.
    void setWorkers(int workers);
    int workers() const { return workers_; }
    // std::thread::hardware_concurrency(), at least 1.
    static int allCores();

    // How many chunks parallelFor cuts count items into: for per-chunk partial results.
    static int chunkCount(int count, int grain) {
        if (count <= 0) return 0;
        if (grain < 1) grain = 1;
        return count / grain + (count % grain != 0);
    }

    template <class Fn>
    void parallelFor(int count, int grain, Fn&& fn) {
        if (grain < 1) grain = 1;
        const int chunks = chunkCount(count, grain);
        if (chunks == 0) return;
        if (chunks == 1 || workers_ <= 1 || insideLoop()) {
            for (int c = 0; c < chunks; ++c) {
                const int begin = c * grain;
                fn(begin, begin + grain < count ? begin + grain : count, 0);
            }
            return;
        }
        using Body = std::remove_reference_t<Fn>;
        run(
            count, grain, chunks,
            [](void* body, int begin, int end, int worker) {
                (*static_cast<Body*>(body))(begin, end, worker);
            },
            const_cast<void*>(static_cast<const void*>(&fn)));
    }

    // Loops that shared work since construction (for tests and measurements).
    long long sharedLoops() const { return sharedLoops_; }

private:
    using ChunkFn = void (*)(void* body, int begin, int end, int worker);
    void run(int count, int grain, int chunks, ChunkFn chunkFn, void* body);
    void start();
    void stop();
    void helperLoop(int worker);
    // Claims and runs chunks of the current loop until none is left.
    void drain(int worker);
    void runChunk(int chunk, int worker);
    static bool insideLoop();

    int workers_ = 1;
    std::vector<std::thread> helpers_;
    long long sharedLoops_ = 0;

    // The current loop. Each worker's share is a cursor holding the share's end (high half)
    // and its next chunk (low half): a claim is one fetch_add on it, and a chunk claimed below
    // the end belongs to the loop in progress, whose description below cannot change before
    // that chunk is done (a claim on a finished share only moves its next chunk past the end).
    struct alignas(64) Share {
        std::atomic<std::uint64_t> cursor{0};
    };
    std::unique_ptr<Share[]> shares_;
    // Claims a chunk of worker `owner`'s share; false when the share is used up.
    bool claim(int owner, int& chunk);
    // Chunks of the current loop finished, on a cache line of its own: the workers add to it and
    // the caller polls it, while every chunk reads the loop's description below.
    alignas(64) std::atomic<int> done_{0};
    alignas(64) ChunkFn chunkFn_ = nullptr;
    void* body_ = nullptr;
    int count_ = 0, grain_ = 1;
    // The exception of the lowest chunk that threw, if any.
    std::mutex failureMutex_;
    std::exception_ptr failure_;
    int failedChunk_ = -1;

    // Waking: a new loop bumps wake_; helpers that spun out wait on it.
    std::atomic<std::uint32_t> wake_{0};
    std::atomic<int> sleepers_{0};
    std::atomic<bool> stopping_{false};
};

}  // namespace phasebox
