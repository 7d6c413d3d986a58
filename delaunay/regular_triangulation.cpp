// Incremental regular triangulation: insertion, location, hidden points (removal is in
// regular_triangulation_removal.cpp).
// The design and the literature are in regular_triangulation.h; this file says why each step is
// done the way it is.
#include "regular_triangulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <delpsc/kernel/predicates.h>

#include "regular_triangulation_scratch.h"
#include "spatial_sort.h"
#include "tetrahedron_tables.h"

namespace delpsc::delaunay {

namespace kn = delpsc::kernel;
using namespace detail;

namespace {

// Cavities with at most this many boundary vertices (all but pathological ones) glue their new
// cells through a direct (m x m) table; larger ones through a hash map.
constexpr std::size_t kDirectEdgeTable = 128;

// Point ids stay below 2^31, so the sentinels (infinite vertex, dead cell) are the only vertex
// values with the top bit set: one OR tells whether a live cell is infinite.
constexpr std::size_t kMaxPoints = std::size_t{1} << 31;
inline bool has_infinite_vertex(const std::array<PointId, 4>& v) {
  return ((v[0] | v[1] | v[2] | v[3]) >> 31) != 0;
}

bool same_position(const double* a, const double* b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

// Perturbed power test of p against a finite, positively oriented cell: +1 conflict, -1 not.
// The filtered test is inlined; only exact ties (degenerate inputs) pay for the tie-break call.
// Unweighted sets use insphere, whose filter is a little cheaper.
inline bool finite_cell_conflict(const double* const q[4], const double* p, bool weighted) {
  const int o = weighted ? kn::power_test(q[0], q[1], q[2], q[3], p) : kn::insphere(q[0], q[1], q[2], q[3], p);
  if (o != 0) return o > 0;
  return (weighted ? kn::power_test_perturbed(q[0], q[1], q[2], q[3], p)
                   : kn::insphere_perturbed(q[0], q[1], q[2], q[3], p)) > 0;
}

}  // namespace


RegularTriangulation::Scratch& RegularTriangulation::scratch() const {
  if (!scratch_) scratch_ = std::make_unique<Scratch>();
  return *scratch_;
}

// ---------------------------------------------------------------------------------------------
// Life cycle
// ---------------------------------------------------------------------------------------------

RegularTriangulation::RegularTriangulation() = default;
RegularTriangulation::~RegularTriangulation() = default;
RegularTriangulation::RegularTriangulation(RegularTriangulation&&) noexcept = default;
RegularTriangulation& RegularTriangulation::operator=(RegularTriangulation&&) noexcept = default;

RegularTriangulation::RegularTriangulation(const RegularTriangulation& o)
    : points_(o.points_),
      point_cell_(o.point_cell_),
      status_(o.status_),
      hidden_next_(o.hidden_next_),
      cell_hidden_(o.cell_hidden_),
      cells_(o.cells_),
      free_head_(o.free_head_),
      free_count_(o.free_count_),
      infinite_cell_(o.infinite_cell_),
      last_cell_(o.last_cell_),
      vertex_count_(o.vertex_count_),
      hidden_count_(o.hidden_count_),
      infinite_cell_count_(o.infinite_cell_count_),
      weighted_(o.weighted_),
      pending_(o.pending_),
      basis_(o.basis_),
      basis_size_(o.basis_size_),
      hidden_storage_(o.hidden_storage_) {}

RegularTriangulation& RegularTriangulation::operator=(const RegularTriangulation& o) {
  if (this != &o) *this = RegularTriangulation(o);
  return *this;
}

void RegularTriangulation::clear() {
  points_.clear();
  point_cell_.clear();
  status_.clear();
  hidden_next_.clear();
  cell_hidden_.clear();
  cells_.clear();
  free_head_ = kNoCell;
  free_count_ = 0;
  infinite_cell_ = kNoCell;
  last_cell_ = kNoCell;
  vertex_count_ = 0;
  hidden_count_ = 0;
  infinite_cell_count_ = 0;
  weighted_ = false;
  pending_.clear();
  basis_size_ = 0;
  hidden_storage_ = false;
  if (scratch_) {
    scratch_->cell_mark.clear();
    scratch_->local_id.clear();
  }
}

void RegularTriangulation::reserve(std::size_t points) {
  points_.reserve(points);
  point_cell_.reserve(points);
  status_.reserve(points);
  // A Delaunay triangulation of n uniform points has about 6.75 n cells.
  const std::size_t cells = points / 100 * 685 + 64;
  cells_.reserve(cells);
  scratch().cell_mark.reserve(cells);
}

std::size_t RegularTriangulation::memory_bytes() const {
  std::size_t bytes = sizeof(*this);
  bytes += points_.capacity() * sizeof(WeightedPoint) + point_cell_.capacity() * sizeof(CellId) +
           status_.capacity() * sizeof(PointStatus) + hidden_next_.capacity() * sizeof(PointId) +
           cell_hidden_.capacity() * sizeof(PointId) + cells_.capacity() * sizeof(Cell) +
           pending_.capacity() * sizeof(PointId);
  if (scratch_) {
    const Scratch& s = *scratch_;
    bytes += sizeof(Scratch) + s.cell_mark.capacity() +
             (s.local_id.capacity() + s.edge_table.capacity() + 4 * s.created_local.capacity() +
              s.hole_outer.capacity()) *
                 sizeof(std::uint32_t) +
             (s.conflict.capacity() + s.rejected.capacity() + s.created.capacity() +
              s.star.capacity() + s.hole.capacity() + s.new_of.capacity()) * sizeof(CellId) +
             s.boundary.capacity() * sizeof(Facet) +
             (s.interior.capacity() + s.relocate.capacity() + s.link_points.capacity() +
              s.reinsert.capacity() + s.boundary_vertices.capacity()) * sizeof(PointId) +
             s.edges.memory_bytes() + s.local_of.memory_bytes() + s.outer_of.memory_bytes() + s.new_of_star.memory_bytes();
    if (s.link) bytes += s.link->memory_bytes();
  }
  return bytes;
}

// ---------------------------------------------------------------------------------------------
// Cells, points, hidden lists
// ---------------------------------------------------------------------------------------------

CellId RegularTriangulation::append_cell() {
  // Neighbour links keep the cell id in 30 bits.
  if (cells_.size() >= (std::size_t{1} << 30))
    throw std::length_error("RegularTriangulation: more than 2^30 cells");
  // Grow by a quarter rather than doubling: the cell array is most of the memory.
  if (cells_.size() == cells_.capacity()) cells_.reserve(cells_.size() + cells_.size() / 4 + 1024);
  cells_.push_back(Cell{});
  if (hidden_storage_) cell_hidden_.push_back(kNoPoint);
  return static_cast<CellId>(cells_.size() - 1);
}

void RegularTriangulation::free_cell(CellId c) {
  cells_[c].v[0] = kDeadCell;
  cells_[c].n[0] = free_head_;
  free_head_ = c;
  ++free_count_;
}

PointId RegularTriangulation::append_point(const WeightedPoint& p) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(p.w))
    throw std::invalid_argument("RegularTriangulation::insert: non-finite coordinate or weight");
  if (points_.size() >= kMaxPoints)
    throw std::length_error("RegularTriangulation: more than 2^31 points");
  const auto id = static_cast<PointId>(points_.size());
  points_.push_back(p);
  point_cell_.push_back(kNoCell);
  status_.push_back(PointStatus::pending);
  if (hidden_storage_) hidden_next_.push_back(kNoPoint);
  weighted_ = weighted_ || p.w != 0;
  return id;
}

