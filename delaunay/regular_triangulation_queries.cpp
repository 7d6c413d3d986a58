// Read-only queries of the regular triangulation: stars, rings around edges, duals.
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

#include <Eigen/Geometry>

#include <delpsc/kernel/constructions.h>

#include "regular_triangulation.h"
#include "tetrahedron_tables.h"

namespace delpsc::delaunay {

using detail::kFacetSlots;

namespace {

/// Visited-set for the star walks: a linear scan of the cells found so far while the star is
/// small (the usual case, ~27 cells), a hash set beyond. Local, so const queries stay re-entrant.
class VisitedCells {
 public:
  VisitedCells(std::vector<CellId>& out) : out_(out), first_(out.size()) {}
  bool insert(CellId c) {
    if (out_.size() - first_ < 48) {
      if (std::find(out_.begin() + static_cast<std::ptrdiff_t>(first_), out_.end(), c) != out_.end())
        return false;
      out_.push_back(c);
      if (out_.size() - first_ == 48) set_.insert(out_.begin() + static_cast<std::ptrdiff_t>(first_), out_.end());
      return true;
    }
    if (!set_.insert(c).second) return false;
    out_.push_back(c);
    return true;
  }

 private:
  std::vector<CellId>& out_;
  std::size_t first_;
  std::unordered_set<CellId> set_;
};

}  // namespace

std::array<PointId, 3> RegularTriangulation::facet_vertices(Facet f) const {
  const int* s = kFacetSlots[f.index];
  const auto& v = cells_[f.cell].v;
  return {v[s[0]], v[s[1]], v[s[2]]};
}

void RegularTriangulation::incident_cells(PointId v, std::vector<CellId>& out) const {
  if (dimension() < 3) return;
  if (v != kInfiniteVertex && status_[v] != PointStatus::vertex) return;
  const std::size_t first = out.size();
  VisitedCells visited(out);
  visited.insert(incident_cell(v));
  for (std::size_t k = first; k < out.size(); ++k) {
    const Cell& cell = cells_[out[k]];
    for (int i = 0; i < 4; ++i)
      if (cell.v[i] != v) visited.insert(cell.n[i] >> 2);
  }
}

void RegularTriangulation::incident_facets(PointId v, std::vector<Facet>& out) const {
  std::vector<CellId> star;
  incident_cells(v, star);
  for (const CellId c : star) {
    const int iv = index_of(c, v);
    for (int i = 0; i < 4; ++i) {
      if (i == iv) continue;
      // Each facet is shared by two cells of the star: name it from the smaller link.
      const std::uint32_t self = detail::make_link(c, i);
      if (self < cells_[c].n[i]) out.push_back({c, i});
    }
  }
}

// Turning around the edge (a, b): in a cell (a, b, x, y), leave through the facet opposite x, which
// is (a, b, y); the next cell is (a, b, y, z) and we leave it through the facet opposite y. The
// rotation sense is fixed by the choice of x at the start.
void RegularTriangulation::cells_around_edge(CellId c, int i, int j, std::vector<CellId>& out) const {
  std::vector<Facet> ring;
  facets_around_edge(c, i, j, ring);
  for (const Facet& f : ring) out.push_back(f.cell);
}

void RegularTriangulation::facets_around_edge(CellId c, int i, int j, std::vector<Facet>& out) const {
  const PointId a = cells_[c].v[i], b = cells_[c].v[j];
  int k = 0;
  while (k == i || k == j) ++k;
  PointId x = cells_[c].v[k];
  CellId cur = c;
  do {
    const Cell& cell = cells_[cur];
    const int sx = index_of(cur, x);
    out.push_back({cur, sx});
    PointId y = kNoPoint;
    for (const PointId w : cell.v)
      if (w != a && w != b && w != x) y = w;
    cur = cell.n[sx] >> 2;
    x = y;
  } while (cur != c);
}

Vec3 RegularTriangulation::orthocentre(CellId c) const {
  const auto& v = cells_[c].v;
  const auto o = kernel::orthocentre(points_[v[0]], points_[v[1]], points_[v[2]], points_[v[3]]);
  if (!o) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  return o->point();
}

double RegularTriangulation::orthoradius_squared(CellId c) const {
  const auto& v = cells_[c].v;
  const auto o = kernel::orthocentre(points_[v[0]], points_[v[1]], points_[v[2]], points_[v[3]]);
  return o ? o->w : std::numeric_limits<double>::quiet_NaN();
}

VoronoiEdge RegularTriangulation::dual(Facet f) const {
  VoronoiEdge e;
  Facet inside = f;
  Facet other = mirror_facet(f);
  if (is_infinite(inside.cell)) std::swap(inside, other);
  e.source = orthocentre(inside.cell);
  if (!is_infinite(other.cell)) {
    e.target = orthocentre(other.cell);
    return e;
  }
  // Hull facet: the ray leaves along the outward normal. facet_vertices lists the facet so that
  // the cell's opposite vertex is on the side of (b - a) x (c - a); outward is the other side.
  const auto t = facet_vertices(inside);
  const Vec3 a = points_[t[0]].point(), b = points_[t[1]].point(), cc = points_[t[2]].point();
  const Vec3 ab = b - a, ac = cc - a;
  e.direction = -ab.cross(ac);
  e.is_ray = true;
  return e;
}

}  // namespace delpsc::delaunay
