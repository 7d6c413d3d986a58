// Incremental 3D regular (weighted Delaunay) triangulation with vertex removal.
//
// What it computes. Given weighted points p_i = (x_i, w_i), w_i = r_i^2 (w = 0 for ordinary points),
// the regular triangulation is the projection of the lower convex hull of the lifted points
// (x_i, |x_i|^2 - w_i) (Edelsbrunner & Shah, "Incremental topological flipping works for regular
// triangulations", Algorithmica 15, 1996). A point whose lifted image lies above that hull is
// *redundant*: it is kept as a *hidden* point, never a vertex. Ties (five co-spherical points, four
// co-circular points on the hull, ...) are broken by the symbolic perturbation of Devillers &
// Teillaud (CGTA 44(3), 2011) implemented by kernel/predicates.h. That perturbation depends only on
// the points, so the triangulation of a point set is unique: after any sequence of insertions and
// removals the cells are exactly those a construction from scratch would give, and exactly CGAL's
// Regular_triangulation_3 (Epick) on the same points.
//
// How. Insertion is Bowyer–Watson: locate the point by a remembering stochastic walk (Devillers,
// Pion & Teillaud, "Walking in a triangulation", 2002), grow the conflict region by a breadth-first
// search with the perturbed power test, and star the cavity from the new point. Vertices whose
// every incident cell is in conflict become hidden. Removal fills the star of the vertex with the
// cells of a small regular triangulation of its link that lie inside the hole (the make_hole /
// fill_hole scheme of CGAL's Triangulation_3::remove, after Devillers, "On deletion in Delaunay
// triangulations", IJCGA 12(3), 2002), then re-inserts the points the vertex was hiding.
// Batches are spatially sorted first (BRIO rounds + Hilbert order, spatial_sort.h).
//
// Convex hull. An infinite vertex (kInfiniteVertex, not a point) is joined to every hull facet, so
// every facet has two cells and every point of space is in some cell. There are no bounding-box
// vertices. Orientation convention (CGAL's): every finite cell (v0,v1,v2,v3) has
// orient3d(v0,v1,v2,v3) > 0; an infinite cell becomes positively oriented when its infinite vertex
// is replaced by any point strictly outside the hull beyond its finite facet.
//
// Degenerate starts. Until four affinely independent points have been inserted there are no cells:
// the points are *pending* and dimension() reports the affine dimension of the pending points
// (-1 empty, 0 one position, 1 collinear, 2 coplanar). The first time a point makes them span 3D,
// the first tetrahedron is built and the pending points are inserted. A set that stays coplanar
// forever is therefore reported with dimension() < 3, its points pending and no cells.
//
// Identity. Every inserted point gets a PointId: the number of points inserted before it (a batch
// is inserted, hence numbered, in spatial order; insert() reports each input's id). A vertex is
// named by its PointId. A PointId keeps its meaning forever; a removed point's id is not reused.
//
// Memory. Flat arrays with 32-bit indices: a cell is 4 vertex ids + 4 neighbour links (32 bytes);
// a neighbour link (cell << 2 | j) also gives the index j of the facet as seen from the neighbour,
// so the mirror facet is known without search. Dead cells go to a free list. Per point: the
// WeightedPoint (32 bytes), one incident cell, one status byte, a 4-byte scratch number, and,
// once some point is hidden, a link in its cell's list of hidden points; per cell one scratch
// mark byte (and a hidden-list head once some point is hidden). With ~6.75 cells per point for
// uniform points that is ~265 bytes per vertex, 216 of them the cells.
// Limits: fewer than 2^31 points, fewer than 2^30 cells.
//
// Cost (measured on 10^6 uniform points, 2-core shared machine, see BENCHMARKS.md for the formal
// numbers): batch insertion ~4 us per point (CGAL's Delaunay_triangulation_3 ~4.9 us in the same
// conditions); per insertion about 46 filtered power tests, 12 orient3d, 28 new cells. Removal
// ~20 us per vertex, most of it building the link triangulation (~15 points).
//
// Not thread-safe: one triangulation per thread. Const queries share nothing mutable, so they may
// run concurrently when no thread modifies the triangulation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <delpsc/kernel/large_array.h>

