// The restricted Delaunay facets of the mesher (Dey & Levine 2009, §1.2 and §2): a finite facet
// t of the regular triangulation is restricted to patch σ when its dual Voronoi edge V_t meets σ.
// For each such (t, σ) we keep the point of V_t ∩ σ farthest, in power distance, from t's
// vertices and that distance, size(t, σ) (§2: "the maximum weighted distance between the
// vertices of t and the points where the dual Voronoi edge of t intersects σ").
//
// Incremental: after each insert() or remove() of the triangulation, update() forgets the facets
// of the destroyed cells and examines the facets of the created cells, and nothing else. That is
// complete: a facet whose dual changed lost at least one of its two cells, so it is a facet of a
// destroyed cell, and if it survives it is a facet of a created cell (the cell that replaced the
// lost one). Records hang off the cell facets (both sides of each facet); a destroyed cell's slot
// still holds its references when update() runs, even if a created cell reuses the slot, because
// the destroyed cells are processed first. After an insertion a facet on the cavity's boundary
// is not queried again when its old outcome still decides the new one (its dual edge only
// shrank): none if the old dual met nothing, else each single crossing kept or dropped by one
// exact power comparison with the new point (update(), carry_over()).
//
// The largest size is served by a max-heap with lazy deletion, made on first use: an entry is
// valid while its record's stamp is unchanged. Per vertex, the list of records incident to it (its umbrellas,
// all patches mixed), for the disk condition.
//
// Units: size is a length, sqrt(max(0, power distance)), comparable with ball radii and λ.
// Cost: update is O(cells created + destroyed) facet examinations, each one segment or ray query
// of the Domain, and no hashing; memory ~100 bytes per restricted facet plus 21 bytes per cell
// slot.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include <delpsc/delaunay/regular_triangulation.h>

#include "domain.h"
#include "incidence_lists.h"

namespace delpsc::refine {

using delaunay::PointId;

inline constexpr std::uint32_t kNoFacet = 0xffffffffu;

/// One restricted pair (t, σ).
struct RestrictedFacet {
  std::array<PointId, 3> vertices{};  ///< increasing
  std::uint32_t patch = 0;            ///< σ
  Vec3 point = Vec3::Zero();          ///< the point of V_t ∩ σ realising size(t, σ)
  double power = 0;                   ///< its power distance to t's vertices (largest of the three)
  double size = 0;                    ///< sqrt(max(0, power))
  std::uint32_t stamp = 0;            ///< changes whenever the slot is reused
  std::uint32_t next = kNoFacet;      ///< next record of the same triangle (other patches)
  bool alive = false;
  bool discarded = false;             ///< skipped by largest() (see discard)
  /// The dual edge met σ exactly once, crossing it (not running inside it), and was computed from
  /// cells far from flat: update() may then carry the record over to a shrunk dual edge.
  bool carriable = false;
  std::uint32_t kept = 0;             ///< the update that last carried it over
};

/// A live record as seen from one of its vertices v: its slot, its patch and the edge of t
/// opposite v, which is all the disk condition reads (disk_condition.h). Kept in v's list so a
/// check walks one contiguous array instead of touching each ~100-byte record.
struct Incidence {
  std::uint32_t slot = kNoFacet;
  std::uint32_t patch = 0;
  std::array<PointId, 2> link{};  ///< t's other two vertices, increasing
};

class RestrictedFacets {
 public:
  /// Both must outlive this object; the triangulation must have dimension 3 before rebuild().
  RestrictedFacets(const delaunay::RegularTriangulation& dt, const Domain& domain);

