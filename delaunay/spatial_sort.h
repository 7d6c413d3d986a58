// Spatial sorting of a batch of points before incremental insertion.
//
// Inserting points in an order where consecutive points are close keeps the location walks short
// and the touched memory in cache; inserting them in random order keeps the expected size of the
// conflict regions constant. BRIO (Amenta, Choi & Rote, "Incremental constructions con BRIO",
// SoCG 2003) gets both: the points are shuffled, split into rounds of geometrically growing size
// (each round 8 times the previous one, as CGAL's spatial_sort), and each round is sorted along a
// 3D Hilbert curve (Skilling, "Programming the Hilbert curve", AIP Conf. Proc. 707, 2004).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <delpsc/kernel/point.h>

namespace delpsc::delaunay {

/// Sorts `indices` (indices into `points`) in place along a Hilbert curve through the bounding box
/// of those points, on a grid of 2^bits cells per axis (bits in [1, 21]; the default resolves
/// 10^9 cells, plenty for locality). O(n) key computation + O(n) radix sort. Ties keep no
/// particular order. Non-finite coordinates are outside the contract.
void hilbert_sort(std::span<const WeightedPoint> points, std::span<std::uint32_t> indices,
                  int bits = 10);

/// Returns in `order` a permutation of [0, points.size()) suited to incremental insertion: BRIO
/// rounds (shuffled with `seed`, deterministic), each Hilbert-sorted; the last round holds about
/// 7/8 of the points, rounds below `small_round` points are merged into the first. O(n log n)
/// expected (the shuffle is O(n), each round's radix sort O(round size)).
void brio_order(std::span<const WeightedPoint> points, std::vector<std::uint32_t>& order,
                std::uint64_t seed = 0x9e3779b97f4a7c15ull, std::size_t small_round = 64);

}  // namespace delpsc::delaunay
