// RegularTriangulation::remove: a vertex's star re-triangulated from a small regular
// triangulation of its link (the make_hole / fill_hole scheme; regular_triangulation.h gives the
// literature), and the points it hid inserted again.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include <delpsc/kernel/predicates.h>

#include "regular_triangulation.h"
#include "regular_triangulation_scratch.h"
#include "tetrahedron_tables.h"

namespace delpsc::delaunay {

namespace kn = delpsc::kernel;
using namespace detail;

// ---------------------------------------------------------------------------------------------
// Removal
// ---------------------------------------------------------------------------------------------

bool RegularTriangulation::remove(PointId id, ChangeSet* changes, std::string* error) {
  if (changes) changes->clear();
  if (id >= points_.size()) {
    if (error) *error = "remove: no point with id " + std::to_string(id);
    return false;
  }
  switch (status_[id]) {
    case PointStatus::removed:
      if (error) *error = "remove: point " + std::to_string(id) + " was already removed";
      return false;
    case PointStatus::pending:
      remove_pending(id);
      return true;
    case PointStatus::hidden:
      detach_hidden(id);
      status_[id] = PointStatus::removed;
      return true;
    case PointStatus::vertex:
      break;
  }
  return remove_vertex(id, changes, error);
}

void RegularTriangulation::collect_star(PointId v, std::vector<CellId>& star) {
  Scratch& s = scratch();
  if (s.cell_mark.size() < cells_.size()) s.cell_mark.resize(cells_.size(), 0);
  std::uint8_t* mark = s.cell_mark.data();
  star.clear();
  const CellId first = incident_cell(v);
  mark[first] = kInConflict;
  star.push_back(first);
  for (std::size_t k = 0; k < star.size(); ++k) {
    const Cell& cell = cells_[star[k]];
    for (int i = 0; i < 4; ++i) {
      if (cell.v[i] == v) continue;  // the facet opposite v does not contain v
      const CellId y = cell.n[i] >> 2;
      if (mark[y]) continue;
      mark[y] = kInConflict;
      star.push_back(y);
    }
  }
  for (const CellId c : star) mark[c] = 0;
}

bool RegularTriangulation::remove_vertex(PointId v, ChangeSet* changes, std::string* error) {
  if (vertex_count_ <= 4) {
    if (error)
      *error = "remove: vertex " + std::to_string(v) +
               " is one of the last four vertices; the triangulation would drop below dimension 3";
    return false;
  }
  Scratch& s = scratch();
  collect_star(v, s.star);

  // The link vertices, numbered in order of discovery.
  s.link_points.clear();
  s.local_of.reset(64);
  for (const CellId c : s.star)
    for (const PointId w : cells_[c].v)
      if (w != v && w != kInfiniteVertex && !s.local_of.find(w)) {
        s.local_of.insert(w, static_cast<std::uint32_t>(s.link_points.size()));
        s.link_points.push_back(w);
      }
  if (!s.link) s.link = std::make_unique<RegularTriangulation>();
  RegularTriangulation& link = *s.link;
  link.clear();
  for (const PointId w : s.link_points) link.insert(points_[w]);

  // The link spans 3D unless v is a hull vertex whose neighbours are all coplanar.
  if (link.dimension() < 3) {
    if (!fill_flat_hole(v, error)) return false;
  } else {
    if (link.number_of_vertices() != s.link_points.size())
      throw std::logic_error("RegularTriangulation::remove: a link vertex is redundant in its link");
    fill_hole_from_link(v);
  }
  finish_removal(v, changes);
  return true;
}

// The cells of the regular triangulation of the remaining points that lie in the hole are the
// cells of the regular triangulation of the link vertices that lie in the hole (Devillers 2002;
// CGAL's Triangulation_3::remove_3D): they are regular for the link vertices, and the
// triangulation is unique under the perturbation. v's position is strictly inside the hole (or,
// for a hull vertex, beyond the link's hull facets that replace its star), so the link cell found
// by walking to it is a hole cell; the others are reached from it without crossing a hole
// boundary facet. Those facets are recognised by their oriented vertex triple, as v sees it.
void RegularTriangulation::fill_hole_from_link(PointId v) {
  Scratch& s = scratch();
  const RegularTriangulation& link = *s.link;
  constexpr std::uint32_t kLocalInfinite = kFacetKeyMask;
  if (s.link_points.size() >= kLocalInfinite)
    throw std::length_error("RegularTriangulation::remove: vertex degree too large");
  // Link vertex numbers are the link triangulation's point ids.
  auto local = [&](PointId w) -> std::uint32_t {
    return w == kInfiniteVertex ? kLocalInfinite : *s.local_of.find(w);
  };
  auto link_local = [&](PointId w) -> std::uint32_t { return w == kInfiniteVertex ? kLocalInfinite : w; };

  s.outer_of.reset(s.star.size());
  for (const CellId x : s.star) {
    const Cell& cell = cells_[x];
    const int k = index_of(x, v);
    const int* fs = kFacetSlots[k];
    s.outer_of.insert(facet_key(local(cell.v[fs[0]]), local(cell.v[fs[1]]), local(cell.v[fs[2]])),
                      cell.n[k]);
  }

  constexpr std::uint32_t kInside = 0xFFFFFFFFu;
  s.hole.clear();
  s.hole_outer.clear();
  s.new_of.assign(link.cell_capacity(), kNoCell);
  const CellId seed = link.walk(points_[v].data(), link.valid_start(kNoCell));
  s.new_of[seed] = 0;
  s.hole.push_back(seed);
  std::size_t boundary_found = 0;
  for (std::size_t h = 0; h < s.hole.size(); ++h) {
    const CellId t = s.hole[h];
    const auto& tv = link.cells_[t].v;
    for (int f = 0; f < 4; ++f) {
      const int* fs = kFacetSlots[f];
      const std::uint32_t* outer =
          s.outer_of.find(facet_key(link_local(tv[fs[0]]), link_local(tv[fs[1]]), link_local(tv[fs[2]])));
      if (outer) {
        s.hole_outer.push_back(*outer);
        ++boundary_found;
        continue;
      }
      s.hole_outer.push_back(kInside);
      const CellId u = link.neighbour(t, f);
      if (s.new_of[u] == kNoCell) {
        s.new_of[u] = static_cast<CellId>(s.hole.size());
        s.hole.push_back(u);
      }
    }
  }
  if (boundary_found != s.star.size())
    throw std::logic_error("RegularTriangulation::remove: the link triangulation does not fit the hole");

  for (CellId& n : s.new_of) n = kNoCell;
  for (const CellId t : s.hole) s.new_of[t] = new_cell();
  s.created.clear();
  for (std::size_t h = 0; h < s.hole.size(); ++h) {
    const CellId t = s.hole[h];
    const CellId n = s.new_of[t];
    Cell& cell = cells_[n];
    for (int k = 0; k < 4; ++k) {
      const PointId lv = link.vertex(t, k);
      cell.v[k] = lv == kInfiniteVertex ? kInfiniteVertex : s.link_points[lv];
    }
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t outer = s.hole_outer[4 * h + static_cast<std::size_t>(f)];
      if (outer != kInside) {
        cell.n[f] = outer;
        cells_[outer >> 2].n[outer & 3u] = make_link(n, f);
      } else {
        cell.n[f] = make_link(s.new_of[link.neighbour(t, f)], link.mirror_index(t, f));
      }
    }
    s.created.push_back(n);
  }
}

