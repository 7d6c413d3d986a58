// Mesh2Complex, step 2 of DelPSC (Dey & Levine 2009, §3), on a regular triangulation of the
// protecting balls (weighted points) and of unweighted points inserted on the patches:
//   (a) if some vertex p fails D1 or D2 (disk_condition.h): with d1 the largest size(t, σ) (x the
//       point realising it) and d2 the largest ball radius, insert x if d1 >= d2, else RefineBall
//       the largest ball; else if some vertex fails D3 or D4, insert the point of its offending
//       umbrella triangle (the x of the termination proof, Theorem 3.1);
//       With local_disk_refinement (the default), d1 and d2 are taken over p's neighbourhood:
//       the restricted facets incident to p (all patches) and, for an unweighted p, the balls
//       among their vertices; for a ball p, its own ball only (a larger ball next to it is
//       judged at its own vertex and at the unweighted points it is joined to). The paper's
//       global maxima make one persistent local failure (a thin wedge, a short curve) refine
//       the whole model down to the size that failure needs. Lemma 2.2
//       (D1, D2 hold at p once the triangles and balls near p are small enough) suggests the
//       local choice also terminates, but the packing argument of §3 is written for the global
//       one and is not redone here: max_vertices is the guard. Locally, x is inserted while
//       d1 >= kLocalBallRatio d2 (below; kLocalCornerBallRatio for a corner ball), not
//       d1 >= d2. When p has no usable umbrella facet and is no ball, the global choice is used,
//       unless p has no facet at all (insert_in_own_cell);
//       a ball p whose umbrella has no facet on the failing patch σ takes σ's facets at its
//       neighbours instead (largest_facet_next_to), then a surface point of σ in its power cell
//       if there is one (cell_surface_point.h). A D3/D4 failure whose facet's point already proved off
//       V_t (discarded) is handled by the same local step. A D3/D4 facet whose point lies within √2 radii of a ball vertex off its
//       patch refines that ball instead (ball_reaching_patch: the termination proof assumes
//       balls keep away from the patches their curves do not bound; Protect does not ensure it).
//   (b) else if some restricted facet fails the criteria (facet_criteria.h: size(t, σ) > λ - or
//       > sizing(x) -, facet_distance, facet_angle), insert the point x of a worst one (the
//       worst eighth of an octave of badness, in Morton order within it: RestrictedFacets::worst);
//   (c) repeat while something changed;
//   (d) not in the paper: then, if a patch's restricted triangles come in several pieces (the
//       disk condition is local and passes on a closed piece away from the rest: narrow cones),
//       refine the facets within an octave of the largest of each piece but the patch's
//       largest piece, and go on (extra_pieces.h).
// Everything is incremental: each insert/remove reports its cells (ChangeSet), the restricted
// facets follow (restricted_facets.h), and only the vertices of changed facets are re-checked.
//
// Admissibility (§2.1): an unweighted point is inserted only if its power distance to every
// vertex of its facet is positive (kernel::power_distance_sign, exact) - they are its power-
// nearest vertices, so it then lies in no ball; otherwise it is refused and the ball refined.
// After a RefineBall, unweighted points that the new, smaller balls swallow are removed (the new
// balls can poke slightly outside the old one).
//
// Initialisation: the balls; for every patch without boundary (a component without features) a
// few seed points where lines through its interior point meet it; unless initial_sample is off,
// a sample of the patches whose every point is power-farther than a separation (λ for the
// lattice's points, 0.9 λ for the gap fillers) from the seeds and the sample points before it,
// and than half that from the balls (initial_sample.h) - not in the paper, which starts from the
// balls. The sample is a
// finite set of points outside every ball (admissible, §2.1), inserted before step 2 starts:
// §3's packing argument for termination is about step 2's own insertions, each of which is still
// farther than λ from every point of S, so it holds as before (a finite start set only adds a
// constant), and the guarantees, which are about the state step 2 ends in (the disk condition
// at every vertex, every size(t, σ) <= λ), are checked as before. What changes is the
// cost: the sample goes in as one spatially sorted batch and the restricted facets are computed
// once, instead of ~40 dual-edge queries per point as facets are made and unmade level after
// level (refinement -40 to -60% on the libcgal-demo models, 3-6% more vertices; BENCHMARKS.md);
// step 2 then has ~1/6 of the insertions left. Candidates come from a jittered lattice on each
// cluster of nearly parallel triangles (surface_lattice.h, triangle_clusters.h), which covers it
// with (almost) no holes, chosen first, then random points near the clusters' boundaries and on
// clusters too small for a lattice (select_sample): step 2 is left with 0.2-9% of the vertices
// to insert (11-17% with random candidates alone), and the meshes have 15-22% fewer vertices
// (779d6c6; the closer gap fillers of 1f018ab add 0-2.5% back). Last, a net of every patch
// (every point within 1.5 λ of a net point) is chosen from at 0.9 λ: it fills what holes are left
// and, every net point being chosen or refused by a ball or point, proves how far any point of
// the domain can be from the sample (sample_cover_power, 2.66 λ with balls of radius λ). The
// first examination of the facets then skips every facet whose orthocentre's power exceeds that
// (RestrictedFacets::rebuild): its dual edge cannot meet the domain. That is ~3 facets in 4 of
// the batch's triangulation at 0.5% (the volume's tetrahedra; 39-58% at ~2%), and with the rest
// of the first examination queried only near the surface, meshing at 0.5% is ~8-22% faster.
// And 8 unweighted frame points
// far outside the bounding box (3 diagonals away), which make the triangulation 3-dimensional
// even for a flat sheet and keep removals legal. Their Voronoi cells never reach the domain
// (every domain point is power-closer to any sample than to them), so no restricted facet uses
// them, and their facets are not even examined (RestrictedFacets::exclude_vertices): on a convex
// model every sample point is a hull point, and the frame's facets were ~20% of the dual-edge
// queries, the longest ones.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <delpsc/delaunay/regular_triangulation.h>
#include <delpsc/io/surface_mesh.h>

