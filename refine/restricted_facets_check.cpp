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

// Whether the scan's record puts its point where another vertex is clearly power-nearer than the
// triangle's: the dual edge the scan computed (from nearly flat cells, see
// RestrictedFacets::dual_projected) runs where the true one does not. Brute force over the
// vertices: it runs only for the pairs the two sides disagree on.
bool off_its_voronoi_edge(const delaunay::RegularTriangulation& dt, const RestrictedFacet& r, double scale2) {
  const auto power = [&](PointId v) {
    const WeightedPoint& w = dt.point(v);
    return (r.point - w.point()).squaredNorm() - w.w;
  };
  const double own = std::min({power(r.vertices[0]), power(r.vertices[1]), power(r.vertices[2])});
  const double tolerance = 1e-6 * std::abs(own) + 1e-12 * scale2;
  for (PointId v = 0; v < dt.number_of_points(); ++v)
    if (dt.status(v) == delaunay::PointStatus::vertex && power(v) < own - tolerance) return true;
  return false;
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
  if (only.empty()) return problems;
  const kernel::Box3 box = domain.bounding_box();
  const double scale2 = (box.hi - box.lo).squaredNorm();
  fresh.for_each([&](std::uint32_t, const RestrictedFacet& r) {
    const Pair p{r.vertices[0], r.vertices[1], r.vertices[2], r.patch};
    if (problems.size() < max_problems && std::binary_search(only.begin(), only.end(), p) &&
        !off_its_voronoi_edge(dt, r, scale2))
      problems.push_back(describe(p, "is found by a fresh scan but not kept"));
  });
  return problems;
}

}  // namespace delpsc::refine