// Hidden points are rare for unweighted inputs (only exact duplicates), so their per-cell list
// heads cost nothing until the first one appears.
void RegularTriangulation::enable_hidden_storage() {
  if (hidden_storage_) return;
  hidden_storage_ = true;
  hidden_next_.assign(points_.size(), kNoPoint);
  cell_hidden_.assign(cells_.size(), kNoPoint);
}

void RegularTriangulation::attach_hidden(PointId id, CellId c) {
  enable_hidden_storage();
  if (status_[id] != PointStatus::hidden) {
    status_[id] = PointStatus::hidden;
    ++hidden_count_;
  }
  point_cell_[id] = c;
  hidden_next_[id] = cell_hidden_[c];
  cell_hidden_[c] = id;
}

void RegularTriangulation::detach_hidden(PointId id) {
  const CellId c = point_cell_[id];
  PointId* link = &cell_hidden_[c];
  while (*link != id) link = &hidden_next_[*link];
  *link = hidden_next_[id];
  hidden_next_[id] = kNoPoint;
  point_cell_[id] = kNoCell;
  --hidden_count_;
}

void RegularTriangulation::hidden_points(CellId c, std::vector<PointId>& out) const {
  if (!hidden_storage_) return;
  for (PointId h = cell_hidden_[c]; h != kNoPoint; h = hidden_next_[h]) out.push_back(h);
}

