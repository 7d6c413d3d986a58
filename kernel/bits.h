// Integer tools several modules share: a 64-bit mixing function, a radix sort of (key, index)
// pairs (in a LargeVector: the sorts run over every candidate or point of a batch), and a sort
// of three values.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "large_array.h"

namespace delpsc::kernel {

/// splitmix64's finaliser (Steele, Lea & Flood 2014): a bijection of 64-bit integers whose
/// every output bit depends on every input bit. For hashing small consecutive integers (grid
/// cells) and, applied to a counter advanced by 0x9e3779b97f4a7c15, as a tiny deterministic
/// generator.
inline std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

/// Sorts (key, index) pairs by the low `key_bits` bits of the key (1 to 64), stably: least
/// significant digit first, 8 or 16 bits a pass, skipping a digit that all keys share. O(n) per pass,
/// n extra pairs of memory.
using KeyedIndices = LargeVector<std::pair<std::uint64_t, std::uint32_t>>;
void radix_sort_by_key(KeyedIndices& items, int key_bits = 64);

/// Sorts three values in increasing order by three compare-exchanges, without branches on the
/// values. For the vertex ids of a facet, sorted once per facet examined: std::sort on three
/// items goes through an insertion sort whose moves call memmove (2.3% of meshing the cube).
template <class T>
inline void sort3(std::array<T, 3>& v) {
  const auto exchange = [](T& a, T& b) {
    const T lo = std::min(a, b), hi = std::max(a, b);
    a = lo;
    b = hi;
  };
  exchange(v[0], v[1]);
  exchange(v[1], v[2]);
  exchange(v[0], v[1]);
}

}  // namespace delpsc::kernel
