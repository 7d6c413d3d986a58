// Sorting a triangle mesh's edge records (one per triangle side, each naming its ends lo < hi)
// so that the records of one edge are adjacent: by lo with a counting sort over the vertex ids,
// then each vertex's short run by the caller's order. The topology report and the distance
// measurement of `delpsc mesh` both group sides this way; a comparison sort of the 3T records
// was their largest part (std::sort: ~30 compares a record at 40,000 records, against ~3 in a
// run of a vertex's ~6 sides).
//
// Cost: O(n + V) for n records and vertex ids below V, plus the runs' sorts; O(n + V) memory.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <delpsc/kernel/large_array.h>

namespace delpsc::refine {

/// Sorts `records` (a vector of records, each with a std::uint32_t member `lo`, below
/// `vertex_bound`; any allocator) into the order
/// std::sort(records, less) gives, for a `less` that orders by `lo` first and is a strict total
/// order on the records (with ties in `less` the order within them is unspecified, as for
/// std::sort). Precondition: every lo < vertex_bound.
template <class Records, class Less>
void sort_edge_records(Records& records, std::size_t vertex_bound, Less less) {
  using Record = typename Records::value_type;
  kernel::LargeVector<std::uint32_t> first(vertex_bound + 1, 0);
  for (const Record& r : records) ++first[r.lo + 1];
  for (std::size_t v = 0; v < vertex_bound; ++v) first[v + 1] += first[v];
  Records sorted(records.size());
  {
    kernel::LargeVector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (const Record& r : records) sorted[fill[r.lo]++] = r;
  }
  for (std::size_t v = 0; v < vertex_bound; ++v)
    if (first[v + 1] - first[v] > 1) std::sort(sorted.begin() + first[v], sorted.begin() + first[v + 1], less);
  records.swap(sorted);
}

}  // namespace delpsc::refine
