#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <numeric>
#include <random>
#include <string>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>
#include <utility>
#include <vector>

#include <delpsc/kernel/large_array.h>

using namespace delpsc;

TEST_CASE("allocate_large: large blocks aligned to huge pages, small ones usable, contents kept") {
  for (const std::size_t bytes :
       {std::size_t{1}, kernel::kPoolMinBytes - 1, kernel::kPoolMinBytes, kernel::kPoolMinBytes + 1, kernel::kPoolMaxBytes,
        kernel::kPoolMaxBytes + 1, kernel::kHugePageBytes + 1, 3 * kernel::kHugePageBytes}) {
    auto* p = static_cast<unsigned char*>(kernel::allocate_large(bytes));
    REQUIRE(p != nullptr);
    CHECK(reinterpret_cast<std::uintptr_t>(p) % alignof(std::max_align_t) == 0);
    if (kernel::kPoolInUse && bytes >= kernel::kPoolMinBytes)
      CHECK(reinterpret_cast<std::uintptr_t>(p) % kernel::kPoolMinBytes == 0);
    if (bytes > kernel::kPoolMaxBytes) CHECK(reinterpret_cast<std::uintptr_t>(p) % kernel::kHugePageBytes == 0);
    for (std::size_t i = 0; i < bytes; i += 997) p[i] = static_cast<unsigned char>(i);
    p[bytes - 1] = 7;
    bool kept = p[bytes - 1] == 7;
    for (std::size_t i = 0; i + 1 < bytes; i += 997) kept = kept && p[i] == static_cast<unsigned char>(i);
    CHECK(kept);
    kernel::deallocate_large(p, bytes);
  }
  kernel::deallocate_large(nullptr, 12345);  // a no-op, as free(nullptr)
}

namespace {

// Allocates `count` pooled blocks of random sizes, fills each with its own pattern, and checks
// that they do not overlap and that every pattern survives the others' writes; frees them in
// random order. Returns false on the first fault found.
bool pooled_blocks_are_disjoint_and_kept(std::uint32_t seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> size(kernel::kPoolMinBytes, kernel::kPoolMaxBytes);
  std::vector<std::pair<unsigned char*, std::size_t>> blocks;
  for (int i = 0; i < count; ++i) {
    const std::size_t bytes = i % 3 == 0 ? size(rng) : size(rng) / 64 + kernel::kPoolMinBytes;
    auto* p = static_cast<unsigned char*>(kernel::allocate_large(bytes));
    std::fill(p, p + bytes, static_cast<unsigned char>(i * 7 + 1));
    blocks.emplace_back(p, bytes);
  }
  bool ok = true;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const auto [p, bytes] = blocks[i];
    ok = ok && std::all_of(p, p + bytes, [&](unsigned char c) { return c == static_cast<unsigned char>(i * 7 + 1); });
  }
  std::vector<std::pair<unsigned char*, std::size_t>> sorted = blocks;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 1; i < sorted.size(); ++i) ok = ok && sorted[i - 1].first + sorted[i - 1].second <= sorted[i].first;
  std::shuffle(blocks.begin(), blocks.end(), rng);
  for (const auto& [p, bytes] : blocks) kernel::deallocate_large(p, bytes);
  return ok;
}

}  // namespace

