#include "large_array.h"

#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace delpsc::kernel {

namespace {

std::size_t rounded_to_huge_pages(std::size_t bytes) {
  return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
}

}  // namespace

void* allocate_large(std::size_t bytes) {
  if (bytes < kLargeBlockBytes) return ::operator new(bytes);
  const std::size_t rounded = rounded_to_huge_pages(bytes);
  if (rounded < bytes) throw std::bad_alloc();
  // aligned_alloc's size must be a multiple of the alignment: it is.
  void* p = std::aligned_alloc(kHugePageBytes, rounded);
  if (p == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Advice only: if the kernel refuses (THP off), the block works with base pages.
  (void)madvise(p, rounded, MADV_HUGEPAGE);
#endif
  return p;
}

void deallocate_large(void* p, std::size_t bytes) noexcept {
  if (p == nullptr) return;
  if (bytes < kLargeBlockBytes) {
    ::operator delete(p);
    return;
  }
  std::free(p);
}

}  // namespace delpsc::kernel
