// Storage for the flat arrays that grow to megabytes: the triangulation's cells and points, the
// restricted facets' records and per-cell references, the sample's candidates.
//
// Why: these arrays are read at random (a walk or a cavity search jumps across the cell array),
// and with 4 KiB pages a mesher run of 50,000 vertices touches ~20,000 pages. Each first touch is
// a page fault, which on some virtual machines costs several microseconds of system time, and
// each random read risks a TLB miss. Blocks above 1 MiB are therefore aligned to 2 MiB and, where
// huge_page_policy.h finds it worthwhile, advised for transparent huge pages (Linux
// madvise(MADV_HUGEPAGE); honoured when the system's THP mode is "always" or "madvise"): on the
// cube at 0.456% of the diagonal, faults fell from ~21,000 to ~4,000 and the CPU time of the
// whole pipeline by ~40%, user time as much as system time (BENCHMARKS.md, "Huge pages"). Not on
// a virtual machine that reports its free memory to the host, where a fresh huge page costs
// five times what its base pages do (BENCHMARKS.md, "Session 29") - unless its base pages are
// dearer still (session 35; huge_page_policy.h decides).
//
// Blocks from 4 KiB to 1 MiB come from a pool of 2 MiB chunks (huge pages where advised, as
// above), so that the many arrays of a small run (a few thousand vertices: each array tens of
// KiB) do not fault in their pages one by one: on the virtual machines of session 20 a 4 KiB
// fault cost ~11 us, a whole 2 MiB huge page ~160 us. The pool keeps one free list per
// power-of-two size and reuses freed blocks (a growing vector's old blocks serve the next one);
// it returns its chunks to the system when no pooled block is live, but one; a forked child
// starts an empty pool, as writing into the parent's chunks would copy them page by page
// (BENCHMARKS.md, "Session 20: a pool for mid-sized arrays").
//
// Freed blocks above 1 MiB are kept and reused (the smallest that fits, at most twice the size
// asked for) while other such blocks are live, up to as many bytes as are live, and all go back
// to the system when none is: a mesher run's later tables then take the pages its sample freed
// instead of faulting in new ones (BENCHMARKS.md, "Session 27"). Not under AddressSanitizer,
// as the pool.
//
// Cost: a pooled block takes the next power of two of its size; a block above 1 MiB is rounded up
// to a multiple of 2 MiB (at most 2 MiB more per array). Below 4 KiB, operator new as before.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace delpsc::kernel {

/// Whether the pool and the reuse of large blocks are on. Not under AddressSanitizer: blocks
/// carved from one chunk would hide an overrun of one array into the next, and a reused block a
/// use after free, which ASan finds between separate heap blocks.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kPoolInUse = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kPoolInUse = false;
#else
inline constexpr bool kPoolInUse = true;
#endif
#else
inline constexpr bool kPoolInUse = true;
#endif
/// Blocks from this size up to kPoolMaxBytes come from the huge-page pool.
inline constexpr std::size_t kPoolMinBytes = std::size_t{4} << 10;
/// Blocks above this size get their own huge-page-aligned, advised mapping.
inline constexpr std::size_t kPoolMaxBytes = std::size_t{1} << 20;
/// The huge page size the blocks are aligned to (x86-64 and arm64 with 4 KiB base pages).
inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

/// `bytes` of storage aligned for any type; throws std::bad_alloc. O(1) plus the system's cost.
/// Thread-safe (the pool takes a lock).
void* allocate_large(std::size_t bytes);
/// Frees what allocate_large(bytes) returned, with the same `bytes`.
void deallocate_large(void* p, std::size_t bytes) noexcept;

/// Bytes of freed large blocks kept for reuse now (see the file comment); for tests and
/// statistics. O(1).
std::size_t kept_large_bytes() noexcept;

/// A std::allocator whose large blocks go through allocate_large. Stateless: all compare equal.
template <class T>
struct LargeArrayAllocator {
  using value_type = T;
  LargeArrayAllocator() = default;
  template <class U>
  LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}  // NOLINT: rebinding is implicit
  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(allocate_large(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { deallocate_large(p, n * sizeof(T)); }
  template <class U>
  bool operator==(const LargeArrayAllocator<U>&) const noexcept { return true; }
};

/// A std::vector on LargeArrayAllocator: the same interface, huge pages once it is large.
template <class T>
using LargeVector = std::vector<T, LargeArrayAllocator<T>>;

}  // namespace delpsc::kernel
