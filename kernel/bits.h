// Two integer tools several modules share: a 64-bit mixing function and a radix sort of
// (key, index) pairs (in a LargeVector: the sorts run over every candidate or point of a batch).
#pragma once

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

}  // namespace delpsc::kernel
