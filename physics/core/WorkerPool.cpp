#include "physics/core/WorkerPool.h"

#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace phasebox {

namespace {

// Set on a helper for its lifetime and on the calling thread while it runs a loop: a loop
// started there runs serially (nesting would wait on the helpers that run it).
thread_local bool tInsideLoop = false;

// How long a helper keeps looking for the next loop before it sleeps: the step's loops follow
// one another within microseconds, but a large scene's serial stretches (a step's start: its
// integration, the broad phase's bounds, the contacts numbered in order) last up to a
// millisecond, and a helper asleep costs the caller a wake (a system call, tens of
// microseconds on a virtual machine) and the loop the helper's share until it is up. The
// 100-row pyramid on two workers, 240 steps: 1,632 wakes (47 ms of the caller's time in them)
// with 50 µs, 583 with 500 µs, 12 to 16 with 1 ms. A frame's next step comes milliseconds
// later, so a helper spins at most this long a frame (6% of a core at 60 frames a second).
// With more workers than cores a spinning helper takes the core of a worker with work (the
// 100-row pyramid on four workers and two cores: 32.5 ms a step with 1 ms, 13.6 ms with 50 µs).
constexpr auto kSpin = std::chrono::microseconds(1000);
constexpr auto kSpinOversubscribed = std::chrono::microseconds(50);

void relax() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#else
    std::this_thread::yield();
#endif
}

struct InsideLoop {
    InsideLoop() { tInsideLoop = true; }
    ~InsideLoop() { tInsideLoop = false; }
};

}  // namespace

WorkerPool::WorkerPool(int workers) {
    setWorkers(workers);
}

WorkerPool::~WorkerPool() {
    stop();
}

int WorkerPool::allCores() {
    // Once (glibc reads it from /sys): a helper asks each time it waits for a loop.
    static const int cores = [] {
        const unsigned n = std::thread::hardware_concurrency();
        return n == 0 ? 1 : static_cast<int>(n);
    }();
    return cores;
}

void WorkerPool::setWorkers(int workers) {
    const int n = workers <= 0 ? allCores() : workers;
    if (n == workers_ && (n == 1 || !helpers_.empty())) return;
    stop();
    workers_ = n;
}

bool WorkerPool::insideLoop() {
    return tInsideLoop;
}

void WorkerPool::start() {
    stopping_.store(false);
    shares_ = std::make_unique<Share[]>(static_cast<std::size_t>(workers_));
    helpers_.reserve(static_cast<std::size_t>(workers_ - 1));
    for (int w = 1; w < workers_; ++w) helpers_.emplace_back([this, w] { helperLoop(w); });
}

void WorkerPool::stop() {
    if (helpers_.empty()) return;
    stopping_.store(true, std::memory_order_seq_cst);
    wake_.fetch_add(1, std::memory_order_seq_cst);
    wake_.notify_all();
    for (std::thread& t : helpers_) t.join();
    helpers_.clear();
    stopping_.store(false);
}

void WorkerPool::runChunk(int chunk, int worker) {
    const int begin = chunk * grain_;
    const int end = begin + grain_ < count_ ? begin + grain_ : count_;
    try {
        chunkFn_(body_, begin, end, worker);
    } catch (...) {
        const std::lock_guard<std::mutex> lock(failureMutex_);
        if (failedChunk_ < 0 || chunk < failedChunk_) {
            failedChunk_ = chunk;
            failure_ = std::current_exception();
        }
    }
}

bool WorkerPool::claim(int owner, int& chunk) {
    const std::uint64_t cursor = shares_[owner].cursor.fetch_add(1, std::memory_order_acq_rel);
    const auto end = static_cast<std::uint32_t>(cursor >> 32);
    const auto next = static_cast<std::uint32_t>(cursor);
    if (next >= end) return false;
    chunk = static_cast<int>(next);
    return true;
}

void WorkerPool::drain(int worker) {
    // Its own share first, then the others', the next worker's first. The chunks it finished
    // are counted once, when nothing is left to claim: the counter is shared by every worker,
    // and each add moves its cache line from one core to another (about 0.25 µs on a machine
    // whose two cores sit apart), which a count per chunk paid 16 times a loop.
    int finished = 0;
    for (int k = 0; k < workers_; ++k) {
        const int owner = (worker + k) % workers_;
        for (int chunk; claim(owner, chunk);) {
            runChunk(chunk, worker);
            ++finished;
        }
    }
    if (finished > 0) done_.fetch_add(finished, std::memory_order_release);
}

void WorkerPool::run(int count, int grain, int chunks, ChunkFn chunkFn, void* body) {
    if (helpers_.empty()) start();
    ++sharedLoops_;
    chunkFn_ = chunkFn;
    body_ = body;
    count_ = count;
    grain_ = grain;
    failedChunk_ = -1;
    failure_ = nullptr;
    done_.store(0, std::memory_order_relaxed);
    // Publishing the shares releases the description above to whoever claims a chunk.
    for (int w = 0; w < workers_; ++w) {
        const auto begin =
            static_cast<std::uint64_t>(static_cast<long long>(chunks) * w / workers_);
        const auto end =
            static_cast<std::uint64_t>(static_cast<long long>(chunks) * (w + 1) / workers_);
        shares_[w].cursor.store(end << 32 | begin, std::memory_order_seq_cst);
    }
    wake_.fetch_add(1, std::memory_order_seq_cst);
    if (sleepers_.load(std::memory_order_seq_cst) > 0) wake_.notify_all();
    {
        const InsideLoop inside;
        drain(0);
    }
    // The helpers' last chunks.
    for (int spins = 0; done_.load(std::memory_order_acquire) < chunks; ++spins) {
        if (spins < 256)
            relax();
        else
            std::this_thread::yield();
    }
    if (failure_) {
        std::exception_ptr failure = failure_;
        failure_ = nullptr;
        std::rethrow_exception(failure);
    }
}

void WorkerPool::helperLoop(int worker) {
    tInsideLoop = true;
    std::uint32_t seen = 0;
    for (;;) {
        // Until a new loop is announced: spin a while, then sleep.
        const auto spinUntil = std::chrono::steady_clock::now() +
                               (workers_ > allCores() ? kSpinOversubscribed : kSpin);
        std::uint32_t now = wake_.load(std::memory_order_acquire);
        for (int spins = 0; now == seen; ++spins) {
            relax();
            if ((spins & 63) == 63 && std::chrono::steady_clock::now() > spinUntil) {
                sleepers_.fetch_add(1, std::memory_order_seq_cst);
                if (wake_.load(std::memory_order_seq_cst) == seen) wake_.wait(seen);
                sleepers_.fetch_sub(1, std::memory_order_seq_cst);
            }
            now = wake_.load(std::memory_order_acquire);
        }
        seen = now;
        if (stopping_.load(std::memory_order_acquire)) return;
        drain(worker);
    }
}

}  // namespace phasebox