#include <delpsc/kernel/point.h>

namespace delpsc::delaunay {

using PointId = std::uint32_t;  ///< index of an inserted point; also names the vertex it becomes
using CellId = std::uint32_t;   ///< index of a cell slot (some slots are dead: see is_cell_alive)

inline constexpr PointId kInfiniteVertex = 0xFFFFFFFFu;  ///< the vertex "at infinity"
inline constexpr PointId kNoPoint = 0xFFFFFFFEu;         ///< "no point" (e.g. a hidden insertion)
inline constexpr CellId kNoCell = 0xFFFFFFFFu;           ///< "no cell"

/// What became of an inserted point.
enum class PointStatus : std::uint8_t {
  pending,  ///< dimension() < 3: stored, waiting for four affinely independent points
  vertex,   ///< a vertex of the triangulation
  hidden,   ///< redundant: in conflict with no cell; attached to the cell that contains it
  removed,  ///< removed by remove(); the id is never reused
};

/// A facet: the face of cell `cell` opposite its vertex number `index` (0..3).
struct Facet {
  CellId cell = kNoCell;
  int index = 0;
  friend bool operator==(const Facet&, const Facet&) = default;
};

/// The Voronoi (power diagram) edge dual to a finite facet: the segment between the orthocentres
/// of its two cells, or, for a hull facet, the ray from the orthocentre of its finite cell in the
/// direction of the facet's outward normal (`direction`, not normalised).
struct VoronoiEdge {
  Vec3 source = Vec3::Zero();     ///< orthocentre of the finite cell (of facet.cell if both finite)
  Vec3 target = Vec3::Zero();     ///< orthocentre of the other cell (segment only)
  Vec3 direction = Vec3::Zero();  ///< outward direction of the ray (ray only)
  bool is_ray = false;
};

/// The changes one insert() or remove() made, for a client (the mesher) that keeps data on cells.
/// `destroyed`: cells alive before the call that are gone; `created`: cells alive after the call
/// that did not exist before. Cell slots are recycled, so one id may appear in both lists: the old
/// cell died and a new one took its slot — process `destroyed` before `created`.
/// `hidden`: points that became hidden (possibly the inserted point itself, or vertices it made
/// redundant); `revealed`: hidden points that became vertices (after a removal).
/// `replaced`: after an insertion into a triangulation already of dimension 3, one per created
/// cell (same order): the destroyed cell's facet that created[k]'s facet opposite the new point
/// replaces - the same triangle, seen from the conflict cell it bounded - so a client can read
/// what it kept on that facet from the destroyed cell (whose data it is about to drop anyway)
/// instead of from the surviving neighbour. Empty otherwise.
struct ChangeSet {
  std::vector<CellId> created;
  std::vector<CellId> destroyed;
  std::vector<PointId> hidden;
  std::vector<PointId> revealed;
  std::vector<Facet> replaced;
  void clear() {
    created.clear();
    destroyed.clear();
    hidden.clear();
    revealed.clear();
    replaced.clear();
  }
};

/// Defined only by the tests of is_valid(), which corrupt a triangulation on purpose to show that
/// the checker finds each kind of damage; no library code uses it.
struct RegularTriangulationTestAccess;

class RegularTriangulation {
 public:
  RegularTriangulation();
  ~RegularTriangulation();
  RegularTriangulation(const RegularTriangulation&);  ///< copies the triangulation, not scratch
  RegularTriangulation& operator=(const RegularTriangulation&);
  RegularTriangulation(RegularTriangulation&&) noexcept;
  RegularTriangulation& operator=(RegularTriangulation&&) noexcept;

  /// Removes everything (points included); keeps the allocated memory.
  void clear();
  /// Reserves room for `points` points in total (and ~6.85 cells per point). Optional: the cell
  /// array otherwise grows by 25% steps.
  void reserve(std::size_t points);

  // -------------------------------------------------------------------------------------------
  // Modification
  // -------------------------------------------------------------------------------------------