#include "ball_source.h"
#include "disk_condition.h"
#include "domain.h"
#include "facet_criteria.h"
#include "initial_sample.h"
#include "restricted_facets.h"

namespace delpsc::refine {

/// Step 2(a) with local_disk_refinement refines p's ball only when every restricted facet around
/// p is smaller than this fraction of its radius (d1 < kLocalBallRatio d2); until then it inserts
/// the point x of p's largest facet. At a corner where two feature curves leave a few degrees
/// apart - a needle face, common on convex hulls of random points and CAD parts, - or where a
/// patch folds back by a few degrees, the configuration looks the same at every scale: a disk
/// failure there is resolved by a sample finer than the balls, never by smaller balls, and with
/// d1 >= d2 each RefineBall was followed by the same failure one scale down until the balls'
/// floor (protect::kSmallestBallOfLambda) ended the run. Measured (BENCHMARKS.md, session 18):
/// random convex hulls 27 of 1,120 runs failing -> 0 at 1/16; over the 143 libcgal-demo models
/// at 4/2/1/0.5% every model that meshed still meshes, 3-23% fewer vertices on the models whose
/// balls shrank before (lion, triceratops, blade), the benchmark models unchanged; at 1/64 hand
/// meshes at 2% and 0.5% as well. Inserted points keep a weighted distance of at least
/// kLocalBallRatio times the smallest ball radius from the others, so the packing argument
/// bounds them as before, with the constant divided by 64.
inline constexpr double kLocalBallRatio = 1.0 / 64;

/// kLocalBallRatio when the ball step 2(a) would refine is a corner ball. A corner ball's
/// RefineBall is the root of a refinement tree (Lemma 2.5: it halves the ball and re-covers every
/// curve leaving the corner), and at a pleat - the surface around a corner sweeping more than
/// 360° and overlapping itself in a wedge of angle θ, its sheets there at angle φ - the disk
/// condition at the corner needs samples ~sin θ sin φ times the ball's radius apart near its
/// sphere, the same at every scale: on libcgal-demo's mech-holes-shark.off (a flipped sliver
/// triangle, θ = 3.3°, folds of 8° and 17.8°) that is 1/125, finer than 1/64, and each shrink of
/// the corner ball was followed by the same failure one scale down, to the balls' floor. At 1/256
/// it meshes at 1% and 0.5% (at 2% and 4% too, with the floor of protect::options_for_size at
/// most 5e-7 of the diagonal, since session 19 1e-8); io::make_pleated_sheet is the same defect, generated. The packing
/// bound of kLocalBallRatio holds with 256 for 64.
inline constexpr double kLocalCornerBallRatio = 1.0 / 256;

struct MesherOptions {
  double facet_size = 0;          ///< λ of step 2(b), absolute (> 0 unless `sizing` is given)
  /// λ as a function of position, absolute, positive and finite on the domain (the smaller of it
  /// and facet_size applies). Empty: the constant facet_size.
  std::function<double(const Vec3&)> sizing;
  double facet_distance = 0;      ///< CGAL's facet_distance, absolute; 0: off (facet_criteria.h)
  double facet_angle = 0;         ///< lower bound on angles of all-unweighted triangles, degrees,
                                  ///< at most kMaxFacetAngleDegrees (30); 0: off
  /// Stop when the mesh has this many vertices (0: no limit). With more protecting balls than
  /// this, run() stops before inserting anything (stats().message says so; the output is empty).
  std::size_t max_vertices = 0;
  int seeds_per_patch = 8;        ///< seeds on each patch without boundary (>= 4 advised)
  /// Start step 2 from a well-spread sample of the patches (initial_sample.h, and the file
  /// comment) besides the balls and seeds; false: from the balls and seeds alone, as the paper.
  /// Needs facet_size > 0; with `sizing` too, each sample point's separation is min(λ, sizing)
  /// (0.9 times that for the gap fillers).
  bool initial_sample = true;
  /// How near the balls the initial sample may come, in (0, 1] (initial_sample.h,
  /// kBallClearance; the constructor refuses other values): 1 keeps it a full separation from
  /// them. `delpsc mesh` retries a run that ends at the balls' floor once with 1.
  double sample_ball_clearance = kBallClearance;
  /// Step 2(a) for a D1/D2 failure at p chooses x and the ball among p's umbrellas (see the
  /// file comment) instead of over the whole mesh; false: the paper's global choice.
  bool local_disk_refinement = true;
  /// When step 2 ends, a patch whose restricted triangles come in several pieces has the facets
  /// within an octave of the largest of each piece but its largest refined, and step 2 goes on
  /// (refine_extra_pieces in mesher.cpp); false: the run ends there, as the paper's.
  bool refine_extra_pieces = true;
  /// Called with the number of domain vertices every `progress_every` steps of the loop, and
  /// during initialisation (every 2^16 points of the batch insertion and every 2^16 cells of the
  /// first restricted-facet pass), for a progress line; empty: never.
  std::function<void(std::size_t vertices)> progress;
  std::size_t progress_every = 2000;
  /// Asked every 64 steps of the loop, between initialisation's phases and at its progress
  /// points (see progress); true ends run() where it is, with stats().stopped_on_request, and
  /// output() is the mesh reached: empty until the initial points are all inserted and examined
  /// (stats().initialised), then the restricted triangles of the moment, where the disk
  /// condition may still fail. A caller's time limit (`delpsc mesh --max-seconds`); empty:
  /// never. Costs one call every 64 steps.
  std::function<bool()> stop;
};

struct MesherStats {
  std::size_t insertions_disk = 0;      ///< step 2(a), D1/D2 failure, d1 >= d2 (locally: kLocalBallRatio d2)
  std::size_t insertions_d34 = 0;       ///< step 2(a), D3/D4 failure
  std::size_t insertions_empty_cell = 0;  ///< step 2(a), a ball without restricted facets: a point of its cell
  std::size_t insertions_size = 0;      ///< step 2(b), facet_size (or sizing) failed worst
  std::size_t insertions_distance = 0;  ///< step 2(b), facet_distance failed worst
  std::size_t insertions_angle = 0;     ///< step 2(b), facet_angle failed worst
  std::size_t insertions_pieces = 0;    ///< a patch's extra piece sampled (extra_pieces.h)
  std::size_t ball_refinements = 0;     ///< RefineBall calls of step 2(a)
  /// Step 2(a) steps that took the paper's global d1 and d2 (with local_disk_refinement: nothing
  /// local applied at the failing vertex): a sign of a configuration the local steps miss.
  std::size_t global_choices = 0;
  std::size_t refused_inside_ball = 0;  ///< points refused for admissibility
  std::size_t swallowed = 0;            ///< unweighted points removed inside new balls
  std::size_t rejected_inaccurate = 0;  ///< points of an inaccurate dual edge that were hidden
  std::size_t seeds = 0;
  std::size_t sampled = 0;              ///< points of the initial sample
  /// Facets of the first examination the sample's proven cover spared a dual-edge query
  /// (RestrictedFacets::rebuild), and those queried; 0 skipped without a sample or its net.
  std::size_t cover_skipped = 0, first_queries = 0;
  std::size_t full_sweeps = 0;          ///< closing full re-checks (initialise's first one not
                                        ///< counted; one only after a RefineBall since the last)
  bool stopped_at_max_vertices = false;
  bool stopped_on_request = false;      ///< MesherOptions::stop said so
  bool initialised = false;             ///< the initial points all inserted and examined
  bool stuck = false;                   ///< a failure no step could address (see message)
  std::string message;
};

class Mesher {
 public:
  /// `domain` and `balls` must outlive the mesher; balls are refined through `balls`.
  /// Throws std::invalid_argument for impossible options (facet_criteria.h).
  Mesher(const Domain& domain, BallSource& balls, const MesherOptions& options);