// v is a hull vertex whose finite neighbours are coplanar: its star is a cone from v over a flat
// region R of their plane, plus infinite cells. Without v, R becomes part of the hull: each finite
// star cell is replaced by the infinite cell on its base facet (v's slot given to the infinite
// vertex keeps the orientation convention, since v lay outside the new hull). If the far side of
// R is not triangulated, every remaining vertex is in that plane: refuse.
bool RegularTriangulation::fill_flat_hole(PointId v, std::string* error) {
  Scratch& s = scratch();
  for (const CellId x : s.star) {
    if (is_infinite(x)) continue;
    if (is_infinite(neighbour(x, index_of(x, v)))) {
      if (error)
        *error = "remove: removing vertex " + std::to_string(v) +
                 " would leave only coplanar vertices (dimension < 3)";
      return false;
    }
  }
  s.new_of_star.reset(s.star.size());
  s.created.clear();
  for (const CellId x : s.star)
    if (!is_infinite(x)) {
      const CellId n = new_cell();
      s.new_of_star.insert(x, n);
      s.created.push_back(n);
    }
  for (const CellId x : s.star) {
    if (is_infinite(x)) continue;
    const CellId n = *s.new_of_star.find(x);
    const Cell old = cells_[x];
    const int k = index_of(x, v);
    Cell& cell = cells_[n];
    cell.v = old.v;
    cell.v[k] = kInfiniteVertex;
    cell.n[k] = old.n[k];
    cells_[old.n[k] >> 2].n[old.n[k] & 3u] = make_link(n, k);
    for (int j = 0; j < 4; ++j) {
      if (j == k) continue;
      const CellId y = old.n[j] >> 2;
      if (const std::uint32_t* ny = s.new_of_star.find(y)) {
        cell.n[j] = make_link(*ny, static_cast<int>(old.n[j] & 3u));
      } else {
        // y = (inf, v, edge): the new cell meets the infinite cell beyond y's facet opposite v.
        const std::uint32_t outer = cells_[y].n[index_of(y, v)];
        cell.n[j] = outer;
        cells_[outer >> 2].n[outer & 3u] = make_link(n, j);
      }
    }
  }
  return true;
}

