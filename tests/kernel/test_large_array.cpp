#include <doctest/doctest.h>

#include <cstdint>
#include <fstream>
#include <numeric>
#include <string>

#include <delpsc/kernel/large_array.h>

using namespace delpsc;

TEST_CASE("allocate_large: large blocks aligned to huge pages, small ones usable, contents kept") {
  for (const std::size_t bytes : {std::size_t{1}, std::size_t{4096}, kernel::kLargeBlockBytes - 1, kernel::kLargeBlockBytes,
                                  kernel::kHugePageBytes + 1, 3 * kernel::kHugePageBytes}) {
    auto* p = static_cast<unsigned char*>(kernel::allocate_large(bytes));
    REQUIRE(p != nullptr);
    CHECK(reinterpret_cast<std::uintptr_t>(p) % alignof(std::max_align_t) == 0);
    if (bytes >= kernel::kLargeBlockBytes) CHECK(reinterpret_cast<std::uintptr_t>(p) % kernel::kHugePageBytes == 0);
    for (std::size_t i = 0; i < bytes; i += 997) p[i] = static_cast<unsigned char>(i);
    p[bytes - 1] = 7;
    bool kept = p[bytes - 1] == 7;
    for (std::size_t i = 0; i + 1 < bytes; i += 997) kept = kept && p[i] == static_cast<unsigned char>(i);
    CHECK(kept);
    kernel::deallocate_large(p, bytes);
  }
  kernel::deallocate_large(nullptr, 12345);  // a no-op, as free(nullptr)
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