  /// Inserts one weighted point (w = r^2 >= 0 expected but not required; finite coordinates in the
  /// range of kernel/predicates.h; std::invalid_argument for NaN or infinity). Returns its PointId; status(id) then tells whether it became a
  /// vertex, is hidden or is pending. A point at the position of an existing vertex v replaces v
  /// (v becomes hidden) if its weight is larger, and is hidden otherwise (equal weights: the new
  /// point is hidden; CGAL drops it instead). `hint`: a cell near the point (e.g.
  /// incident_cell(v) of a nearby vertex); by default the last cell touched. `changes`, if given,
  /// is cleared and filled. Expected O(1) amortised for spatially coherent insertions (plus the
  /// walk), O(size of the conflict region) otherwise.
  PointId insert(const WeightedPoint& p, ChangeSet* changes = nullptr, CellId hint = kNoCell);

  /// Inserts a batch in BRIO + Hilbert order (spatial_sort.h). The points are stored, and
  /// numbered, in that order: they get the ids first, first + 1, ..., first + n - 1 (first =
  /// number_of_points() before the call, which is returned), and `ids`, if given, receives for
  /// each k the PointId of points[k]. Storing them in spatial order is what makes the insertion
  /// fast: a cell's vertices are then close in memory. No change report (a mesher inserting one
  /// point at a time uses insert()). Expected O(n log n). The whole batch is validated first: on
  /// std::invalid_argument nothing was inserted. `progress`, if given, is called with the number
  /// of points inserted so far every 2^16 points (a progress line for big batches).
  /// `lead`: the first `lead` points of the span (a far bounding frame, say) are inserted before
  /// all the others, though numbered in the spatial order all the same: a frame left to that
  /// order lands anywhere in it, and a corner inserted late replaces every hull cell it sees
  /// (thousands when the hull is a sampled surface). std::invalid_argument if lead > n.
  PointId insert(std::span<const WeightedPoint> points, std::vector<PointId>* ids = nullptr,
                 const std::function<void(std::size_t inserted)>& progress = {}, std::size_t lead = 0);

  /// Removes a point: a vertex (its star is re-triangulated and the points it hid come back where
  /// they should), a hidden point (simply forgotten) or a pending point. Returns false and leaves
  /// the triangulation unchanged, with a reason in *error, if `id` is not a live point or if
  /// removing the vertex would leave fewer than four affinely independent vertices (the
  /// triangulation would drop below dimension 3). `changes`, if given, is cleared and filled.
  /// Expected O(degree^2) for a vertex (a small triangulation of its ~15-30 link vertices).
  bool remove(PointId id, ChangeSet* changes = nullptr, std::string* error = nullptr);

  // -------------------------------------------------------------------------------------------
  // Sizes and status
  // -------------------------------------------------------------------------------------------

  /// 3 once cells exist; otherwise the affine dimension of the pending points (-1 if none).
  int dimension() const { return cells_.size() > free_count_ ? 3 : pending_dimension(); }
  std::size_t number_of_points() const { return points_.size(); }  ///< the next PointId
  std::size_t number_of_vertices() const { return vertex_count_; }  ///< finite vertices
  std::size_t number_of_hidden() const { return hidden_count_; }
  std::size_t number_of_cells() const { return cells_.size() - free_count_; }  ///< with infinite
  std::size_t number_of_finite_cells() const { return number_of_cells() - infinite_cell_count_; }
  /// Every CellId is < cell_capacity(); use is_cell_alive() to skip dead slots.
  std::size_t cell_capacity() const { return cells_.size(); }
  /// Bytes held by the triangulation's arrays (capacity, scratch included), for memory reports.
  std::size_t memory_bytes() const;

  PointStatus status(PointId id) const { return status_[id]; }
  /// Precondition: id < number_of_points() (not kInfiniteVertex).
  const WeightedPoint& point(PointId id) const { return points_[id]; }
  /// Points hidden in cell c (attached to it because c contains them).
  void hidden_points(CellId c, std::vector<PointId>& out) const;

  // -------------------------------------------------------------------------------------------
  // Combinatorics (dimension() == 3)
  // -------------------------------------------------------------------------------------------

