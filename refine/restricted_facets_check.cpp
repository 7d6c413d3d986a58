#include "restricted_facets_check.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace delpsc::refine {

namespace {

using Pair = std::array<std::uint32_t, 4>;  // sorted triangle vertices, patch

std::vector<Pair> pairs_of(const RestrictedFacets& facets) {
  std::vector<Pair> out;
  facets.for_each([&](std::uint32_t, const RestrictedFacet& r) {
    out.push_back({r.vertices[0], r.vertices[1], r.vertices[2], r.patch});
  });
  std::sort(out.begin(), out.end());
  return out;
}

std::string describe(const Pair& p, const char* where) {
  return "triangle " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) +
         " restricted to patch " + std::to_string(p[3]) + " " + where;
}

}  // namespace

std::vector<std::string> check_restricted_facets(const delaunay::RegularTriangulation& dt, const Domain& domain,
                                                 const RestrictedFacets& kept, std::size_t max_problems) {
  RestrictedFacets fresh(dt, domain);
  std::vector<PointId> touched;
  fresh.rebuild(touched);
  const std::vector<Pair> a = pairs_of(kept), b = pairs_of(fresh);
  std::vector<std::string> problems;
  std::vector<Pair> only;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(only));
  for (const Pair& p : only)
    if (problems.size() < max_problems) problems.push_back(describe(p, "is kept but a fresh scan does not find it"));
  only.clear();
  std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(only));
  for (const Pair& p : only)
    if (problems.size() < max_problems) problems.push_back(describe(p, "is found by a fresh scan but not kept"));
  return problems;
}

}  // namespace delpsc::refine
