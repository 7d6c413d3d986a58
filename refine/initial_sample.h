// The mesher's initial sample (not in the paper; mesher.h says why it keeps the guarantees):
// points of the patches chosen so that each one is power-farther than a separation from every
// point chosen before it - the spacing λ for the lattice's points, kGapFillSpacing λ (0.9 λ) for
// the random points that fill its gaps - and than half that from every protecting ball
// (kBallClearance), so each lies outside every ball and the sample is a finite, well-spread set. Inserting it in one sorted batch instead of
// one point at a time, each with a restricted-facet update and a disk check, is the point: step 2
// of Mesh2Complex (Dey & Levine 2009, §3) then starts close to its end. The candidates end with
// a net of every patch, chosen from last: once every net point is decided, the sample provably
// reaches every point of the domain (sample_cover_power), which spares most of the first
// examination's dual-edge queries (RestrictedFacets::rebuild).
//
// Units: lengths of the coordinates; spacing > 0. Cost: O(n) expected for n candidates plus a
// sort of the candidates by grid cell; memory O(n).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/point.h>

namespace delpsc::refine {

/// Indices into `candidates` of the points chosen, in the order they were chosen: greedily, in an
/// order sorted by grid cell, a candidate is chosen when its power distance to every ball of
/// `balls` and its squared distance to every point of `fixed` and every point chosen before it
/// all exceed spacing². Candidates that are not finite are skipped. Empty when spacing is not
/// positive and finite, or so small against the candidates' extent that the grid would need more
/// than 2^19 cells along an axis, or when there are 2^32 candidates or more.
/// `local_spacing`, if not empty (one per candidate, each in (0, spacing]), replaces spacing in a
/// candidate's own test: what a sizing function asks for there (step 2(b) inserts x when its
/// weighted distance to S exceeds sizing(x)). A candidate whose local spacing is not in that
/// range is skipped.
/// `decided`, if given, is set to whether every candidate was decided: false when the call
/// refused (above) or skipped a candidate.
std::vector<std::uint32_t> select_separated_points(std::span<const Vec3> candidates,
                                                   std::span<const WeightedPoint> balls,
                                                   std::span<const Vec3> fixed, double spacing,
                                                   std::span<const double> local_spacing = {},
                                                   bool* decided = nullptr);

/// The separation of the random candidates that fill the lattice's gaps, relative to the
/// spacing. Random sequential choice leaves thin pockets along the protecting balls and the
/// clusters' seams where a restricted facet's size just exceeds the spacing: on the cube at 2%
/// all 241 step-2(b) insertions lay 1.01-1.23 λ from an edge with sizes 1.00-1.08 λ, and more
/// candidates hardly helped (241 -> 211 at four times the density). Each such insertion costs
/// several batch points. At 0.9 most pockets close (cube 241 -> 152, fandisk 149 -> 70 at 2%;
/// anchor 1,407 -> 673, elephant 1,260 -> 580 at 0.5%) for 0-2.5% more vertices. The paper's
/// termination argument (§3: each step-2 insertion is farther than λ from every other point)
/// is about the loop's insertions; a finite initial sample may be as dense as it likes.
inline constexpr double kGapFillSpacing = 0.9;

/// How near the balls select_sample lets a candidate come: its power distance to every ball must
/// exceed (kBallClearance × its spacing)², against spacing² to every other point. A sample point
/// is then at least sqrt(r² + (s/2)²) from a ball's centre, outside the ball (admissible, §2.1),
/// and no nearer than a point of step 2 might be: the paper inserts a facet's surface point
/// wherever its weighted distance to the vertices is large, and the sample's own spacing already
/// departs from λ. What the clearance buys: right after the batch, most disk failures on CAD
/// models are D3 at a ball - a ball joined to a ball of another curve across a strip where the
/// full clearance left no room for a sample point - each repaired by a step-2 insertion at ~4
/// times a batch point's cost. At 0.5 (1 before) the 2% runs have 13 instead of 166 insertions
/// on the cube, 83 / 165 on fandisk, 69 / 190 on anchor, 98 / 220 on joint, for 1-5% more
/// vertices at the same size; at equal output vertex count (scripts/bench-vs-cgal.sh
/// --match-vertices yes) every model with curves meshed 1-8% faster, the sphere (no balls) the
/// same (BENCHMARKS.md, session 17). The cover bound (sample_cover_power) even tightens: a net
/// point refused by a ball has power at most (kBallClearance s)² to it.
inline constexpr double kBallClearance = 0.5;
// Not everywhere a gain: on two of the hardest libcgal-demo models the half clearance shifted
// where refinement met the balls' floor (hand.off at 1%, a 2.1° fold, and cheese.off at 4%
// failed; triceratops.off at 4% newly meshed), so `delpsc mesh` retries such a run once with
// the full clearance (MesherOptions::sample_ball_clearance).

/// The radius of the net Domain::surface_candidates ends with, relative to the spacing: every
/// point of every patch is within it of a net point. The net lets the mesher prove how far the
/// sample reaches (sample_cover_power) and skip the dual-edge queries of the facets that cannot be
/// restricted (RestrictedFacets::rebuild). At 1.5 the net is ~0.5 points per spacing² and the
/// proven reach 2.66 spacings (restricted facets of the CGAL demo models' samples reach 1.3).
/// Meshing at 0.5%: 2-17% faster than without the net and the skipped queries; at 2.5 and 3.5
/// the cheaper net skips fewer queries and the sum is no better.
inline constexpr double kNetRadius = 1.5;

/// When the net's triangle samples (its points but the triangles' corners) would be more than
/// kNetExcess times as many as the lattice and the random candidates together, it is thinned
/// (PolygonDomain::surface_candidates): a net point is left out when one kept before lies within
/// kNetThinning net radii (thinning_grid.h), and the net's radius grows to (1 + kNetThinning)
/// kNetRadius spacings. Why: triangle_samples gives
/// every triangle at least a row along its longest edge, so a fan of d needles of length L (a CAD
/// cylinder's cap fanned from its centre) gets d L / h points where its area needs ~L² / h²: on a
/// closed cylinder of 20,000 rim points at 0.5%, 3.56 million net points of 3.79 million
/// candidates. On models without such fans the net is about as large as the rest (fandisk at
/// 0.5%: 67,355 of 140,110), far below the ratio, and nothing changes (BENCHMARKS.md, session 35).
inline constexpr double kNetExcess = 4;
inline constexpr double kNetThinning = 0.5;

/// What Domain::surface_candidates appended, in order: a lattice that covers the big triangles
/// (surface_lattice.h), chosen from first; random points that fill its gaps; a net of every
/// patch, chosen from last.
struct CandidateParts {
  std::size_t lattice = 0;  ///< at the front (0: none)
  std::size_t net = 0;      ///< at the back (0: none)
  /// Every point of every patch is within this distance of a net point (0: no net).
  double net_radius = 0;
};

/// The initial sample from Domain::surface_candidates' `parts`: the lattice is selected first at
/// `spacing`, then the random points, then the net, each at kGapFillSpacing × spacing with the
/// points chosen before among the fixed ones, so that random points only fill the lattice's gaps
/// and net points only what is left. Each chosen point passes select_separated_points' test, at
/// its own part's spacing, against all points chosen before it - but against the balls at
/// kBallClearance times that spacing. Indices into `candidates`;
/// `local_spacing` as there (scaled the same way). `net_decided`, if given, is set to whether
/// every net point was decided - chosen, or refused by a ball or point within its spacing - which
/// is what sample_cover_power assumes; false without a net. `ball_clearance` in (0, 1] replaces
/// kBallClearance (1: the balls at the full spacing); outside that range, nothing is chosen.
/// `stop`, if given, is asked every 65,536 candidates; true ends the selection with what was
/// chosen so far (net_decided false): a caller's time limit (MesherOptions::stop).
std::vector<std::uint32_t> select_sample(std::span<const Vec3> candidates, const CandidateParts& parts,
                                         std::span<const WeightedPoint> balls, std::span<const Vec3> fixed,
                                         double spacing, std::span<const double> local_spacing = {},
                                         bool* net_decided = nullptr, double ball_clearance = kBallClearance,
                                         const std::function<bool()>& stop = {});

/// A bound on the power distance from any point of the patches to the nearest of the balls, the fixed
/// points and the points chosen (all of them, or the triangulation's vertices that hide the
/// rest) when select_sample decided a net of radius `net_radius` at `spacing` (the net's own,
/// kGapFillSpacing × select_sample's) with the balls at `ball_clearance` k (select_sample's): a
/// patch point y is within h of a net point q, and q was chosen (power h² at most), or is within
/// s of a point (at most (s + h)²), or has power distance at most (k s)² to a ball B(c, r), whence
/// π(y, B) <= (sqrt(k² s² + r²) + h)² - r² = k² s² + h² + 2 h sqrt(k² s² + r²), at the largest ball
/// radius; the larger of the last two. With k = 1 the ball's term is the larger; kBallClearance
/// lowers the bound from 6.3 to 5.1 λ² with balls of radius λ, and the first examination skips
/// more facets.
double sample_cover_power(double spacing, double net_radius, double largest_ball_radius, double ball_clearance = 1);

}  // namespace delpsc::refine