  /// Facets with one of these points as a vertex are never examined and never restricted: for
  /// points whose power cells are known to miss the domain (the mesher's far frame points), whose
  /// facets' dual edges are the longest and costliest queries (~20% of them on a convex model).
  /// Call before rebuild(). Throws std::invalid_argument for an id that is no point of the
  /// triangulation (>= number_of_points()). O(number_of_points()) memory, one byte each.
  void exclude_vertices(std::span<const PointId> points);
  /// Examines every finite facet once (initialisation only). Appends every vertex of a
  /// restricted facet to `touched`. Calls `tick` (if any) every 2^16 cells, for a progress line.
  /// `cover_power`: a bound the caller has proven on the power distance from every point of the
  /// domain to its power-nearest point of the triangulation (sample_cover_power). A point x of a
  /// facet's dual edge has power distance P + |x - o|² >= P to the facet's vertices (o, P: the
  /// facet's orthocentre and its power), and they are its nearest; so where P exceeds the bound
  /// (by a 1% margin for rounding, in a triangle far from degenerate) the edge misses the domain
  /// and is not queried: ~3 facets in 4 after the mesher's initial sample, the far side of the
  /// volume's tetrahedra. Of the others only the window |s| <= sqrt(bound - P) around the
  /// orthocentre is queried (nothing when the computed edge misses it). +inf (the default):
  /// every facet's whole dual edge is queried. update() goes on using the bound for the facets
  /// of new cells until the first removal: the least power distance to the vertices equals the
  /// least to all points inserted, hidden ones included, so an insertion (whatever it hides)
  /// only lowers it at every point of space; a removal may raise it.
  void rebuild(kernel::LargeVector<PointId>& touched, const std::function<void()>& tick = {},
               double cover_power = std::numeric_limits<double>::infinity());
  /// Follows one insert()/remove(): see the file comment. Appends to `touched` every vertex
  /// whose set of incident (triangle, patch) pairs changed - not a vertex whose pairs were
  /// merely recomputed, nor a new vertex without restricted facets: the caller checks that one.
  /// `inserted`: the point whose insertion made the changes (cells only shrink, see update()), or
  /// delaunay::kNoPoint when they come from a removal. Precondition for an insertion: the
  /// triangulation had dimension 3 before it, so the created cells are exactly those with
  /// `inserted` as a vertex (not so when an insertion first reaches dimension 3: use rebuild()).
  void update(const delaunay::ChangeSet& changes, kernel::LargeVector<PointId>& touched, PointId inserted);

  /// rebuild() reserves 1 / kGrowthRoom more of every per-cell and per-vertex array for step 2's
  /// points (1-27% more vertices on the CGAL demo models); the mesher reserves as much of the
  /// triangulation's per-point arrays.
  static constexpr std::size_t kGrowthRoom = 4;

  std::size_t size() const { return live_; }
  /// Dual edges queried against the domain so far (segments and rays): the cost that
  /// carry-over and exclude_vertices save.
  std::size_t queries() const { return queries_; }
  /// Facets spared a query so far because of rebuild()'s `cover_power` (their dual edge or its
  /// window misses the domain), by rebuild() and then by update().
  std::size_t skipped() const { return skipped_; }
  const RestrictedFacet& operator[](std::uint32_t slot) const { return records_[slot]; }
  /// Checker of the references from cells to records: every live finite cell's facet holds
  /// the same reference from both sides, naming a live record of that triangle (or none), and
  /// every dead cell slot holds none. Returns the first problem, or an empty string.
  /// O(cells). For tests.
  std::string refs_consistent() const;
  /// The live records incident to vertex v, all patches.
  std::span<const Incidence> incident(PointId v) const {
    return by_vertex_[v];
  }
  /// The live record of largest size, kNoFacet when there is none. Amortised O(log n).
  std::uint32_t largest();
  /// How badly a record fails the refinement criteria (> 1: it must be refined; facet_criteria.h),
  /// evaluated once when the record is made. Set before rebuild(); empty: no record is bad.
  using Badness = std::function<double(const RestrictedFacet&)>;
  void set_badness(Badness badness) { badness_ = std::move(badness); }
  /// A live record of badness above 1 in the highest eighth of an octave of badness, the first
  /// of those in Morton order of their points (see order_key); kNoFacet when there is none
  /// (step 2(b)). Amortised O(log n).
  std::uint32_t worst();
  /// Takes a record out of the largest() and worst() orders (its point proved unusable) until it is recomputed.
  void discard(std::uint32_t slot) { records_[slot].discarded = true; }
  /// Calls f(slot, record) for every live record.
  template <class F>
  void for_each(F&& f) const {
    for (std::uint32_t s = 0; s < records_.size(); ++s)
      if (records_[s].alive) f(s, records_[s]);
  }

 private:
  /// The first record of a facet, as seen from one of its two cells: its slot, kNoFacet (no
  /// record), or kUntrusted. Four bytes and no stamp (they were half the restricted facets'
  /// memory, as large as the cells, at 8): outside update() every reference held by a live cell
  /// names a live record of that facet, and a dead cell's holds none (refs_consistent() checks
  /// it). Inside update() a surviving neighbour's reference may name a record just forgotten;
  /// slots freed there are only reused from the next update() on (free_later_), so such a
  /// reference names a dead record until the facet is visited, never another facet's.
  using FacetRef = std::uint32_t;