// ---------------------------------------------------------------------------------------------
// Pending points (dimension < 3)
// ---------------------------------------------------------------------------------------------

// True when `id` raises the affine dimension of the basis (for a full basis of three: when it is
// not coplanar with them, i.e. four affinely independent points are now known).
bool RegularTriangulation::extends_basis(PointId id) const {
  const double* p = points_[id].data();
  switch (basis_size_) {
    case 0:
      return true;
    case 1:
      return !same_position(points_[basis_[0]].data(), p);
    case 2:
      return !kn::collinear(points_[basis_[0]].data(), points_[basis_[1]].data(), p);
    default:
      return kn::orient3d(points_[basis_[0]].data(), points_[basis_[1]].data(),
                          points_[basis_[2]].data(), p) != 0;
  }
}

void RegularTriangulation::add_pending(PointId id, ChangeSet* changes) {
  status_[id] = PointStatus::pending;
  pending_.push_back(id);
  if (!extends_basis(id)) return;
  if (basis_size_ < 3) {
    basis_[basis_size_++] = id;
    return;
  }
  // Four affinely independent points: build the first tetrahedron, then insert the others in
  // their order of arrival (any order gives the same triangulation).
  std::vector<PointId> waiting;
  waiting.swap(pending_);
  basis_size_ = 0;
  build_first_tetrahedron(basis_[0], basis_[1], basis_[2], id);
  for (const PointId q : waiting)
    if (status_[q] == PointStatus::pending) insert_in_3d(q, kNoCell, nullptr, false);
  if (changes) {
    for (CellId c = 0; c < cells_.size(); ++c)
      if (is_cell_alive(c)) changes->created.push_back(c);
    for (const PointId q : waiting)
      if (status_[q] == PointStatus::hidden) changes->hidden.push_back(q);
  }
}

void RegularTriangulation::remove_pending(PointId id) {
  pending_.erase(std::find(pending_.begin(), pending_.end(), id));
  status_[id] = PointStatus::removed;
  // The basis may have lost a point: rebuild it from what remains (it cannot reach four).
  basis_size_ = 0;
  for (const PointId q : pending_)
    if (basis_size_ < 3 && extends_basis(q)) basis_[basis_size_++] = q;
}

