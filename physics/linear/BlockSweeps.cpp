#include "physics/linear/BlockSweeps.h"

#include <atomic>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define PHASEBOX_WIDE_KERNELS 1
#include <immintrin.h>
#endif

namespace phasebox::blocks {

namespace {

// The kernels' table, one per instruction set.
struct Kernels {
    void (*multiply)(const Rows&, const double*, double*);
    void (*forward)(const Rows&, const double*, const double*, double*);
    void (*restrictUpper)(const Rows&, const int*, const double*, double*);
    void (*backward)(const Rows&, const double*, const double*, double*);
    void (*lowerSolve)(const Rows&, double*);
    void (*upperSolve)(const Rows&, const double*, double*);
};

namespace twoLane {
// Σ_k A_k·x_k over the blocks [begin, end) of a row into sum: each block row times the
// point's (x, y) is one two-lane product. The sum is split over independent accumulators two
// blocks at a time; one chain of additions would make each row wait on the adder's latency.
[[gnu::always_inline]] inline void rowSum(const Rows& a, int begin, int end, const double* x,
                                          double* sum) {
    typedef double Lanes __attribute__((vector_size(16)));
    auto load = [](const double* p) {
        Lanes v;
        __builtin_memcpy(&v, p, sizeof v);
        return v;
    };
    Lanes p0 = {0.0, 0.0}, p1 = {0.0, 0.0}, q0 = {0.0, 0.0}, q1 = {0.0, 0.0};
    int k = begin;
    for (; k + 1 < end; k += 2) {
        const double* v = a.values + 4 * k;
        const Lanes xp = load(x + a.column[k]), xq = load(x + a.column[k + 1]);
        p0 += load(v) * xp;
        p1 += load(v + 2) * xp;
        q0 += load(v + 4) * xq;
        q1 += load(v + 6) * xq;
    }
    if (k < end) {
        const double* v = a.values + 4 * k;
        const Lanes xp = load(x + a.column[k]);
        p0 += load(v) * xp;
        p1 += load(v + 2) * xp;
    }
    const Lanes r0 = p0 + q0, r1 = p1 + q1;
    sum[0] = r0[0] + r0[1];
    sum[1] = r1[0] + r1[1];
}
#include "physics/linear/BlockSweepLoops.inc"
}  // namespace twoLane

#ifdef PHASEBOX_WIDE_KERNELS
#pragma GCC push_options
#pragma GCC target("avx2,fma")
namespace fourLane {
// The same on four lanes: a row-major block times (x, y, x, y) is one fused multiply-add, and
// the lane pairs are summed once at the end of the row.
[[gnu::always_inline]] inline void rowSum(const Rows& a, int begin, int end, const double* x,
                                          double* sum) {
    auto point = [&](int k) {
        return _mm256_broadcast_pd(reinterpret_cast<const __m128d*>(x + a.column[k]));
    };
    __m256d p = _mm256_setzero_pd(), q = _mm256_setzero_pd();
    int k = begin;
    for (; k + 1 < end; k += 2) {
        p = _mm256_fmadd_pd(_mm256_loadu_pd(a.values + 4 * k), point(k), p);
        q = _mm256_fmadd_pd(_mm256_loadu_pd(a.values + 4 * k + 4), point(k + 1), q);
    }
    if (k < end) p = _mm256_fmadd_pd(_mm256_loadu_pd(a.values + 4 * k), point(k), p);
    p = _mm256_add_pd(p, q);
    _mm_storeu_pd(sum, _mm_hadd_pd(_mm256_castpd256_pd128(p), _mm256_extractf128_pd(p, 1)));
}
#include "physics/linear/BlockSweepLoops.inc"
}  // namespace fourLane
#pragma GCC pop_options
#endif

constexpr Kernels kNarrow{twoLane::multiplyLoop, twoLane::forwardLoop,    twoLane::restrictLoop,
                          twoLane::backwardLoop, twoLane::lowerSolveLoop, twoLane::upperSolveLoop};

bool wideAvailable() {
#ifdef PHASEBOX_WIDE_KERNELS
    static const bool available = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    return available;
#else
    return false;
#endif
}

const Kernels* choose(bool on) {
#ifdef PHASEBOX_WIDE_KERNELS
    static constexpr Kernels kWide{fourLane::multiplyLoop,   fourLane::forwardLoop,
                                   fourLane::restrictLoop,   fourLane::backwardLoop,
                                   fourLane::lowerSolveLoop, fourLane::upperSolveLoop};
    if (on && wideAvailable()) return &kWide;
#endif
    (void)on;
    return &kNarrow;
}

// Chosen at first use (worker threads may get there together: all choose the same table).
std::atomic<const Kernels*> active{nullptr};

const Kernels& kernels() {
    const Kernels* k = active.load(std::memory_order_relaxed);
    if (!k) {
        k = choose(true);
        active.store(k, std::memory_order_relaxed);
    }
    return *k;
}

}  // namespace

void multiply(const Rows& a, const double* x, double* y) {
    kernels().multiply(a, x, y);
}
void forward(const Rows& a, const double* inverse, const double* b, double* x) {
    kernels().forward(a, inverse, b, x);
}
void restrictUpper(const Rows& a, const int* toCoarse, const double* x, double* coarse) {
    kernels().restrictUpper(a, toCoarse, x, coarse);
}
void backward(const Rows& a, const double* inverse, const double* b, double* x) {
    kernels().backward(a, inverse, b, x);
}
void lowerSolve(const Rows& l, double* y) {
    kernels().lowerSolve(l, y);
}
void upperSolve(const Rows& u, const double* inverse, double* y) {
    kernels().upperSolve(u, inverse, y);
}

bool setWide(bool on) {
    const Kernels* k = choose(on);
    active.store(k, std::memory_order_relaxed);
    return k != &kNarrow;
}

}  // namespace phasebox::blocks
