#pragma once
// Counts heap allocations while counting is switched on, so a benchmark can say whether a step
// allocates. Include this in exactly ONE translation unit per executable: it defines the
// program's global operator new and (with glibc) malloc, which may exist only once.
//
// Two doors lead to the heap and both are watched: C++ operator new (std::string, std::vector,
// std::optional payloads) and malloc/calloc/realloc, which is where Eigen gets its vectors
// and sparse matrices (Eigen never calls operator new for dynamic storage). The replacement
// operator new goes straight to glibc's allocator, so one allocation is counted once.
// Single-threaded benchmarks only: the counters are plain integers.

#include <cstddef>
#include <cstdlib>
#include <new>

namespace phasebox::bench {

struct AllocationCounts {
    long long operatorNew = 0;
    long long malloc = 0;  // malloc, calloc, realloc (0 where malloc cannot be replaced)
    long long total() const { return operatorNew + malloc; }
};

namespace detail {
inline bool countingOn = false;
inline AllocationCounts counts;
}  // namespace detail

// AddressSanitizer owns malloc and operator new; replacing them under it crashes at start-up,
// so a sanitizer build counts nothing (the release build runs the allocation checks).
#if defined(__SANITIZE_ADDRESS__)
#define PHASEBOX_BENCH_NO_COUNTING 1
constexpr bool kCountsAllocations = false;
#else
constexpr bool kCountsAllocations = true;
#endif

// Whether malloc is watched too (glibc only); without it Eigen's allocations go unseen.
#if defined(__GLIBC__) && !defined(PHASEBOX_BENCH_NO_COUNTING)
constexpr bool kCountsMalloc = true;
#else
constexpr bool kCountsMalloc = false;
#endif

inline void startCountingAllocations() {
    detail::counts = {};
    detail::countingOn = true;
}
inline AllocationCounts stopCountingAllocations() {
    detail::countingOn = false;
    return detail::counts;
}

}  // namespace phasebox::bench

#if !defined(PHASEBOX_BENCH_NO_COUNTING)
#if defined(__GLIBC__)
// glibc lets a program replace malloc by defining it; its own allocator stays reachable under
// these names (the documented "Replacing malloc" hooks). Every other entry point (free,
// posix_memalign, …) still reaches the same allocator, so mixing is safe.
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);

void* malloc(std::size_t size) noexcept {
    if (phasebox::bench::detail::countingOn) ++phasebox::bench::detail::counts.malloc;
    return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
    if (phasebox::bench::detail::countingOn) ++phasebox::bench::detail::counts.malloc;
    return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) noexcept {
    if (phasebox::bench::detail::countingOn) ++phasebox::bench::detail::counts.malloc;
    return __libc_realloc(p, size);
}
}
#define PHASEBOX_BENCH_RAW_MALLOC __libc_malloc
#else
#define PHASEBOX_BENCH_RAW_MALLOC std::malloc
#endif

namespace phasebox::bench::detail {
inline void* countedNew(std::size_t size) {
    if (countingOn) ++counts.operatorNew;
    if (void* p = PHASEBOX_BENCH_RAW_MALLOC(size ? size : 1)) return p;
    throw std::bad_alloc();
}
inline void* countedAlignedNew(std::size_t size, std::align_val_t alignment) {
    if (countingOn) ++counts.operatorNew;
    const auto a = static_cast<std::size_t>(alignment);
    // aligned_alloc wants a size that is a multiple of the alignment.
    if (void* p = std::aligned_alloc(a, (size + a - 1) / a * a + (size ? 0 : a))) return p;
    throw std::bad_alloc();
}
}  // namespace phasebox::bench::detail

void* operator new(std::size_t size) {
    return phasebox::bench::detail::countedNew(size);
}
void* operator new[](std::size_t size) {
    return phasebox::bench::detail::countedNew(size);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return phasebox::bench::detail::countedNew(size);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    return operator new(size, std::nothrow);
}
void* operator new(std::size_t size, std::align_val_t alignment) {
    return phasebox::bench::detail::countedAlignedNew(size, alignment);
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
    return phasebox::bench::detail::countedAlignedNew(size, alignment);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
#endif  // !PHASEBOX_BENCH_NO_COUNTING
