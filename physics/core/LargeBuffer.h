#pragma once
// Buffers of many megabytes on the kernel's transparent huge pages (2 MB) where it has them.
// The contact arrays of a dense scene (a pile of 3,000 disks at one point makes 54,000
// contacts, about 100 MB of constraints, rows and lanes) grow in its first steps, and each
// 4 kB page they touch for the first time is a page fault: on the machines Phasebox is timed
// on (a virtual machine), 37,000 of them cost the pile's first second about 0.2 s of kernel
// time (7,300 faults with huge pages), and the lanes' random reads miss the TLB less. Where the
// kernel gives huge pages only when asked (transparent_hugepage = madvise, as on that machine)
// the advice asks; where it has none, the buffer works as well without. Smaller buffers are
// allocated as std::allocator would.

#include <cstddef>
#include <new>
#include <utility>
#include <vector>

namespace phasebox {

namespace large_buffer {
// The size from which a buffer is given its own huge-page-aligned mapping.
inline constexpr std::size_t kHugePage = std::size_t{2} << 20;
void* allocate(std::size_t bytes);  // throws std::bad_alloc
void release(void* p, std::size_t bytes) noexcept;
}  // namespace large_buffer

template <class T>
struct HugePageAllocator {
    using value_type = T;
    HugePageAllocator() noexcept = default;
    template <class U>
    HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
        const std::size_t bytes = n * sizeof(T);
        if (bytes < large_buffer::kHugePage)
            return static_cast<T*>(::operator new (bytes, std::align_val_t{alignof(T)}));
        static_assert(alignof(T) <= large_buffer::kHugePage);
        return static_cast<T*>(large_buffer::allocate(bytes));
    }
    void deallocate(T* p, std::size_t n) noexcept {
        const std::size_t bytes = n * sizeof(T);
        if (bytes < large_buffer::kHugePage)
            ::operator delete (p, std::align_val_t{alignof(T)});
        else
            large_buffer::release(p, bytes);
    }
    template <class U>
    bool operator==(const HugePageAllocator<U>&) const noexcept {
        return true;
    }
};

// A vector whose buffer, once it is large, lies on huge pages.
template <class T>
using LargeVector = std::vector<T, HugePageAllocator<T>>;

// The same allocator, but resize() leaves new elements of a trivial type uninitialized: a
// buffer of which a step writes only some elements touches only their pages (the kernel zeroes
// each page when it is first touched, the vector's zeroing would touch all of them). Cleared
// before it grows, the vector copies nothing either.
template <class T>
struct UninitializedHugePageAllocator : HugePageAllocator<T> {
    using value_type = T;
    template <class U>
    struct rebind {
        using other = UninitializedHugePageAllocator<U>;
    };
    UninitializedHugePageAllocator() noexcept = default;
    template <class U>
    UninitializedHugePageAllocator(const UninitializedHugePageAllocator<U>&) noexcept {}
    template <class U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;  // default-initialized: nothing written for a trivial U
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
    template <class U>
    bool operator==(const UninitializedHugePageAllocator<U>&) const noexcept {
        return true;
    }
};
template <class T>
using UninitializedLargeVector = std::vector<T, UninitializedHugePageAllocator<T>>;

}  // namespace phasebox
