#include "physics/core/LargeBuffer.h"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace phasebox::large_buffer {

namespace {
std::size_t roundedUp(std::size_t bytes) {
    return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}
}  // namespace

#if defined(__linux__)

void* allocate(std::size_t bytes) {
    // A mapping one huge page longer than the buffer, cut down to the aligned part: the kernel
    // places a huge page only where 2 MB of the mapping start on a 2 MB boundary.
    const std::size_t length = roundedUp(bytes);
    if (length < bytes || length + kHugePage < length) throw std::bad_alloc();
    void* mapped = mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE,
                        MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) throw std::bad_alloc();
    const auto start = reinterpret_cast<std::uintptr_t>(mapped);
    const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
    if (aligned > start) munmap(mapped, aligned - start);
    const std::size_t tail = kHugePage - (aligned - start);
    if (tail > 0) munmap(reinterpret_cast<void*>(aligned + length), tail);
    void* p = reinterpret_cast<void*>(aligned);
    madvise(p, length, MADV_HUGEPAGE);  // advice: without huge pages the buffer works as well
    return p;
}

void release(void* p, std::size_t bytes) noexcept {
    if (p) munmap(p, roundedUp(bytes));
}

#else

void* allocate(std::size_t bytes) {
    void* p = std::aligned_alloc(kHugePage, roundedUp(bytes));
    if (!p) throw std::bad_alloc();
    return p;
}

void release(void* p, std::size_t) noexcept {
    std::free(p);
}

#endif

}  // namespace phasebox::large_buffer
