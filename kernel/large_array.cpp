#include "large_array.h"

#include <array>
#include <cstdint>
#include <cstdlib>
#include <mutex>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace delpsc::kernel {

namespace {

std::size_t rounded_to_huge_pages(std::size_t bytes) {
  return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
}

// `bytes` (a multiple of kHugePageBytes) aligned to a huge page and advised for THP.
void* huge_page_block(std::size_t bytes) {
  // aligned_alloc's size must be a multiple of the alignment: it is.
  void* p = std::aligned_alloc(kHugePageBytes, bytes);
  if (p == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Advice only: if the kernel refuses (THP off), the block works with base pages.
  (void)madvise(p, bytes, MADV_HUGEPAGE);
#endif
  return p;
}

// Size classes of the pool: kPoolMinBytes << k for k = 0 .. kClasses - 1.
constexpr int kClasses = 9;
static_assert((kPoolMinBytes << (kClasses - 1)) == kPoolMaxBytes);
static_assert(kHugePageBytes % kPoolMaxBytes == 0);

int size_class(std::size_t bytes) {
  int k = 0;
  while ((kPoolMinBytes << k) < bytes) ++k;
  return k;
}

// The pool of mid-sized blocks: power-of-two blocks carved from huge-page chunks, kept on one
// free list per size (no coalescing) and reused. A growing vector frees each smaller block as it
// moves on, and the next array that grows takes them. Chunks are returned to the system when no
// block is live any more (one is kept, so that a loop that allocates and frees one scratch array
// does not map and zero a chunk each time).
class MidBlockPool {
 public:
  void* allocate(std::size_t bytes) {
    const int k = size_class(bytes);
    const std::lock_guard lock(mutex_);
    ++live_;
    if (FreeBlock* b = free_[k]) {
      free_[k] = b->next;
      return b;
    }
    const std::size_t size = kPoolMinBytes << k;
    if (static_cast<std::size_t>(end_ - cursor_) < size) {
      shelve_rest_of_chunk();
      // Before the chunk is mapped, so that a failure leaves the pool as it was.
      if (chunks_.size() == chunks_.capacity()) chunks_.reserve(2 * chunks_.size() + 4);
      auto* chunk = static_cast<unsigned char*>(huge_page_block(kHugePageBytes));
      chunks_.push_back(chunk);
      cursor_ = chunk;
      end_ = chunk + kHugePageBytes;
    }
    void* p = cursor_;
    cursor_ += size;
    return p;
  }

  void deallocate(void* p, std::size_t bytes) noexcept {
    const int k = size_class(bytes);
    const std::lock_guard lock(mutex_);
    auto* b = static_cast<FreeBlock*>(p);
    b->next = free_[k];
    free_[k] = b;
    if (--live_ == 0) release_all_but_one();
  }

 private:
  struct FreeBlock {
    FreeBlock* next;
  };

  // The unused end of the current chunk goes to the free lists, largest pieces first (offsets
  // and sizes are multiples of kPoolMinBytes, so every piece is aligned like a carved block).
  void shelve_rest_of_chunk() noexcept {
    for (int k = kClasses - 1; k >= 0; --k) {
      const std::size_t size = kPoolMinBytes << k;
      while (static_cast<std::size_t>(end_ - cursor_) >= size) {
        auto* b = reinterpret_cast<FreeBlock*>(cursor_);
        b->next = free_[k];
        free_[k] = b;
        cursor_ += size;
      }
    }
  }

  void release_all_but_one() noexcept {
    if (chunks_.empty()) return;
    for (std::size_t i = 1; i < chunks_.size(); ++i) std::free(chunks_[i]);
    chunks_.resize(1);
    free_.fill(nullptr);
    cursor_ = chunks_[0];
    end_ = cursor_ + kHugePageBytes;
  }

  std::mutex mutex_;
  std::array<FreeBlock*, kClasses> free_{};
  std::vector<unsigned char*> chunks_;
  unsigned char* cursor_ = nullptr;  // the current chunk's unused part: [cursor_, end_)
  unsigned char* end_ = nullptr;
  std::size_t live_ = 0;
};

MidBlockPool& mid_block_pool() {
  // Never destroyed: blocks may be freed by static destructors that run after ours would.
  static auto* pool = new MidBlockPool;
  return *pool;
}

}  // namespace

void* allocate_large(std::size_t bytes) {
  if (bytes < kPoolMinBytes) return ::operator new(bytes);
  if (bytes <= kPoolMaxBytes) return mid_block_pool().allocate(bytes);
  const std::size_t rounded = rounded_to_huge_pages(bytes);
  if (rounded < bytes) throw std::bad_alloc();
  return huge_page_block(rounded);
}

void deallocate_large(void* p, std::size_t bytes) noexcept {
  if (p == nullptr) return;
  if (bytes < kPoolMinBytes) {
    ::operator delete(p);
  } else if (bytes <= kPoolMaxBytes) {
    mid_block_pool().deallocate(p, bytes);
  } else {
    std::free(p);
  }
}

}  // namespace delpsc::kernel
