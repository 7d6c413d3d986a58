// A surface point inside the power cell of a ball (cell_surface_point.h).
#include "cell_surface_point.h"

#include <algorithm>
#include <span>
#include <vector>

#include <delpsc/kernel/predicates.h>

namespace delpsc::refine {

using delaunay::CellId;
using delaunay::PointId;

namespace {

/// One side of p's power cell, in coordinates y = x - p relative to p's centre: y.normal <= offset.
struct HalfSpace {
  Vec3 normal;
  double offset;
};

/// The convex polygon `poly` cut by the half-spaces (Sutherland-Hodgman, in doubles: the caller
/// checks what it takes from it exactly). Empty when nothing is left.
void clip_polygon(std::vector<Vec3>& poly, std::span<const HalfSpace> sides, std::vector<Vec3>& scratch) {
  for (const HalfSpace& h : sides) {
    if (poly.empty()) return;
    scratch.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec3 &a = poly[i], &b = poly[(i + 1) % poly.size()];
      const double da = a.dot(h.normal) - h.offset, db = b.dot(h.normal) - h.offset;
      if (da <= 0) scratch.push_back(a);
      if ((da < 0 && db > 0) || (da > 0 && db < 0)) scratch.push_back(a + (da / (da - db)) * (b - a));
    }
    poly.swap(scratch);
  }
}

}  // namespace

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
  if (best) return best;
  // Nor there: a needle standing in the cell of a ball at its tip (a cone of 8° on a sheet at 2%)
  // is missed by every segment from the tip, and the domain's points nearest to the Voronoi
  // vertices lie just outside the cell; refining the ball gave the same cell one scale down, to
  // the balls' floor. The farthest point of the wanted patches in the cell itself: their
  // triangles near it cut by the cell's sides, the largest power distance at a corner of what is
  // left (power distance is convex: on each flat polygon it peaks at a corner), each corner
  // moved a little toward its polygon's centre so that rounding leaves it inside; consider()
  // then checks it exactly.
  kernel::Box3 box;
  bool bounded = true;
  for (const CellId c : star) {
    if (dt.is_infinite(c))
      bounded = false;
    else
      box.extend(dt.orthocentre(c));
  }
  const kernel::Box3 whole = domain.bounding_box();
  if (!bounded) box = whole;
  box.lo = box.lo.cwiseMax(whole.lo);
  box.hi = box.hi.cwiseMin(whole.hi);
  std::vector<PatchTriangle> triangles;
  domain.triangles_in_box(box, triangles);
  std::vector<HalfSpace> sides;
  for (const PointId q : neighbours) {
    const WeightedPoint& wq = dt.point(q);
    const Vec3 d = wq.point() - wp.point();
    sides.push_back({2 * d, d.squaredNorm() + wp.w - wq.w});
  }
  constexpr double kInward = 1e-6;  // of the way to the polygon's centre
  std::vector<Vec3> polygon, scratch;
  for (const PatchTriangle& t : triangles) {
    if (!wanted(t.patch)) continue;
    polygon.assign({t.corners[0] - wp.point(), t.corners[1] - wp.point(), t.corners[2] - wp.point()});
    clip_polygon(polygon, sides, scratch);
    if (polygon.size() < 3) continue;
    Vec3 centre = Vec3::Zero();
    for (const Vec3& y : polygon) centre += y;
    centre /= static_cast<double>(polygon.size());
    for (const Vec3& y : polygon) consider(SurfaceHit{wp.point() + y + kInward * (centre - y), 0, t.patch, false});
  }
  return best;
}

}  // namespace delpsc::refine