TEST_CASE("allocate_large: pooled blocks are disjoint, keep their contents, and are reused") {
  CHECK(pooled_blocks_are_disjoint_and_kept(1, 300));  // ~50 MiB: many chunks
  CHECK(pooled_blocks_are_disjoint_and_kept(2, 40));   // after every chunk but one went back

  // A freed block serves the next request of its size class (the pool's point: no new pages).
  void* keep = kernel::allocate_large(5000);  // keeps the pool from releasing its chunks
  void* a = kernel::allocate_large(6000);
  kernel::deallocate_large(a, 6000);
  void* b = kernel::allocate_large(8192);  // same class as 6000 (8 KiB)
  if (kernel::kPoolInUse) CHECK(b == a);
  kernel::deallocate_large(b, 8192);
  kernel::deallocate_large(keep, 5000);

  // Threads allocating and freeing at once.
  std::vector<int> ok(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([t, &ok] {
      bool all = true;
      for (int round = 0; round < 20; ++round) all = all && pooled_blocks_are_disjoint_and_kept(100 * t + round, 30);
      ok[t] = all;
    });
  for (std::thread& thread : threads) thread.join();
  CHECK(std::count(ok.begin(), ok.end(), 1) == 4);
}

// A forked child must not carve or reuse the parent's chunks (shared copy-on-write: every page
// it wrote there would be copied, a fault each), yet the blocks it inherited stay usable.
TEST_CASE("allocate_large: a forked child starts an empty pool") {
  if (!kernel::kPoolInUse) return;  // AddressSanitizer: no pool
  auto* inherited = static_cast<unsigned char*>(kernel::allocate_large(20000));  // keeps the parent's chunk
  std::fill(inherited, inherited + 20000, 5);
  void* freed = kernel::allocate_large(8192);
  kernel::deallocate_large(freed, 8192);  // on the parent's free list
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    int status = 0;
    void* mine = kernel::allocate_large(8192);
    const auto chunk = [](const void* p) { return reinterpret_cast<std::uintptr_t>(p) / kernel::kHugePageBytes; };
    if (mine == freed || chunk(mine) == chunk(inherited)) status |= 1;  // reused the parent's pages
    if (inherited[19999] != 5) status |= 2;                           // the inherited block is intact
    kernel::deallocate_large(inherited, 20000);                      // freeing it is harmless
    kernel::deallocate_large(mine, 8192);
    void* again = kernel::allocate_large(8192);
    if (chunk(again) == chunk(inherited)) status |= 4;
    kernel::deallocate_large(again, 8192);
    _exit(status);
  }
  int status = -1;
  REQUIRE(waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  kernel::deallocate_large(inherited, 20000);
}

TEST_CASE("LargeVector behaves as std::vector through growth past the large-block size") {
  kernel::LargeVector<std::uint64_t> v;
  const std::size_t n = 3 * kernel::kHugePageBytes / sizeof(std::uint64_t);  // ~6 MiB, crosses both sizes
  for (std::size_t i = 0; i < n; ++i) v.push_back(i * i);
  REQUIRE(v.size() == n);
  bool same = true;
  for (std::size_t i = 0; i < n; ++i) same = same && v[i] == i * i;
  CHECK(same);
  kernel::LargeVector<std::uint64_t> copy = v;  // copy, then shrink below the threshold
  copy.resize(10);
  copy.shrink_to_fit();
  CHECK(copy.size() == 10);
  CHECK(copy[9] == 81);
  CHECK(kernel::LargeArrayAllocator<int>() == kernel::LargeArrayAllocator<double>());
  CHECK(reinterpret_cast<std::uintptr_t>(v.data()) % kernel::kHugePageBytes == 0);
}

// Not a check (the kernel may lack huge pages or be out of them): shows whether the advice took.
TEST_CASE("LargeVector's huge pages, as the kernel reports them") {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  std::getline(mode, line);
  kernel::LargeVector<char> v(16 * kernel::kHugePageBytes, 1);
  std::ifstream rollup("/proc/self/smaps_rollup");
  std::string huge;
  for (std::string l; std::getline(rollup, l);)
    if (l.rfind("AnonHugePages", 0) == 0) huge = l;
  MESSAGE("THP mode: " << (line.empty() ? "unknown" : line) << "; " << (huge.empty() ? "no smaps_rollup" : huge));
  CHECK(v[v.size() - 1] == 1);
}

// A freed large block serves a later request it fits while other large blocks are live (its
// pages are faulted in already), never one more than twice smaller, and never two requests at
// once; all go back once no large block is live.
TEST_CASE("allocate_large: freed large blocks are reused while others are live") {
  if (!kernel::kPoolInUse) return;  // AddressSanitizer: no reuse
  const std::size_t huge = kernel::kHugePageBytes;
  void* keep = kernel::allocate_large(8 * huge);  // live throughout: blocks are kept
  auto* a = static_cast<unsigned char*>(kernel::allocate_large(4 * huge));
  a[0] = 3;
  kernel::deallocate_large(a, 4 * huge);
  void* small = kernel::allocate_large(huge);  // a quarter of a's size: a fresh block
  CHECK(small != a);
  auto* b = static_cast<unsigned char*>(kernel::allocate_large(3 * huge + 5));  // fits a, not twice smaller
  CHECK(b == a);
  void* c = kernel::allocate_large(3 * huge);  // a is taken: a fresh block
  CHECK(c != a);
  b[4 * huge - 1] = 1;  // the whole of a's size is usable (rounded up: a request of 4 huge pages)
  kernel::deallocate_large(c, 3 * huge);
  kernel::deallocate_large(b, 3 * huge + 5);
  kernel::deallocate_large(small, huge);
  CHECK(kernel::kept_large_bytes() == 8 * huge);  // c, b and small: kept, as many bytes as keep's...
  kernel::deallocate_large(keep, 8 * huge);        // ...until none is live: all released
  CHECK(kernel::kept_large_bytes() == 0);
  // Kept blocks never outweigh the live ones: with `one` and `big` live (2 + 4 huge pages) a
  // freed block of 2 is kept, then with `one` alone `big` is not.
  void* one = kernel::allocate_large(huge + 1);
  void* big = kernel::allocate_large(4 * huge);
  void* mid = kernel::allocate_large(2 * huge);
  kernel::deallocate_large(mid, 2 * huge);
  CHECK(kernel::kept_large_bytes() == 2 * huge);
  kernel::deallocate_large(big, 4 * huge);
  CHECK(kernel::kept_large_bytes() == 2 * huge);
  kernel::deallocate_large(one, huge + 1);
  CHECK(kernel::kept_large_bytes() == 0);
}

// A forked child forgets the parent's kept large blocks (writing into them would copy them page
// by page) and frees the large blocks it inherited with the system's free, not into its own cache.
TEST_CASE("allocate_large: a forked child starts with no kept large blocks") {
  if (!kernel::kPoolInUse) return;  // AddressSanitizer: no reuse
  const std::size_t huge = kernel::kHugePageBytes;
  auto* inherited = static_cast<unsigned char*>(kernel::allocate_large(4 * huge));  // live in both
  inherited[0] = 7;
  void* kept = kernel::allocate_large(2 * huge);
  kernel::deallocate_large(kept, 2 * huge);
  REQUIRE(kernel::kept_large_bytes() == 2 * huge);
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    int status = 0;
    if (kernel::kept_large_bytes() != 0) status |= 1;
    void* mine = kernel::allocate_large(2 * huge);
    if (mine == kept) status |= 2;            // took the parent's kept block
    if (inherited[0] != 7) status |= 4;       // the inherited block is intact
    kernel::deallocate_large(inherited, 4 * huge);  // not the child's: freed, not kept
    if (kernel::kept_large_bytes() != 0) status |= 8;
    kernel::deallocate_large(mine, 2 * huge);
    _exit(status);
  }
  int status = -1;
  REQUIRE(waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(kernel::kept_large_bytes() == 2 * huge);  // the parent's cache is its own
  kernel::deallocate_large(inherited, 4 * huge);
  CHECK(kernel::kept_large_bytes() == 0);
}