void RegularTriangulation::build_first_tetrahedron(PointId a, PointId b, PointId c, PointId d) {
  if (kn::orient3d(points_[a].data(), points_[b].data(), points_[c].data(), points_[d].data()) < 0)
    std::swap(c, d);
  CellId ids[5];
  for (CellId& id : ids) id = new_cell();
  cells_[ids[0]].v = {a, b, c, d};
  // The infinite cell across facet i: the finite facet with its orientation reversed (two
  // vertices swapped), so that replacing the infinite vertex by a point outside gives a positive
  // orientation.
  for (int i = 0; i < 4; ++i) {
    auto v = cells_[ids[0]].v;
    v[i] = kInfiniteVertex;
    std::swap(v[(i + 1) & 3], v[(i + 2) & 3]);
    cells_[ids[1 + i]].v = v;
  }
  // Finite cell facet i <-> infinite cell i facet i (the infinite vertex is opposite it there).
  // Infinite cells i and j (i != j) share the facet made of the infinite vertex and the two
  // finite vertices other than v_i and v_j; in cell i it is opposite v_j, in cell j opposite v_i.
  const auto& f = cells_[ids[0]].v;
  for (int i = 0; i < 4; ++i) {
    cells_[ids[0]].n[i] = make_link(ids[1 + i], i);
    cells_[ids[1 + i]].n[i] = make_link(ids[0], i);
    for (int j = 0; j < 4; ++j) {
      if (j == i) continue;
      const int in_i = index_of(ids[1 + i], f[j]);  // v_j's slot in infinite cell i
      const int in_j = index_of(ids[1 + j], f[i]);  // v_i's slot in infinite cell j
      cells_[ids[1 + i]].n[in_i] = make_link(ids[1 + j], in_j);
    }
  }
  for (const PointId p : {a, b, c, d}) {
    status_[p] = PointStatus::vertex;
    point_cell_[p] = ids[0];
  }
  vertex_count_ = 4;
  infinite_cell_ = ids[1];
  infinite_cell_count_ = 4;
  last_cell_ = ids[0];
}

// ---------------------------------------------------------------------------------------------
// Insertion
// ---------------------------------------------------------------------------------------------

PointId RegularTriangulation::insert(const WeightedPoint& p, ChangeSet* changes, CellId hint) {
  if (changes) changes->clear();
  const PointId id = append_point(p);
  if (dimension() < 3)
    add_pending(id, changes);
  else
    insert_in_3d(id, hint, changes, true);  // one point, wherever the caller is refining
  return id;
}

PointId RegularTriangulation::insert(std::span<const WeightedPoint> points, std::vector<PointId>* ids,
                                     const std::function<void(std::size_t inserted)>& progress, std::size_t lead) {
  if (lead > points.size()) throw std::invalid_argument("RegularTriangulation::insert: lead exceeds the batch");
  const auto first = static_cast<PointId>(points_.size());
  // Validate the whole batch first, so that a bad point leaves the triangulation unchanged.
  for (const WeightedPoint& p : points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(p.w))
      throw std::invalid_argument("RegularTriangulation::insert: non-finite coordinate or weight");
  if (points_.size() + points.size() > kMaxPoints)
    throw std::length_error("RegularTriangulation: more than 2^31 points");
  reserve(points_.size() + points.size());
  std::vector<std::uint32_t> order;
  brio_order(points, order);
  if (ids) ids->resize(points.size());
  std::vector<PointId> leading;  // the lead points' ids: inserted first, numbered in place
  for (std::size_t k = 0; k < order.size(); ++k) {
    append_point(points[order[k]]);
    const PointId id = first + static_cast<PointId>(k);
    if (ids) (*ids)[order[k]] = id;
    if (order[k] < lead) leading.push_back(id);
  }
  std::size_t done = 0;
  const auto insert_one = [&](PointId id) {
    if (dimension() < 3)
      add_pending(id, nullptr);
    else
      insert_in_3d(id, kNoCell, nullptr, false);
    if (progress && (++done & 0xffff) == 0) progress(done);
  };
  for (const PointId id : leading) insert_one(id);
  std::size_t next_lead = 0;
  for (PointId id = first; id < points_.size(); ++id) {
    if (next_lead < leading.size() && leading[next_lead] == id) {
      ++next_lead;
      continue;
    }
    insert_one(id);
  }
  return first;
}

CellId RegularTriangulation::valid_start(CellId hint) const {
  if (hint < cells_.size() && is_cell_alive(hint)) return hint;
  if (last_cell_ < cells_.size() && is_cell_alive(last_cell_)) return last_cell_;
  return infinite_cell_;
}