  void forget(FacetRef& ref);
  void forget_chain(std::uint32_t first);
  void forget_record(std::uint32_t s);
  /// Carries the records of a cavity-boundary facet over to its shrunk dual edge (see update()):
  /// keeps those whose point is not power-closer to `inserted` than to t, forgets the others.
  /// Returns the new first record (kNoFacet: none left), or nullopt when some record is not
  /// carriable and the facet must be examined afresh.
  std::optional<std::uint32_t> carry_over(std::uint32_t first, PointId inserted);
  /// Appends to `touched` the vertices of the (triangle, patch) pairs in gone_ or made_ but not
  /// both, and empties them.
  void touch_changed(kernel::LargeVector<PointId>& touched);
  /// The line of points power-equidistant from t's vertices: t's orthocentre, t's unit normal,
  /// the power distance from the orthocentre to t's vertices, and t's shape, |ab x ac|² /
  /// (|ab|² |ac|²) (the squared sine of the angle at a). nullopt for a degenerate t.
  struct FacetLine {
    Vec3 orthocentre, normal;
    double power, shape;
  };
  std::optional<FacetLine> facet_line(const std::array<PointId, 3>& t) const;
  /// The dual edge of finite facet f, computed on the line of its vertices (sorted) from their
  /// orthocentre (precondition: both cells finite). An end is not finite when a cell is flat or
  /// there is no line.
  delaunay::VoronoiEdge dual_on_facet_line(delaunay::Facet f, const std::optional<FacetLine>& line) const;
  /// The same from the cells' orthocentres (dual()), projected on the line: for flat cells.
  delaunay::VoronoiEdge dual_projected(delaunay::Facet f, const std::optional<FacetLine>& line) const;
  /// Examines finite facet f (its dual edge against the domain) and records it on both sides;
  /// not when its power exceeds `cover_power` (see rebuild).
  void examine(delaunay::Facet f, double cover_power = std::numeric_limits<double>::infinity());
  bool well_conditioned(delaunay::Facet f) const;
  /// worst()'s heap key of a bad record: badness in eighth octaves, then Morton order of x.
  double order_key(double badness, const Vec3& x) const;
  /// The reference of a facet without records whose dual met no patch but was computed from
  /// nearly flat cells (see well_conditioned): update() examines it again.
  static constexpr FacetRef kUntrusted = kNoFacet - 1;
  /// Whether a reference names a record (neither kNoFacet nor kUntrusted).
  static bool names_record(FacetRef r) { return r < kUntrusted; }
  std::uint32_t new_record();
  FacetRef& ref(delaunay::CellId c, int i) { return facet_refs_[4 * std::size_t{c} + static_cast<std::size_t>(i)]; }

  const delaunay::RegularTriangulation* dt_;
  const Domain* domain_;
  kernel::Box3 box_;  // the domain's, for order_key
  kernel::LargeVector<RestrictedFacet> records_;
  kernel::LargeVector<std::uint32_t> free_;
  kernel::LargeVector<std::uint32_t> free_later_;  // slots forgotten during update(): free at its end
  bool updating_ = false;
  std::size_t live_ = 0;
  IncidenceLists<Incidence> by_vertex_;
  // Per cell slot, per facet index: its records. Indexing by cell facet instead of hashing the
  // vertex triple: the facets to forget are exactly those of the destroyed cells, whose slots
  // still hold the old references when update() runs, so no lookup by vertices is ever needed.
  kernel::LargeVector<FacetRef> facet_refs_;
  kernel::LargeVector<std::uint32_t> created_mark_;    // per cell slot: the update that created it
  // Per cell slot, whether well_conditioned() found the cell nearly flat (unknown until asked).
  static constexpr std::uint8_t kFlatUnknown = 0, kFlatNo = 1, kFlatYes = 2;
  mutable kernel::LargeVector<std::uint8_t> flat_;
  kernel::LargeVector<FacetRef> doomed_;               // scratch: records of destroyed cells, forgotten last
  kernel::LargeVector<FacetRef> boundary_refs_;        // scratch: per created cell, its boundary facet's old ref
  std::uint32_t update_epoch_ = 0;
  std::vector<SurfaceHit> hits_;               // scratch
  kernel::LargeVector<char> excluded_;                 // by PointId: exclude_vertices()
  std::size_t queries_ = 0;
  std::size_t skipped_ = 0;
  // rebuild()'s proven cover, kept by update() until the first removal voids it (see rebuild).
  double cover_power_ = std::numeric_limits<double>::infinity();
  kernel::LargeVector<std::array<std::uint32_t, 4>> gone_, made_;  // scratch: (vertices, patch) forgotten, made
  using HeapEntry = std::tuple<double, std::uint32_t, std::uint32_t>;  // power, slot, stamp
  std::priority_queue<HeapEntry> heap_;
  bool heap_active_ = false;  // heap_ is made on the first largest() call
  Badness badness_;
  std::priority_queue<HeapEntry> bad_heap_;  // order_key, slot, stamp
};

}  // namespace delpsc::refine
