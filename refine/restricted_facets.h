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
// lost one). Cells are named by vertex triples, not by cell slots, so recycled slots are harmless;
// the vertices of each live cell are mirrored here because the triangulation has already
// forgotten a destroyed cell's vertices when it reports it.
//
// The largest size is served by a max-heap with lazy deletion: an entry is valid while its
// record's stamp is unchanged. Per vertex, the list of records incident to it (its umbrellas,
// all patches mixed), for the disk condition.
//
// Units: size is a length, sqrt(max(0, power distance)), comparable with ball radii and λ.
// Cost: update is O(cells created + destroyed) facet examinations, each one segment or ray query
// of the Domain; memory ~100 bytes per restricted facet plus 16 bytes per cell slot.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <queue>
#include <span>
#include <tuple>
#include <unordered_map>
#include <vector>

#include <delpsc/delaunay/regular_triangulation.h>

#include "domain.h"

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
};

class RestrictedFacets {
 public:
  /// Both must outlive this object; the triangulation must have dimension 3 before rebuild().
  RestrictedFacets(const delaunay::RegularTriangulation& dt, const Domain& domain);

  /// Examines every finite facet once (initialisation only). Appends every vertex of a
  /// restricted facet to `touched`.
  void rebuild(std::vector<PointId>& touched);
  /// Follows one insert()/remove(): see the file comment. Appends to `touched` every vertex
  /// whose set of incident restricted facets may have changed, and every vertex of a created
  /// cell (a new vertex must be checked even if it has no restricted facet).
  void update(const delaunay::ChangeSet& changes, std::vector<PointId>& touched);

  std::size_t size() const { return live_; }
  const RestrictedFacet& operator[](std::uint32_t slot) const { return records_[slot]; }
  /// Slots of the live records incident to vertex v, all patches.
  std::span<const std::uint32_t> incident(PointId v) const {
    if (v >= by_vertex_.size()) return {};
    return by_vertex_[v];
  }
  /// The live record of largest size, kNoFacet when there is none. Amortised O(log n).
  std::uint32_t largest();
  /// How badly a record fails the refinement criteria (> 1: it must be refined; facet_criteria.h),
  /// evaluated once when the record is made. Set before rebuild(); empty: no record is bad.
  using Badness = std::function<double(const RestrictedFacet&)>;
  void set_badness(Badness badness) { badness_ = std::move(badness); }
  /// The live record of largest badness above 1, kNoFacet when there is none (step 2(b)).
  /// Amortised O(log n).
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
  struct Key {
    PointId a, b, c;
    friend bool operator==(const Key&, const Key&) = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = k.a * 0x9E3779B97F4A7C15ull;
      h ^= (k.b + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2));
      h ^= (k.c * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2));
      return static_cast<std::size_t>(h);
    }
  };
  static Key key_of(std::array<PointId, 3> v);

  void forget(const Key& k, std::vector<PointId>& touched);
  void project_on_facet_line(const Key& k, delaunay::VoronoiEdge& e) const;
  void examine(delaunay::Facet f, const Key& k, std::vector<PointId>& touched);
  std::uint32_t new_record();
  void mirror(delaunay::CellId c);

  const delaunay::RegularTriangulation* dt_;
  const Domain* domain_;
  std::vector<RestrictedFacet> records_;
  std::vector<std::uint32_t> free_;
  std::size_t live_ = 0;
  std::unordered_map<Key, std::uint32_t, KeyHash> head_;  // triangle -> first record
  std::vector<std::vector<std::uint32_t>> by_vertex_;
  std::vector<std::array<PointId, 4>> cells_;  // mirror of live cells' vertices
  std::vector<Key> examined_;                  // scratch: facets examined in this update
  std::vector<SurfaceHit> hits_;               // scratch
  using HeapEntry = std::tuple<double, std::uint32_t, std::uint32_t>;  // power, slot, stamp
  std::priority_queue<HeapEntry> heap_;
  Badness badness_;
  std::priority_queue<HeapEntry> bad_heap_;  // badness, slot, stamp
};

}  // namespace delpsc::refine