// Remembering stochastic visibility walk (Devillers, Pion & Teillaud 2002): leave the cell
// through a facet that has p strictly on its other side, never back through the facet we came
// in by, trying the facets from a random first one. The randomness matters: in a regular (not
// Delaunay) triangulation the deterministic visibility walk can cycle. Only orient3d decides, so
// the result is exact: a finite cell whose closure contains p, or an infinite cell whose finite
// facet p sees strictly from outside.
CellId RegularTriangulation::walk(const double* p, CellId c) const {
  CellId previous = kNoCell;
  std::uint32_t random = 0x9e3779b9u ^ c;
  for (;;) {
    const Cell& cell = cells_[c];
    const double* q[4];
    int infinite = -1;
    for (int k = 0; k < 4; ++k) {
      if (cell.v[k] == kInfiniteVertex) {
        infinite = k;
        q[k] = p;
      } else {
        q[k] = points_[cell.v[k]].data();
      }
    }
    if (infinite >= 0) {
      // We only enter an infinite cell when p is strictly beyond its finite facet; a start
      // there may not be, then step into the hull.
      if (kn::orient3d(q[0], q[1], q[2], q[3]) > 0) return c;
      previous = c;
      c = cell.n[infinite] >> 2;
      continue;
    }
    random ^= random << 13;
    random ^= random >> 17;
    random ^= random << 5;
    const int first = static_cast<int>(random & 3u);
    CellId next = kNoCell;
    for (int t = 0; t < 4; ++t) {
      const int i = (first + t) & 3;
      const CellId neighbour = cell.n[i] >> 2;
      if (neighbour == previous) continue;
      const double* saved = q[i];
      q[i] = p;
      const int o = kn::orient3d(q[0], q[1], q[2], q[3]);
      q[i] = saved;
      if (o < 0) {
        next = neighbour;
        break;
      }
    }
    if (next == kNoCell) return c;
    previous = c;
    c = next;
  }
}

CellId RegularTriangulation::locate(const Vec3& p, CellId hint) const {
  if (dimension() < 3) return kNoCell;
  return walk(p.data(), valid_start(hint));
}

// The conflict test of CGAL's Regular_triangulation_3::side_of_power_sphere(c, p, perturb=true):
// for a finite cell the perturbed power test; for an infinite cell, p must lie strictly outside
// its hull facet, or in the facet's plane and in conflict with the facet's power circle
// (perturbed). `replaced` is a vertex at p's position that p outweighs: every cell incident to it
// is in conflict (the power product of p with their orthosphere is w_replaced - w_p < 0), and
// the perturbed test does not apply to coincident points.
bool RegularTriangulation::in_conflict(CellId c, const double* p, PointId replaced) const {
  const Cell& cell = cells_[c];
  const double* q[4];
  int infinite = -1;
  for (int k = 0; k < 4; ++k) {
    const PointId v = cell.v[k];
    if (v == replaced) return true;
    if (v == kInfiniteVertex) {
      infinite = k;
      q[k] = p;
    } else {
      q[k] = points_[v].data();
    }
  }
  if (infinite < 0) return finite_cell_conflict(q, p, weighted_);
  const int o = kn::orient3d(q[0], q[1], q[2], q[3]);
  if (o != 0) return o > 0;
  const int* f = kFacetSlots[infinite];
  return kn::power_circle_side_perturbed(q[f[0]], q[f[1]], q[f[2]], p) > 0;
}

