#include "extra_pieces.h"

#include <algorithm>
#include <numeric>

namespace delpsc::refine {

std::vector<ExtraPiece> extra_pieces(const RestrictedFacets& facets, std::size_t point_count) {
  // The live slots, read once: the records are ~100 bytes each, the later passes use this list.
  std::vector<std::uint32_t> live;
  live.reserve(facets.size());
  std::uint32_t patches = 0;
  facets.for_each([&](std::uint32_t s, const RestrictedFacet& r) {
    live.push_back(s);
    patches = std::max(patches, r.patch + 1);
  });
  if (live.empty()) return {};
  std::vector<std::uint32_t> parent(live.back() + 1);
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
  std::vector<std::uint32_t> count(parent.size(), 0), roots;
  for (const std::uint32_t s : live) {
    const std::uint32_t root = find(s);
    if (count[root]++ == 0) roots.push_back(root);  // a root is its piece's first slot: increasing
  }
  std::vector<std::uint32_t> main_piece(patches, kNoFacet);  // per patch, the root with most facets
  for (const std::uint32_t root : roots) {
    std::uint32_t& m = main_piece[facets[root].patch];
    if (m == kNoFacet || count[root] > count[m]) m = root;  // a tie keeps the lower
  }
  std::vector<ExtraPiece> out;
  std::vector<std::uint32_t> index(parent.size(), kNoFacet);  // per extra root, its place in out
  for (const std::uint32_t root : roots)
    if (main_piece[facets[root].patch] != root) {
      index[root] = static_cast<std::uint32_t>(out.size());
      out.push_back({facets[root].patch, {}});
    }
  if (out.empty()) return out;
  for (const std::uint32_t s : live)
    if (const std::uint32_t k = index[find(s)]; k != kNoFacet) out[k].facets.push_back(s);
  return out;
}

}  // namespace delpsc::refine
