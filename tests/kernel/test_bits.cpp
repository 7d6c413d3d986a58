#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <set>

#include <delpsc/kernel/bits.h>

using namespace delpsc;

TEST_CASE("radix_sort_by_key sorts stably by the low key bits, as std::stable_sort does") {
  std::mt19937_64 rng(5);
  for (const int key_bits : {8, 21, 42, 63, 64}) {
    for (const std::size_t n : {0, 1, 2, 17, 1000, 70000}) {
      kernel::KeyedIndices items(n);
      const std::uint64_t mask = key_bits == 64 ? ~0ull : (1ull << key_bits) - 1;
      for (std::uint32_t i = 0; i < n; ++i) {
        // Few distinct keys (ties, to see stability) sharing some digits (skipped passes), and
        // bits above key_bits that must be ignored.
        std::uint64_t key = (rng() % 50) << (key_bits > 16 ? 12 : 0);
        key = (key & mask) | (key_bits < 64 ? (rng() << key_bits) : 0);
        items[i] = {key, i};
      }
      auto expected = items;
      std::stable_sort(expected.begin(), expected.end(),
                       [&](const auto& a, const auto& b) { return (a.first & mask) < (b.first & mask); });
      kernel::radix_sort_by_key(items, key_bits);
      CHECK(items == expected);
    }
  }
}

TEST_CASE("mix64: splitmix64's finaliser, a bijection that spreads consecutive integers") {
  // Reference values of the published splitmix64 generator, seed 0: mix64 of the counter.
  CHECK(kernel::mix64(0x9e3779b97f4a7c15ull) == 0xe220a8397b1dcdafull);
  CHECK(kernel::mix64(0) == 0);
  std::set<std::uint64_t> seen;
  for (std::uint64_t i = 0; i < 10000; ++i) seen.insert(kernel::mix64(i) >> 50);  // top 14 bits
  CHECK(seen.size() > 7000);  // consecutive inputs land all over the range
}

TEST_CASE("sort3 sorts every arrangement of three values, ties included") {
  // All 27 triples over {0, 1, 2} (every order, with and without ties) against std::sort.
  for (std::uint32_t code = 0; code < 27; ++code) {
    std::array<std::uint32_t, 3> v{code % 3, code / 3 % 3, code / 9};
    std::array<std::uint32_t, 3> expected = v;
    std::sort(expected.begin(), expected.end());
    kernel::sort3(v);
    CHECK(v == expected);
  }
  std::array<std::uint32_t, 3> extremes{0xffffffffu, 0, 7};
  kernel::sort3(extremes);
  CHECK(extremes == std::array<std::uint32_t, 3>{0, 7, 0xffffffffu});
}
