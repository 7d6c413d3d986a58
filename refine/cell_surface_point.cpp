// A surface point inside the power cell of a ball (cell_surface_point.h).
#include "cell_surface_point.h"

#include <algorithm>
#include <vector>

#include <delpsc/kernel/predicates.h>

namespace delpsc::refine {

using delaunay::CellId;
using delaunay::PointId;

std::optional<SurfaceHit> surface_point_in_cell(const delaunay::RegularTriangulation& dt, const Domain& domain,
                                                PointId p, double min_power,
                                                const std::function<bool(std::uint32_t patch)>& wanted) {
  if (dt.status(p) != delaunay::PointStatus::vertex) return std::nullopt;
  std::vector<CellId> star;
  dt.incident_cells(p, star);
  std::vector<PointId> neighbours;
  for (const CellId c : star)
    for (int i = 0; i < 4; ++i)
      if (const PointId v = dt.vertex(c, i); v != delaunay::kInfiniteVertex && v != p) neighbours.push_back(v);
  std::sort(neighbours.begin(), neighbours.end());
  neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());

  const WeightedPoint& wp = dt.point(p);
  std::optional<SurfaceHit> best;
  double best_power = min_power;
  const auto consider = [&](const SurfaceHit& h) {
    // Rounded power first (a filter: the exact tests below decide).
    const double power = (h.point - wp.point()).squaredNorm() - wp.w;
    if (power < best_power || !wanted(h.patch)) return;
    const double x[3] = {h.point.x(), h.point.y(), h.point.z()};
    if (kernel::power_distance_sign(x, wp.data()) <= 0) return;
    const bool in_cell = std::none_of(neighbours.begin(), neighbours.end(), [&](PointId q) {
      return kernel::compare_power_distance(x, wp.data(), dt.point(q).data()) > 0;
    });
    if (!in_cell) return;
    best_power = power;
    best = h;
  };
  std::vector<SurfaceHit> hits;
  for (const CellId c : star) {
    if (dt.is_infinite(c)) continue;
    hits.clear();
    domain.intersect_segment(wp.point(), dt.orthocentre(c), hits);
    for (const SurfaceHit& h : hits) consider(h);
  }
  if (best) return best;
  // None on those segments: p on a needle narrower than the spacing around it (a cone of 1°),
  // whose side wraps round p inside p's cell while every segment from p leaves the needle. The
  // surface points nearest to p's Voronoi vertices: each is no farther from its vertex than p is.
  for (const CellId c : star) {
    if (dt.is_infinite(c)) continue;
    if (const auto x = domain.closest_point(dt.orthocentre(c))) consider(SurfaceHit{x->point, 0, x->patch, false});
  }
  return best;
}

}  // namespace delpsc::refine