void RegularTriangulation::insert_in_3d(PointId id, CellId hint, ChangeSet* changes, bool prefetch) {
  const double* p = points_[id].data();
  const CellId c = walk(p, valid_start(hint));
  last_cell_ = c;
  PointId replaced = kNoPoint;
  if (!is_infinite(c)) {
    // p in the closed cell c: if it sits on a vertex, that vertex is one of c's.
    for (const PointId u : cells_[c].v) {
      if (!same_position(points_[u].data(), p)) continue;
      // Two weighted points at one position: the heavier one wins; on a tie the vertex stays.
      if (kn::power_test(points_[u].data(), p) > 0) {
        replaced = u;
        break;
      }
      attach_hidden(id, c);
      if (changes) changes->hidden.push_back(id);
      return;
    }
  }
  // The regular triangulation gains p as a vertex iff p conflicts with the cell containing it;
  // otherwise p is redundant: its lifted point lies above the lower hull.
  if (replaced == kNoPoint && !in_conflict(c, p, kNoPoint)) {
    attach_hidden(id, c);
    if (changes) changes->hidden.push_back(id);
    return;
  }
  find_conflicts(c, p, replaced, prefetch);
  star_cavity(id, changes);
}

// Breadth-first search of the conflict region from a cell in conflict. The region is connected
// (its union is star-shaped from p: it is exactly the union of the cells that will be incident to
// p), so the search finds all of it; every facet between a conflict cell and a non-conflict cell
// is a boundary facet of the cavity. Non-conflict cells are marked too, so that each is tested once.
void RegularTriangulation::find_conflicts(CellId start, const double* p, PointId replaced, bool prefetch) {
  Scratch& s = scratch();
  if (s.cell_mark.size() < cells_.size()) s.cell_mark.resize(cells_.size(), 0);
  // Raw pointers and local counts: the byte-sized marks may alias anything, so going through the
  // vectors would reload their internals after every mark store.
  std::uint8_t* const mark = s.cell_mark.data();
  const Cell* const cells = cells_.data();
  const WeightedPoint* const points = points_.data();
  const bool weighted = weighted_;
  s.conflict.clear();
  s.rejected.clear();
  s.boundary.clear();
  CellId* conflict = s.conflict.reserve_more(64);
  CellId* rejected = s.rejected.reserve_more(64);
  Facet* boundary = s.boundary.reserve_more(64);
  std::size_t nc = 0, nr = 0, nf = 0;
  mark[start] = kInConflict;
  conflict[nc++] = start;
  for (std::size_t k = 0; k < nc; ++k) {
    const CellId x = conflict[k];
    if (nc + 4 > s.conflict.capacity()) {
      s.conflict.set_size(nc);
      conflict = s.conflict.reserve_more(4);
    }
    if (nr + 4 > s.rejected.capacity()) {
      s.rejected.set_size(nr);
      rejected = s.rejected.reserve_more(4);
    }
    if (nf + 4 > s.boundary.capacity()) {
      s.boundary.set_size(nf);
      boundary = s.boundary.reserve_more(4);
    }
    // The four neighbours' cells and marks, then their points, are fetched together: in mesh
    // refinement the cells of a cavity lie scattered in memory and each first touch is a cache
    // miss; issued at once they overlap instead of following one another (mesher -4 to -5%). A
    // batch in spatial order finds them in cache, and there the prefetches cost ~5%.
    if (prefetch) {
      for (int i = 0; i < 4; ++i) {
        const CellId y = cells[x].n[i] >> 2;
        __builtin_prefetch(&cells[y]);
        __builtin_prefetch(&mark[y]);
      }
      for (int i = 0; i < 4; ++i) {
        const Cell& cy = cells[cells[x].n[i] >> 2];
        for (int j = 0; j < 4; ++j)
          if (cy.v[j] != kInfiniteVertex) __builtin_prefetch(&points[cy.v[j]]);
      }
    }
    // One data-dependent branch per neighbour (untested or not); the lists grow branch-free.
    // The marks and the test outcomes are close to random, and mispredicted branches cost more
    // here than the predicates' arithmetic.
    for (int i = 0; i < 4; ++i) {
      const CellId y = cells[x].n[i] >> 2;
      std::uint8_t m = mark[y];
      if (m == 0) {
        // Inline fast path for the common case: a finite cell, no replaced vertex.
        const Cell& cy = cells[y];
        bool in;
        if (replaced != kNoPoint) {
          in = in_conflict(y, p, replaced);
        } else if (!has_infinite_vertex(cy.v)) {
          const double* q[4] = {points[cy.v[0]].data(), points[cy.v[1]].data(),
                                points[cy.v[2]].data(), points[cy.v[3]].data()};
          in = finite_cell_conflict(q, p, weighted);
        } else {
          // Infinite cell: p strictly beyond its hull facet decides; a tie (p in the facet's
          // plane) goes to in_conflict's power-circle rule.
          const double* q[4];
          for (int j = 0; j < 4; ++j) q[j] = cy.v[j] == kInfiniteVertex ? p : points[cy.v[j]].data();
          const int o = kn::orient3d(q[0], q[1], q[2], q[3]);
          in = o != 0 ? o > 0 : in_conflict(y, p, replaced);
        }
        m = in ? kInConflict : kNotInConflict;
        mark[y] = m;
        conflict[nc] = y;
        nc += in;
        rejected[nr] = y;
        nr += !in;
      }
      boundary[nf] = {x, i};
      nf += m == kNotInConflict;
    }
  }
  s.conflict.set_size(nc);
  s.rejected.set_size(nr);
  s.boundary.set_size(nf);
}

