// An allocator for the arrays a ray walks at random (a mesh's BVH nodes and leaf triangles):
// arrays of 2 MiB or more are mapped on their own, 2 MiB aligned, and marked for transparent
// huge pages, so that a walk through a million-triangle mesh misses the TLB far less often.
// Debian's default (transparent_hugepage=madvise) gives huge pages only to memory that asks;
// Embree asks for its BVH the same way. Where the kernel refuses, the mapping stays ordinary
// pages and only the alignment differs. Smaller arrays come from std::allocator.
#pragma once

#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>

namespace glint::render {

inline constexpr size_t kHugePage = size_t(2) << 20;

// Bytes this process holds in huge-page mappings (malloc's statistics do not see them): for
// bench/traversal_bench's bytes per triangle.
inline std::atomic<size_t>& huge_page_bytes() {
    static std::atomic<size_t> bytes{0};
    return bytes;
}

// The mapping's size: whole small pages. The kernel backs each 2 MiB-aligned stretch the
// mapping covers entirely with one huge page and the tail with small ones, so nothing is
// wasted past the last small page (rounding to 2 MiB cost a 2.1 MiB array 90%).
inline size_t huge_page_round(size_t bytes) {
    static const size_t page = static_cast<size_t>(sysconf(_SC_PAGESIZE));
    return (bytes + page - 1) / page * page;
}

template <class T>
struct HugePageAllocator {
    using value_type = T;
    HugePageAllocator() = default;
    template <class U>
    HugePageAllocator(const HugePageAllocator<U>&) {}

    T* allocate(size_t n) {
        if (n > SIZE_MAX / sizeof(T)) throw std::bad_alloc();
        const size_t bytes = n * sizeof(T);
        if (bytes < kHugePage) return std::allocator<T>().allocate(n);
        const size_t size = huge_page_round(bytes);
        // Map one huge page more than needed and cut the ends off, to align the start.
        void* p = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE,
                       MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) throw std::bad_alloc();
        const auto start = reinterpret_cast<uintptr_t>(p);
        const uintptr_t aligned = (start + kHugePage - 1) & ~(kHugePage - 1);
        if (aligned > start) munmap(p, aligned - start);
        const uintptr_t tail = aligned + size, end = start + size + kHugePage;
        if (end > tail) munmap(reinterpret_cast<void*>(tail), end - tail);
        void* q = reinterpret_cast<void*>(aligned);
        madvise(q, size, MADV_HUGEPAGE);  // a hint: failure leaves ordinary pages
        huge_page_bytes() += size;
        return static_cast<T*>(q);
    }

    void deallocate(T* p, size_t n) {
        const size_t bytes = n * sizeof(T);
        if (bytes < kHugePage) {
            std::allocator<T>().deallocate(p, n);
            return;
        }
        const size_t size = huge_page_round(bytes);
        munmap(p, size);
        huge_page_bytes() -= size;
    }

    template <class U>
    bool operator==(const HugePageAllocator<U>&) const { return true; }
    template <class U>
    bool operator!=(const HugePageAllocator<U>&) const { return false; }
};

}  // namespace glint::render