  /// Runs step 2 until nothing changes (or the vertex cap). Call once.
  void run();

  /// ∪ Skl^i: restricted triangles labelled by patch (consistently oriented per connected
  /// component, outward where the component is closed - into the cavity for one inside an odd
  /// number of other closed components -, elsewhere - open sheets, closed shells
  /// meeting along non-manifold edges - as the input's triangles there are;
  /// refine/triangle_orientation.h), edges between consecutive ball centres labelled by curve,
  /// corners.
  io::SurfaceMesh output() const;

  /// Vertices of the domain (balls and surface points) that are vertices of the triangulation.
  std::size_t domain_vertex_count() const;
  /// Vertices failing the disk condition now, with the first failure of each (none before the
  /// initial points are all examined: stats().initialised false).
  std::vector<std::pair<PointId, DiskVerdict>> failing_vertices() const;

  const MesherStats& stats() const { return stats_; }
  const delaunay::RegularTriangulation& triangulation() const { return dt_; }
  const RestrictedFacets& restricted_facets() const { return facets_; }
  const Domain& domain() const { return *domain_; }

 private:
  void initialise();
  /// Throws (a type private to mesher.cpp, caught by run()) when options_.stop says so.
  void stop_if_asked() const;
  void seed_points(std::vector<Vec3>& seeds, std::vector<std::uint32_t>& seed_patch) const;
  void add_initial_sample(std::span<const BallKey> keys, kernel::LargeVector<WeightedPoint>& points,
                          kernel::LargeVector<VertexPlace>& places);
  // Facets, then re-check touched vertices; `inserted`: the point inserted, kNoPoint after a removal.
  void apply(const delaunay::ChangeSet& changes, PointId inserted);
  DiskVerdict recheck(PointId p);  // p's verdict, also kept in failing_d12_ / failing_d34_
  bool insert_surface_point(std::uint32_t facet_slot);
  // Inserts unweighted x on `patch` (walking from `where`); false, and nothing changed, if it
  // came out hidden.
  bool insert_unweighted(const Vec3& x, std::uint32_t patch, delaunay::CellId where);
  // A gross error; `where`: a cell to walk from, on return the cell containing r.point.
  bool far_off_dual_edge(const RestrictedFacet& r, delaunay::CellId& where) const;
  // Local step 2(a) at p, which fails the disk condition on `failing_patch` (the verdict's σ;
  // kNoElement if unknown); false if nothing local applies.
  bool refine_around(PointId p, std::uint32_t failing_patch);
  // An unweighted vertex p with no restricted facet at all: its patch crosses p's power cell
  // without meeting a Voronoi edge (on a narrow cone, a band of the side wrapped round inside the
  // cell of the one point on it). Inserts the surface point of p's patch in p's cell farthest
  // from p (cell_surface_point.h), if one lies at least kLocalBallRatio times p's nearest-
  // neighbour distance away, as the local step's other insertions keep that fraction of the
  // balls' radii. False if there is none. Half that distance was too far for cones narrower
  // than 8°: the side's far wall is ~2 sin θ times the distance to the tip away, the sample's
  // spacing there up to λ.
  bool insert_in_own_cell(PointId p);
  // The largest restricted facet on `patch` (not discarded) incident to a neighbour of p in the
  // triangulation, its size in `size` (-1 if none); kNoFacet if none. Cost: p's star times the
  // neighbours' umbrellas.
  std::uint32_t largest_facet_next_to(PointId p, std::uint32_t patch, double& size) const;
  // For a ball vertex p: the largest ball among p's neighbours in the triangulation that holds
  // p's centre and is not adjacent to p (C3 broken, see refine_around); kNoBallKey if none.
  BallKey larger_ball_over(PointId p) const;
  // For a D3/D4 facet: a ball vertex off the facet's patch that the facet's point is within
  // √2 radii of (size(t, σ) < radius), the largest such; kNoBallKey if none.
  BallKey ball_reaching_patch(const RestrictedFacet& r) const;
  bool sweep_failures();          // re-checks every vertex; true if some fails
  // Where step 2 ends: the largest facets of every extra piece of a patch (extra_pieces.h) are
  // refined; false if there is none, or none above the floor (see mesher.cpp).
  bool refine_extra_pieces();
  void refine_ball(BallKey key);
  PointId insert_ball(BallKey key);
  void remove_point(PointId p);

  const Domain* domain_;
  BallSource* balls_;
  MesherOptions options_;
  FacetCriteria criteria_;
  delaunay::RegularTriangulation dt_;
  kernel::LargeVector<VertexPlace> places_;  // by PointId
  RestrictedFacets facets_;
  DiskCondition disk_;
  std::unordered_map<BallKey, PointId> ball_point_;
  std::unordered_set<PointId> failing_d12_, failing_d34_;
  kernel::LargeVector<PointId> touched_;
  delaunay::ChangeSet changes_;
  std::size_t frame_points_ = 0;
  // stats_.ball_refinements when every vertex was last checked (end of initialise,
  // sweep_failures): the closing full pass runs only if RefineBall happened since.
  std::size_t refinements_at_full_check_ = 0;
  // What the initial sample proves of its reach (sample_cover_power; +inf: nothing), for the
  // first examination of the facets.
  double sample_cover_power_ = std::numeric_limits<double>::infinity();
  MesherStats stats_;
};

}  // namespace delpsc::refine