// Bowyer–Watson step: replace the conflict region by the cells joining p to its boundary facets.
// A new cell keeps the boundary facet's conflict cell's vertex order with p in the slot of the
// vertex opposite the facet (p sees the facet from the same side), so it is positively oriented
// and its facet index toward the outside is unchanged. The new cells are glued to each other
// along the boundary edges: the new facet through p and boundary edge (a, b), oriented as seen
// from its cell, reads (p, a, b) in one cell and (p, b, a) in the other. The boundary vertices
// are numbered 1, 2, ... (the infinite vertex 0) and a first pass files every new facet under its
// directed edge in a small square table; a second pass reads the reversed edge. No search, no
// branch on "found" (Marot, Pellerin & Remacle, "One machine, one minute, three billion
// tetrahedra", IJNME 117, 2019, use the same idea).
void RegularTriangulation::star_cavity(PointId id, ChangeSet* changes) {
  Scratch& s = scratch();

  // All new cells first (one per boundary facet), so that no reallocation moves cells_ below.
  const std::size_t nb = s.boundary.size();
  s.created.resize(nb);
  for (std::size_t t = 0; t < nb; ++t) s.created[t] = new_cell();
  Cell* const cells = cells_.data();
  CellId* const point_cell = point_cell_.data();
  const Facet* const boundary = s.boundary.data();
  const CellId* const created = s.created.data();

  // Hidden points of the doomed cells, taken before their slots are recycled.
  s.relocate.clear();
  if (hidden_storage_)
    for (const CellId x : s.conflict) {
      for (PointId h = cell_hidden_[x]; h != kNoPoint; h = hidden_next_[h]) s.relocate.push_back(h);
      cell_hidden_[x] = kNoPoint;
    }

  // The cavity boundary is a triangulated sphere: V = F/2 + 2 vertices, so local numbers (the
  // infinite vertex 0, the others 1, 2, ... on first sight) stay below F/2 + 3.
  const std::size_t m = nb / 2 + 3;
  const bool direct = m <= kDirectEdgeTable;
  if (direct) {
    if (s.edge_table.size() < m * m) s.edge_table.resize(m * m);
  } else {
    s.edges.reset(2 * nb);
  }
  if (s.local_id.size() < points_.size()) s.local_id.resize(points_.size(), 0);
  std::uint32_t* const local = s.local_id.data();
  std::uint32_t* const table = s.edge_table.data();
  s.created_local.resize(nb);
  auto* const lids = s.created_local.data();
  s.boundary_vertices.clear();
  point_cell[id] = created[0];
  std::size_t infinite_created = 0;

  // Pass 1: the star of p, glued to the outside; every inner facet filed under its edge. Each
  // boundary vertex gets, as incident cell, the first new cell it is seen in (its old cells may
  // all be destroyed).
  for (std::size_t t = 0; t < nb; ++t) {
    const Cell& old = cells[boundary[t].cell];
    const int i = boundary[t].index;
    const CellId n = created[t];
    auto& lid = lids[t];
    lid[i] = 0;
    for (const int k : kFacetSlots[i]) {
      const PointId v = old.v[k];
      if (v == kInfiniteVertex) {
        lid[k] = 0;
        continue;
      }
      if (local[v] == 0) {
        s.boundary_vertices.push_back(v);
        if (s.boundary_vertices.size() >= m)
          throw std::logic_error("RegularTriangulation: cavity boundary is not a sphere");
        local[v] = static_cast<std::uint32_t>(s.boundary_vertices.size());
        point_cell[v] = n;
      }
      lid[k] = local[v];
    }
    Cell& cell = cells[n];
    cell.v = old.v;
    cell.v[i] = id;
    const std::uint32_t outer = old.n[i];
    cell.n[i] = outer;
    cells[outer >> 2].n[outer & 3u] = make_link(n, i);
    if (has_infinite_vertex(cell.v)) {
      infinite_cell_ = n;
      ++infinite_created;
    }
    for (const auto& [j, ka, kb] : kInnerFacets[i]) {
      if (direct)
        table[lid[ka] * m + lid[kb]] = make_link(n, j);
      else
        s.edges.insert(edge_key(lid[ka], lid[kb]), make_link(n, j));
    }
  }
  infinite_cell_count_ += infinite_created;
  // Pass 2: each inner facet meets the facet filed under the reversed edge.
  for (std::size_t t = 0; t < nb; ++t) {
    Cell& cell = cells[created[t]];
    const auto& lid = lids[t];
    for (const auto& [j, ka, kb] : kInnerFacets[boundary[t].index])
      cell.n[j] = direct ? table[lid[kb] * m + lid[ka]] : *s.edges.find(edge_key(lid[kb], lid[ka]));
  }

  // Vertices all of whose cells are in conflict (none on the cavity boundary) become redundant.
  // Only weights can cause that (unweighted points are never redundant, duplicates aside), so
  // unweighted inputs skip the search. The conflict cells are still intact here.
  constexpr std::uint32_t kInteriorVertex = 0xFFFFFFFFu;
  s.interior.clear();
  if (weighted_)
    for (const CellId x : s.conflict)
      for (const PointId v : cells[x].v)
        if (v != kInfiniteVertex && local[v] == 0) {
          local[v] = kInteriorVertex;
          s.interior.push_back(v);
        }
  for (const PointId v : s.boundary_vertices) local[v] = 0;
  for (const PointId v : s.interior) local[v] = 0;

  std::uint8_t* mark = s.cell_mark.data();
  for (const CellId x : s.conflict) {
    if (has_infinite_vertex(cells_[x].v)) --infinite_cell_count_;
    free_cell(x);
    mark[x] = 0;
  }
  for (const CellId x : s.rejected) mark[x] = 0;

  status_[id] = PointStatus::vertex;
  ++vertex_count_;
  last_cell_ = s.created.front();

  // Redundant vertices join the hidden points. Every displaced hidden point stays hidden (adding
  // a point only makes more points redundant) and lies in the union of the new cells, so a walk
  // from one of them finds its new cell.
  for (const PointId v : s.interior) {
    --vertex_count_;
    status_[v] = PointStatus::pending;  // attach_hidden counts it as newly hidden
    s.relocate.push_back(v);
  }
  for (const PointId h : s.relocate) attach_hidden(h, walk(points_[h].data(), last_cell_));

  if (changes) {
    changes->created.insert(changes->created.end(), s.created.begin(), s.created.end());
    changes->replaced.insert(changes->replaced.end(), s.boundary.begin(), s.boundary.end());
    changes->destroyed.insert(changes->destroyed.end(), s.conflict.begin(), s.conflict.end());
    changes->hidden.insert(changes->hidden.end(), s.interior.begin(), s.interior.end());
  }
}

}  // namespace delpsc::delaunay