  bool is_cell_alive(CellId c) const { return cells_[c].v[0] != kDeadCell; }
  /// Vertex i (0..3) of cell c; may be kInfiniteVertex.
  PointId vertex(CellId c, int i) const { return cells_[c].v[i]; }
  /// The cell across the facet opposite vertex i.
  CellId neighbour(CellId c, int i) const { return cells_[c].n[i] >> 2; }
  /// Index of that facet in neighbour(c, i).
  int mirror_index(CellId c, int i) const { return static_cast<int>(cells_[c].n[i] & 3u); }
  Facet mirror_facet(Facet f) const { return {neighbour(f.cell, f.index), mirror_index(f.cell, f.index)}; }
  /// Slot of v in c, -1 if absent.
  int index_of(CellId c, PointId v) const {
    const auto& cv = cells_[c].v;
    return cv[0] == v ? 0 : cv[1] == v ? 1 : cv[2] == v ? 2 : cv[3] == v ? 3 : -1;
  }
  /// Slot of the infinite vertex, -1 if c is finite.
  int infinite_index(CellId c) const { return index_of(c, kInfiniteVertex); }
  bool is_infinite(CellId c) const { return infinite_index(c) >= 0; }
  /// True iff the facet contains the infinite vertex.
  bool is_infinite(Facet f) const {
    const int k = infinite_index(f.cell);
    return k >= 0 && k != f.index;
  }
  /// The three vertices of facet (c, i), ordered so that orient3d(a, b, c, vertex(c, i)) > 0 for a
  /// finite cell (they appear counterclockwise seen from outside the cell).
  std::array<PointId, 3> facet_vertices(Facet f) const;

  /// A cell incident to vertex v (kInfiniteVertex allowed); for a hidden point, the cell it is
  /// attached to; kNoCell for pending and removed points.
  CellId incident_cell(PointId v) const {
    return v == kInfiniteVertex ? infinite_cell_ : point_cell_[v];
  }
  /// Appends every live cell having v as a vertex (v may be kInfiniteVertex). O(degree).
  void incident_cells(PointId v, std::vector<CellId>& out) const;
  /// Appends every facet containing v, each once. O(degree).
  void incident_facets(PointId v, std::vector<Facet>& out) const;
  /// Appends the ring of cells around the edge (vertex(c,i), vertex(c,j)), in rotation order,
  /// starting with c.
  void cells_around_edge(CellId c, int i, int j, std::vector<CellId>& out) const;
  /// Appends the ring of facets containing the edge, in the same rotation order: facet k is shared
  /// by cells k and k+1 of cells_around_edge, named as a facet of cell k.
  void facets_around_edge(CellId c, int i, int j, std::vector<Facet>& out) const;
  /// Calls f(CellId) for every live finite cell.
  template <class F>
  void for_each_finite_cell(F&& f) const {
    for (CellId c = 0; c < cell_capacity(); ++c)
      if (is_cell_alive(c) && !is_infinite(c)) f(c);
  }

  // -------------------------------------------------------------------------------------------
  // Location and duals
  // -------------------------------------------------------------------------------------------

  /// A cell containing p (closed): a finite cell if p is in the convex hull, else an infinite cell
  /// whose finite facet p sees strictly from outside. Exact (orient3d). Walks from `hint` (default:
  /// the last cell touched). Precondition: dimension() == 3.
  CellId locate(const Vec3& p, CellId hint = kNoCell) const;

  /// Orthocentre (centre of the power sphere orthogonal to the four weighted vertices) of a finite
  /// cell; rounded double arithmetic (constructions never decide combinatorics).
  Vec3 orthocentre(CellId c) const;
  /// Squared radius of that power sphere (its weight): |c - p_i|^2 - w_i for each vertex p_i.
  double orthoradius_squared(CellId c) const;
  /// The Voronoi edge dual to a finite facet (precondition: !is_infinite(f)).
  VoronoiEdge dual(Facet f) const;

  // -------------------------------------------------------------------------------------------
  // Checking
  // -------------------------------------------------------------------------------------------

