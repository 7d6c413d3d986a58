#include "extra_pieces.h"

#include <algorithm>
#include <numeric>

namespace delpsc::refine {

std::vector<ExtraPiece> extra_pieces(const RestrictedFacets& facets, std::size_t point_count) {
  // One array on the common path (every patch in one piece), the union-find's: the mesher asks
  // once per run, in a process that often has just started, where each fresh page is a fault
  // (four such arrays cost the cube at 1.87% 27 faults, ~4% of a fresh run on these machines).
  std::uint32_t slots = 0, patches = 0;
  facets.for_each([&](std::uint32_t s, const RestrictedFacet& r) {
    slots = s + 1;
    patches = std::max(patches, r.patch + 1);
  });
  if (slots == 0) return {};
  std::vector<std::uint32_t> parent(slots);
  std::iota(parent.begin(), parent.end(), 0u);
  const auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  // At each vertex, every incidence joins the first one of its patch there; a root is the lowest
  // slot of its piece.
  for (std::size_t v = 0; v < point_count; ++v) {
    const auto around = facets.incident(static_cast<PointId>(v));
    for (std::size_t i = 1; i < around.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (around[j].patch == around[i].patch) {
          const std::uint32_t a = find(around[i].slot), b = find(around[j].slot);
          if (a != b) parent[std::max(a, b)] = std::min(a, b);
          break;
        }
  }
  // The roots, in increasing order (a root is its piece's first live slot), and whether some
  // patch has two.
  std::vector<std::uint32_t> roots;
  std::vector<char> seen(patches, 0);
  bool split = false;
  facets.for_each([&](std::uint32_t s, const RestrictedFacet& r) {
    if (find(s) != s) return;
    roots.push_back(s);
    split |= seen[r.patch]++ != 0;
  });
  if (!split) return {};
  std::vector<std::uint32_t> count(slots, 0);
  facets.for_each([&](std::uint32_t s, const RestrictedFacet&) { ++count[find(s)]; });
  std::vector<std::uint32_t> main_piece(patches, kNoFacet);  // per patch, the root with most facets
  for (const std::uint32_t root : roots) {
    std::uint32_t& m = main_piece[facets[root].patch];
    if (m == kNoFacet || count[root] > count[m]) m = root;  // a tie keeps the lower
  }
  std::vector<ExtraPiece> out;
  std::vector<std::uint32_t>& index = count;  // reused: per extra root, its place in out
  std::fill(index.begin(), index.end(), kNoFacet);
  for (const std::uint32_t root : roots)
    if (main_piece[facets[root].patch] != root) {
      index[root] = static_cast<std::uint32_t>(out.size());
      out.push_back({facets[root].patch, {}});
    }
  facets.for_each([&](std::uint32_t s, const RestrictedFacet&) {
    if (const std::uint32_t k = index[find(s)]; k != kNoFacet) out[k].facets.push_back(s);
  });
  return out;
}

}  // namespace delpsc::refine
