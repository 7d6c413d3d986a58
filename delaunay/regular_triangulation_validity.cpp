// RegularTriangulation::is_valid: every invariant, checked exactly, with a readable diagnosis.
//
// Combinatorial validity (symmetric links, matching facets, a connected star around each vertex)
// plus positive orientation and local regularity of every facet imply that the cells form the
// regular triangulation of the vertices (Edelsbrunner & Shah 1996: locally regular => regular);
// the infinite-cell rule on the hull facets makes the hull locally, hence globally, convex.
#include <sstream>

#include <delpsc/kernel/predicates.h>

#include "regular_triangulation.h"
#include "tetrahedron_tables.h"

namespace delpsc::delaunay {

namespace kn = delpsc::kernel;
using detail::kFacetSlots;
using detail::make_link;

namespace {

bool fail(std::string* why, const std::string& message) {
  if (why) *why = message;
  return false;
}

std::string name(PointId v) { return v == kInfiniteVertex ? std::string("inf") : std::to_string(v); }

}  // namespace

bool RegularTriangulation::is_valid(std::string* why) const {
  const std::size_t np = points_.size();
  if (point_cell_.size() != np || status_.size() != np)
    return fail(why, "per-point arrays have inconsistent sizes");
  if (hidden_storage_ && (hidden_next_.size() != np || cell_hidden_.size() != cells_.size()))
    return fail(why, "hidden-point arrays have inconsistent sizes");

  // Counters and statuses.
  std::size_t vertices = 0, hidden = 0, pending = 0;
  for (PointId p = 0; p < np; ++p) {
    switch (status_[p]) {
      case PointStatus::vertex: ++vertices; break;
      case PointStatus::hidden: ++hidden; break;
      case PointStatus::pending: ++pending; break;
      case PointStatus::removed: break;
    }
  }
  if (vertices != vertex_count_ || hidden != hidden_count_)
    return fail(why, "counters disagree with statuses: " + std::to_string(vertices) + " vertices, " +
                         std::to_string(hidden) + " hidden; counters say " +
                         std::to_string(vertex_count_) + ", " + std::to_string(hidden_count_));
  if (dimension() < 3) {
    if (vertices || hidden) return fail(why, "dimension < 3 but some point is a vertex or hidden");
    if (pending != pending_.size()) return fail(why, "pending list and statuses disagree");
    return true;
  }
  if (pending) return fail(why, std::to_string(pending) + " points still pending in dimension 3");

  // Free list.
  std::size_t free_found = 0;
  for (CellId c = free_head_; c != kNoCell; c = cells_[c].n[0]) {
    if (c >= cells_.size() || is_cell_alive(c)) return fail(why, "free list reaches a live cell");
    if (++free_found > free_count_) return fail(why, "free list longer than its count");
  }
  if (free_found != free_count_) return fail(why, "free list shorter than its count");

  // Cells: vertices, links, orientation.
  std::size_t infinite_cells = 0;
  std::vector<std::uint32_t> occurrences(np, 0);
  for (CellId c = 0; c < cells_.size(); ++c) {
    if (!is_cell_alive(c)) continue;
    const Cell& cell = cells_[c];
    const std::string cname = "cell " + std::to_string(c);
    int infinite = 0;
    for (int i = 0; i < 4; ++i) {
      const PointId v = cell.v[i];
      if (v == kInfiniteVertex) {
        ++infinite;
        continue;
      }
      if (v >= np) return fail(why, cname + " has an invalid vertex id");
      if (status_[v] != PointStatus::vertex)
        return fail(why, cname + " uses point " + name(v) + " which is not a vertex");
      ++occurrences[v];
      for (int j = 0; j < i; ++j)
        if (cell.v[j] == v) return fail(why, cname + " repeats vertex " + name(v));
    }
    if (infinite > 1) return fail(why, cname + " has two infinite vertices");
    infinite_cells += infinite;
    for (int i = 0; i < 4; ++i) {
      const CellId d = cell.n[i] >> 2;
      const int j = static_cast<int>(cell.n[i] & 3u);
      if (d >= cells_.size() || !is_cell_alive(d))
        return fail(why, cname + " has a dead or invalid neighbour " + std::to_string(i));
      if (cells_[d].n[j] != make_link(c, i))
        return fail(why, cname + " facet " + std::to_string(i) + ": neighbour link not symmetric");
      // Same facet, opposite orientation.
      const auto fa = facet_vertices({c, i});
      const auto fb = facet_vertices({d, j});
      bool opposite = false;
      for (int r = 0; r < 3; ++r)
        opposite = opposite || (fa[0] == fb[r] && fa[1] == fb[(r + 2) % 3] && fa[2] == fb[(r + 1) % 3]);
      if (!opposite)
        return fail(why, cname + " facet " + std::to_string(i) + " is not the reversed facet of cell " +
                             std::to_string(d));
    }
    if (!infinite) {
      const double* q[4];
      for (int k = 0; k < 4; ++k) q[k] = points_[cell.v[k]].data();
      if (kn::orient3d(q[0], q[1], q[2], q[3]) <= 0)
        return fail(why, cname + " (" + name(cell.v[0]) + " " + name(cell.v[1]) + " " +
                             name(cell.v[2]) + " " + name(cell.v[3]) + ") is not positively oriented");
    }
  }
  if (infinite_cells != infinite_cell_count_) return fail(why, "infinite cell count is wrong");
  if (infinite_cell_ >= cells_.size() || !is_cell_alive(infinite_cell_) ||
      infinite_index(infinite_cell_) < 0)
    return fail(why, "the infinite vertex's cell does not contain it");

  // Local regularity: the vertex opposite each facet is not in conflict with the cell.
  for (CellId c = 0; c < cells_.size(); ++c) {
    if (!is_cell_alive(c)) continue;
    const Cell& cell = cells_[c];
    for (int i = 0; i < 4; ++i) {
      const CellId d = cell.n[i] >> 2;
      const PointId w = cells_[d].v[cell.n[i] & 3u];
      if (w == kInfiniteVertex) continue;
      const double* pw = points_[w].data();
      for (const PointId u : cell.v)
        if (u != kInfiniteVertex && points_[u].x == pw[0] && points_[u].y == pw[1] &&
            points_[u].z == pw[2])
          return fail(why, "vertices " + name(u) + " and " + name(w) + " have the same position");
      if (in_conflict(c, pw, kNoPoint))
        return fail(why, "facet " + std::to_string(i) + " of cell " + std::to_string(c) +
                             " is not locally regular: opposite vertex " + name(w) +
                             " is in conflict");
    }
  }

  // Vertex -> cell links and connected stars: the cells reached around v are all its cells.
  std::vector<CellId> star;
  for (PointId v = 0; v < np; ++v) {
    if (status_[v] != PointStatus::vertex) continue;
    const CellId c = point_cell_[v];
    if (c >= cells_.size() || !is_cell_alive(c) || index_of(c, v) < 0)
      return fail(why, "vertex " + name(v) + " points to a cell not incident to it");
    star.clear();
    incident_cells(v, star);
    if (star.size() != occurrences[v])
      return fail(why, "the star of vertex " + name(v) + " is not connected (" +
                           std::to_string(star.size()) + " of " + std::to_string(occurrences[v]) +
                           " cells reached)");
  }

  // Hidden points: listed once in the cell they point to, inside it, not in conflict with it.
  std::size_t listed = 0;
  if (hidden_storage_) {
    for (CellId c = 0; c < cells_.size(); ++c) {
      PointId h = cell_hidden_[c];
      if (h != kNoPoint && !is_cell_alive(c)) return fail(why, "a dead cell keeps hidden points");
      for (; h != kNoPoint; h = hidden_next_[h]) {
        if (h >= np || status_[h] != PointStatus::hidden || point_cell_[h] != c)
          return fail(why, "cell " + std::to_string(c) + " lists point " + name(h) +
                               " which is not hidden in it");
        if (++listed > hidden_count_) return fail(why, "hidden lists longer than the hidden count");
      }
    }
  }
  if (listed != hidden_count_) return fail(why, "some hidden point is in no cell's list");
  for (PointId h = 0; h < np; ++h) {
    if (status_[h] != PointStatus::hidden) continue;
    const CellId c = point_cell_[h];
    const Cell& cell = cells_[c];
    if (is_infinite(c)) return fail(why, "hidden point " + name(h) + " is in an infinite cell");
    const double* p = points_[h].data();
    const double* q[4];
    PointId at = kNoPoint;
    for (int k = 0; k < 4; ++k) {
      q[k] = points_[cell.v[k]].data();
      if (q[k][0] == p[0] && q[k][1] == p[1] && q[k][2] == p[2]) at = cell.v[k];
    }
    for (int i = 0; i < 4; ++i) {
      const double* saved = q[i];
      q[i] = p;
      const int o = kn::orient3d(q[0], q[1], q[2], q[3]);
      q[i] = saved;
      if (o < 0)
        return fail(why, "hidden point " + name(h) + " lies outside its cell " + std::to_string(c));
    }
    const bool conflict = at != kNoPoint ? kn::power_test(points_[at].data(), p) > 0
                                         : in_conflict(c, p, kNoPoint);
    if (conflict)
      return fail(why, "hidden point " + name(h) + " is in conflict with its cell " +
                           std::to_string(c) + " (it should be a vertex)");
  }
  return true;
}

}  // namespace delpsc::delaunay