// Common end of a vertex removal: retire the star, register the new cells, forget v, and insert
// again the points the star's cells were hiding (CGAL's Regular_triangulation_3::remove does the
// same): each comes back as a vertex or is hidden again where it now lies. Points hidden in other
// cells stay hidden: those cells survive, and so does the reason they were not in conflict.
void RegularTriangulation::finish_removal(PointId v, ChangeSet* changes) {
  Scratch& s = scratch();
  s.reinsert.clear();
  for (const CellId x : s.star) {
    if (hidden_storage_) {
      for (PointId h = cell_hidden_[x]; h != kNoPoint; h = hidden_next_[h]) s.reinsert.push_back(h);
      cell_hidden_[x] = kNoPoint;
    }
    if (is_infinite(x)) --infinite_cell_count_;
    free_cell(x);
  }
  for (const CellId n : s.created)
    for (const PointId w : cells_[n].v) {
      if (w == kInfiniteVertex) {
        infinite_cell_ = n;
        ++infinite_cell_count_;
      } else {
        point_cell_[w] = n;
      }
    }
  status_[v] = PointStatus::removed;
  point_cell_[v] = kNoCell;
  --vertex_count_;
  last_cell_ = s.created.front();
  if (changes) {
    changes->destroyed.assign(s.star.begin(), s.star.end());
    changes->created.assign(s.created.begin(), s.created.end());
  }
  if (s.reinsert.empty()) return;

  // Re-insertions may destroy cells this removal just made; the report must be net. (Insertion
  // does not touch s.reinsert.)
  ChangeSet step;
  for (const PointId h : s.reinsert) {
    hidden_next_[h] = kNoPoint;
    status_[h] = PointStatus::pending;
    --hidden_count_;
    insert_in_3d(h, last_cell_, changes ? &step : nullptr, false);
    if (!changes) continue;
    for (const CellId d : step.destroyed) {
      auto it = std::find(changes->created.begin(), changes->created.end(), d);
      if (it != changes->created.end()) {
        *it = changes->created.back();
        changes->created.pop_back();
      } else {
        changes->destroyed.push_back(d);
      }
    }
    changes->created.insert(changes->created.end(), step.created.begin(), step.created.end());
    for (const PointId q : step.hidden) {
      auto it = std::find(changes->revealed.begin(), changes->revealed.end(), q);
      if (it != changes->revealed.end()) {
        *it = changes->revealed.back();
        changes->revealed.pop_back();
      } else if (q != h) {
        changes->hidden.push_back(q);
      }
    }
    if (status_[h] == PointStatus::vertex) changes->revealed.push_back(h);
    step.clear();
  }
}

}  // namespace delpsc::delaunay