  /// Checks every invariant, exactly: live cells have distinct valid vertices and symmetric
  /// neighbour links whose facet indices match; finite cells are positively oriented; every facet
  /// is locally regular (perturbed power test of the opposite vertex, the infinite-cell rule on
  /// the hull); vertex -> cell links point to incident cells; the hull is closed (each infinite
  /// cell's finite facet is seen from outside); every point is a vertex, hidden, pending or removed
  /// consistently with the counters; every vertex's star is connected; each hidden point lies in
  /// its cell and is not in conflict with it (hence with no cell containing it: the lifted
  /// triangulation is convex). Returns false with a description of the first problem in *why.
  /// O(n) predicates.
  bool is_valid(std::string* why = nullptr) const;

 private:
  friend struct RegularTriangulationTestAccess;
  static constexpr PointId kDeadCell = 0xFFFFFFFDu;  // marks a free slot in Cell::v[0]

  /// 32 bytes: vertex ids, and neighbour links (neighbour cell << 2 | index of the shared facet
  /// in the neighbour). A free slot has v[0] == kDeadCell and n[0] = next free slot.
  struct Cell {
    std::array<PointId, 4> v;
    std::array<std::uint32_t, 4> n;
  };
  struct Scratch;  // working arrays reused across operations (no per-insertion allocation)

  int pending_dimension() const { return basis_size_ - 1; }
  PointId append_point(const WeightedPoint& p);
  bool extends_basis(PointId id) const;
  void add_pending(PointId id, ChangeSet* changes);
  void remove_pending(PointId id);
  void build_first_tetrahedron(PointId a, PointId b, PointId c, PointId d);
  // `prefetch`: fetch each conflict cell's neighbours ahead (find_conflicts); pays off when the
  // point's neighbourhood is likely out of cache (single insertions), not in a sorted batch.
  void insert_in_3d(PointId id, CellId hint, ChangeSet* changes, bool prefetch);
  CellId valid_start(CellId hint) const;
  CellId walk(const double* p, CellId start) const;
  bool in_conflict(CellId c, const double* p, PointId replaced) const;
  void find_conflicts(CellId start, const double* p, PointId replaced, bool prefetch);
  void star_cavity(PointId id, ChangeSet* changes);
  void attach_hidden(PointId id, CellId c);
  void detach_hidden(PointId id);
  void enable_hidden_storage();
  CellId new_cell();
  CellId append_cell();
  void free_cell(CellId c);
  void collect_star(PointId v, std::vector<CellId>& star);
  bool remove_vertex(PointId v, ChangeSet* changes, std::string* error);
  void fill_hole_from_link(PointId v);
  bool fill_flat_hole(PointId v, std::string* error);
  void finish_removal(PointId v, ChangeSet* changes);
  Scratch& scratch() const;

  kernel::LargeVector<WeightedPoint> points_;   // by PointId
  kernel::LargeVector<CellId> point_cell_;      // vertex: an incident cell; hidden: its cell; else kNoCell
  kernel::LargeVector<PointStatus> status_;     // by PointId
  kernel::LargeVector<PointId> hidden_next_;    // next hidden point of the same cell (allocated lazily)
  kernel::LargeVector<PointId> cell_hidden_;    // first hidden point of each cell (allocated lazily)
  kernel::LargeVector<Cell> cells_;
  CellId free_head_ = kNoCell;
  std::size_t free_count_ = 0;
  CellId infinite_cell_ = kNoCell;
  CellId last_cell_ = kNoCell;          // default hint for the walk
  std::size_t vertex_count_ = 0;
  std::size_t hidden_count_ = 0;
  std::size_t infinite_cell_count_ = 0;
  bool weighted_ = false;               // some point with w != 0 was inserted
  std::vector<PointId> pending_;        // points waiting for dimension 3, in arrival order
  std::array<PointId, 3> basis_{};      // affinely independent pending points (pending_dimension+1)
  int basis_size_ = 0;
  bool hidden_storage_ = false;         // hidden_next_ / cell_hidden_ allocated
  mutable std::unique_ptr<Scratch> scratch_;
};

}  // namespace delpsc::delaunay
