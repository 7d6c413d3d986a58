#include "admissibility_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <delpsc/kernel/predicates.h>

namespace delpsc::refine {

std::vector<std::string> check_admissibility(const delaunay::RegularTriangulation& dt, std::size_t max_problems) {
  using delaunay::PointId;
  std::vector<PointId> unweighted, weighted;
  for (PointId id = 0; id < dt.number_of_points(); ++id) {
    if (dt.status(id) != delaunay::PointStatus::vertex) continue;
    (dt.point(id).w > 0 ? weighted : unweighted).push_back(id);
  }
  // Unweighted vertices sorted by x: each ball scans the slab of x within (a generous bound on)
  // its radius, and the exact predicate decides.
  std::sort(unweighted.begin(), unweighted.end(), [&](PointId a, PointId b) { return dt.point(a).x < dt.point(b).x; });
  std::vector<std::string> problems;
  for (const PointId b : weighted) {
    const WeightedPoint& ball = dt.point(b);
    const double reach = 2 * std::sqrt(ball.w) + 1e-12 * std::fabs(ball.x);  // > radius, whatever the rounding
    const auto first = std::lower_bound(unweighted.begin(), unweighted.end(), ball.x - reach,
                                        [&](PointId u, double x) { return dt.point(u).x < x; });
    for (auto it = first; it != unweighted.end() && dt.point(*it).x <= ball.x + reach; ++it) {
      const WeightedPoint& u = dt.point(*it);
      if (kernel::power_distance_sign(u.data(), ball.data()) > 0) continue;
      char line[200];
      std::snprintf(line, sizeof line, "unweighted vertex %u (%.17g %.17g %.17g) in or on the ball of vertex %u",
                    static_cast<unsigned>(*it), u.x, u.y, u.z, static_cast<unsigned>(b));
      problems.emplace_back(line);
      if (problems.size() == max_problems) return problems;
    }
  }
  return problems;
}

}  // namespace delpsc::refine
