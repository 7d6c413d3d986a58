#include "large_array.h"

#include "huge_page_policy.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <mutex>

#if defined(__linux__)
#include <sys/mman.h>
#endif
#if defined(__unix__)
#include <pthread.h>
#endif

namespace delpsc::kernel {

namespace {

std::size_t rounded_to_huge_pages(std::size_t bytes) {
  return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
}

// `bytes` (a multiple of kHugePageBytes) aligned to a huge page, and advised for THP where that
// makes first touches cheaper (huge_page_policy.h).
void* huge_page_block(std::size_t bytes) {
  // aligned_alloc's size must be a multiple of the alignment: it is.
  void* p = std::aligned_alloc(kHugePageBytes, bytes);
  if (p == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Advice only: if the kernel refuses (THP off), the block works with base pages.
  if (huge_pages_advised()) (void)madvise(p, bytes, MADV_HUGEPAGE);
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
//
// After fork() the child starts an empty pool: the parent's chunks are shared copy-on-write, and
// reusing their free parts would copy them 4 KiB page by page, each a fault (a process that
// loads a model and then forks a child per run, as our CGAL comparison does, lost the pool's
// gain that way). Blocks the child inherited stay valid; freeing one leaves it alone.
class MidBlockPool {
 public:
  /// The process's pool, made on first use and never destroyed (blocks may be freed by static
  /// destructors that run after its own would).
  static MidBlockPool& instance() {
    static auto* pool = new MidBlockPool;
    return *pool;
  }

  void* allocate(std::size_t bytes) {
    const int k = size_class(bytes);
    const std::lock_guard lock(mutex_);
    if (FreeBlock* b = free_[k]) {
      free_[k] = b->next;
      ++live_;
      return b;
    }
    const std::size_t size = kPoolMinBytes << k;
    if (static_cast<std::size_t>(end_ - cursor_) < size) {
      // Room first, so that a failure leaves the pool as it was.
      chunks_.reserve(chunks_.size() + 1);
      auto* chunk = static_cast<unsigned char*>(huge_page_block(kHugePageBytes));
      shelve_rest_of_chunk();
      chunks_.insert(std::upper_bound(chunks_.begin(), chunks_.end(), chunk), chunk);
      cursor_ = chunk;
      end_ = chunk + kHugePageBytes;
    }
    void* p = cursor_;
    cursor_ += size;
    ++live_;
    return p;
  }

  void deallocate(void* p, std::size_t bytes) noexcept {
    const int k = size_class(bytes);
    const std::lock_guard lock(mutex_);
    if (!owns(p)) return;  // from before a fork: the parent's
    auto* b = static_cast<FreeBlock*>(p);
    b->next = free_[k];
    free_[k] = b;
    if (--live_ == 0) release_all_but_one();
  }

 private:
  MidBlockPool() {
#if defined(__unix__)
    // The lock is held across fork(), so that the child never inherits it locked mid-update.
    pthread_atfork([] { instance().mutex_.lock(); }, [] { instance().mutex_.unlock(); },
                   [] {
                     MidBlockPool& pool = instance();
                     pool.mutex_.unlock();
                     pool.forget_all();
                   });
#endif
  }

  struct FreeBlock {
    FreeBlock* next;
  };

  // Whether p lies in one of this process's chunks (sorted by address). O(log chunks).
  bool owns(const void* p) const noexcept {
    const auto* c = reinterpret_cast<const unsigned char*>(reinterpret_cast<std::uintptr_t>(p) & ~(kHugePageBytes - 1));
    return std::binary_search(chunks_.begin(), chunks_.end(), c);
  }

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

  // In a forked child: the inherited chunks are left mapped (live blocks may be in them) but
  // never carved or reused again.
  void forget_all() noexcept {
    chunks_.clear();
    free_.fill(nullptr);
    cursor_ = end_ = nullptr;
    live_ = 0;
  }

  std::mutex mutex_;
  std::array<FreeBlock*, kClasses> free_{};
  std::vector<unsigned char*> chunks_;  // sorted by address
  unsigned char* cursor_ = nullptr;     // the current chunk's unused part: [cursor_, end_)
  unsigned char* end_ = nullptr;
  std::size_t live_ = 0;
};


// Blocks above kPoolMaxBytes, each its own huge-page-aligned block. A freed one is kept and
// handed to the next request it fits (the smallest that holds it, at most twice its size) while
// other large blocks are live: its pages are faulted in already, where a fresh block pays a
// fault and a clear per huge page, the larger part of the system time of a mesher run at 0.5%
// of the diagonal. A run frees the sample's arrays and growing vectors' old blocks before it
// makes the restricted facets' tables, which then take those pages (BENCHMARKS.md, "Session
// 27"). Kept blocks never exceed the live ones in bytes (so the run's footprint at most
// doubles, and in practice grows by the blocks nothing reused), and all go back to the system
// once no large block is live. After fork() the child forgets the parent's blocks, as the pool
// does, and frees with std::free the ones it inherited.
class LargeBlockCache {
 public:
  static LargeBlockCache& instance() {
    static auto* cache = new LargeBlockCache;
    return *cache;
  }

  /// `bytes` is a multiple of kHugePageBytes.
  void* allocate(std::size_t bytes) {
    {
      const std::lock_guard lock(mutex_);
      std::size_t best = kept_.size();
      for (std::size_t i = 0; i < kept_.size(); ++i)
        if (kept_[i].bytes >= bytes && kept_[i].bytes / 2 <= bytes &&
            (best == kept_.size() || kept_[i].bytes < kept_[best].bytes))
          best = i;
      if (best != kept_.size()) {
        live_.reserve(live_.size() + 1);  // room first: a throw leaves the lists as they were
        const Block b = kept_[best];
        kept_[best] = kept_.back();
        kept_.pop_back();
        kept_bytes_ -= b.bytes;
        live_.push_back(b);
        live_bytes_ += b.bytes;
        return b.p;
      }
    }
    void* p = huge_page_block(bytes);
    try {
      const std::lock_guard lock(mutex_);
      live_.push_back({p, bytes});
      live_bytes_ += bytes;
    } catch (...) {
      std::free(p);
      throw;
    }
    return p;
  }

  std::size_t kept_bytes() noexcept {
    const std::lock_guard lock(mutex_);
    return kept_bytes_;
  }

  void deallocate(void* p) noexcept {
    std::array<void*, kMaxKept + 1> release{};
    std::size_t n = 0;
    {
      const std::lock_guard lock(mutex_);
      const auto it = std::find_if(live_.begin(), live_.end(), [p](const Block& b) { return b.p == p; });
      if (it == live_.end()) {
        release[n++] = p;  // inherited from the parent before a fork
      } else {
        const Block b = *it;
        *it = live_.back();
        live_.pop_back();
        live_bytes_ -= b.bytes;
        if (live_.empty()) {
          for (const Block& k : kept_) release[n++] = k.p;
          kept_.clear();
          kept_bytes_ = 0;
          release[n++] = b.p;
        } else if (kept_.size() < kMaxKept && kept_bytes_ + b.bytes <= live_bytes_) {
          kept_.push_back(b);
          kept_bytes_ += b.bytes;
        } else {
          release[n++] = b.p;
        }
      }
    }
    for (std::size_t i = 0; i < n; ++i) std::free(release[i]);
  }

 private:
  static constexpr std::size_t kMaxKept = 32;
  struct Block {
    void* p;
    std::size_t bytes;
  };

  LargeBlockCache() {
    kept_.reserve(kMaxKept);  // deallocate() never allocates
#if defined(__unix__)
    pthread_atfork([] { instance().mutex_.lock(); }, [] { instance().mutex_.unlock(); },
                   [] {
                     LargeBlockCache& cache = instance();
                     cache.mutex_.unlock();
                     cache.live_.clear();
                     cache.kept_.clear();
                     cache.live_bytes_ = cache.kept_bytes_ = 0;
                   });
#endif
  }

  std::mutex mutex_;
  std::vector<Block> live_, kept_;
  std::size_t live_bytes_ = 0, kept_bytes_ = 0;
};

}  // namespace

void* allocate_large(std::size_t bytes) {
  if (bytes < kPoolMinBytes || (!kPoolInUse && bytes <= kPoolMaxBytes)) return ::operator new(bytes);
  if (bytes <= kPoolMaxBytes) return MidBlockPool::instance().allocate(bytes);
  const std::size_t rounded = rounded_to_huge_pages(bytes);
  if (rounded < bytes) throw std::bad_alloc();
  return kPoolInUse ? LargeBlockCache::instance().allocate(rounded) : huge_page_block(rounded);
}

void deallocate_large(void* p, std::size_t bytes) noexcept {
  if (p == nullptr) return;
  if (bytes < kPoolMinBytes || (!kPoolInUse && bytes <= kPoolMaxBytes)) {
    ::operator delete(p);
  } else if (bytes <= kPoolMaxBytes) {
    MidBlockPool::instance().deallocate(p, bytes);
  } else if (kPoolInUse) {
    LargeBlockCache::instance().deallocate(p);
  } else {
    std::free(p);
  }
}

std::size_t kept_large_bytes() noexcept { return kPoolInUse ? LargeBlockCache::instance().kept_bytes() : 0; }

}  // namespace delpsc::kernel
