#include "bits.h"

#include <algorithm>

namespace delpsc::kernel {

void radix_sort_by_key(KeyedIndices& items, int key_bits) {
  // 16-bit digits (fewer passes) once the items outnumber the counters; 8-bit below.
  const int width = items.size() >= (std::size_t{1} << 16) ? 16 : 8;
  std::vector<std::size_t> count((std::size_t{1} << width) + 1);
  KeyedIndices other(items.size());
  for (int shift = 0; shift < key_bits; shift += width) {
    // The last digit may be narrower: bits above key_bits take no part.
    const std::uint64_t digit = (std::uint64_t{1} << std::min(width, key_bits - shift)) - 1;
    std::fill(count.begin(), count.end(), 0);
    for (const auto& it : items) ++count[((it.first >> shift) & digit) + 1];
    // One digit for all keys: the pass would leave the order as it is.
    if (std::find(count.begin() + 1, count.end(), items.size()) != count.end()) continue;
    for (std::size_t b = 0; b + 1 < count.size(); ++b) count[b + 1] += count[b];
    for (const auto& it : items) other[count[(it.first >> shift) & digit]++] = it;
    items.swap(other);
  }
}

}  // namespace delpsc::kernel
