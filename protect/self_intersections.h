// Self-intersections of the input: pairs of triangles that meet other than in a vertex or an edge
// they share. DelPSC meshes a piecewise smooth complex (Dey & Levine 2009, §1.1), whose patches
// meet only along its curves and corners; two sheets crossing each other along a line that is no
// curve of the complex are not one, the disk condition can never hold along that line (§3: the
// restricted triangles around a point of it form no disk), and refinement would go on until
// memory runs out. So the commands reject such input up front, naming the triangles.
//
// Every decision is exact (orient3d, coplanar orientations and the exact segment/triangle
// classification of kernel/constructions.h): touching counts as meeting, however slightly.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/point.h>
#include <delpsc/protect/complex.h>

namespace delpsc::protect {

/// True iff the closed non-degenerate triangles a and b meet in a point that is not a vertex or
/// an edge they share - a common vertex is one with the same index in `ia` and `ib` (vertices are
/// welded, so equal positions have equal indices). Triangles with all three vertices in common
/// (a duplicate) intersect. Preconditions: neither triangle is degenerate (collinear). Exact.
bool triangles_intersect_improperly(const std::array<Vec3, 3>& a, const std::array<std::uint32_t, 3>& ia,
                                    const std::array<Vec3, 3>& b, const std::array<std::uint32_t, 3>& ib);

/// For a pair for which triangles_intersect_improperly holds: a point where they meet other than
/// at a vertex or edge they share, for a message to point at (rounded: within a few ulps of the
/// contact, not exact), or nullopt when none is found that way (then, say, a centroid will do).
/// Each triangle's edges against the other (intersect_segment_triangle): the crossing point, or
/// for an edge lying in the other's plane, the ends and middle of the overlap, the first of them
/// not on a shared vertex or edge (within 1e-9 of the pair's size).
std::optional<Vec3> improper_contact_point(const std::array<Vec3, 3>& a, const std::array<std::uint32_t, 3>& ia,
                                           const std::array<Vec3, 3>& b, const std::array<std::uint32_t, 3>& ib);

/// Pairs of triangles of `complex` (indices into complex.triangles, first < second, sorted) that
/// intersect improperly, at most `max_pairs` of them (the search stops there). An AABB tree finds
/// the pairs whose boxes overlap; each is decided exactly, except the pairs inside a certified
/// fan (16 or more triangles around a vertex whose angular sectors, seen along an axis through
/// it, are proven disjoint, exactly, once: a flat fan, the side of a cone around its apex), which
/// the descent leaves out; pairs across two such fans are found by angle about one fan's axis
/// instead (the side of a cone and its base fanned from the centre: a few pairs per triangle
/// rather than d² of them). O(T log T + K) time for T triangles and K box-overlapping pairs not
/// inside fans (about 15 per triangle on a clean mesh; a fan's triangles against long thin
/// triangles of no fan whose boxes overlap theirs count, as a cone's side against a base
/// triangulated in one strip); O(T) memory.
std::vector<std::array<std::uint32_t, 2>> find_self_intersections(const Complex& complex,
                                                                  std::size_t max_pairs = 100);
/// The same with `tree` an AabbTree over complex.vertices and complex.triangles, built once by a
/// caller that runs both checks of this file.
std::vector<std::array<std::uint32_t, 2>> find_self_intersections(const Complex& complex, const kernel::AabbTree& tree,
                                                                  std::size_t max_pairs);

/// A vertex of `complex` (one some triangle uses) and a triangle not incident to it at a distance
/// below `tolerance` but not exactly 0 (touching is a self-intersection above; a distance that
/// rounds to 0 is decided by the exact test), or nullopt: a surface
/// that comes that close to itself has a feature that small, which refinement resolves only by
/// sampling at that scale (a tetrahedron 1e-15 thick refined for minutes towards the vertex
/// cap). The smallest such (vertex, triangle) pair. Distances in floating point
/// (closest_point_on_triangle); the AABB tree pairs each triangle with those within about
/// `tolerance` of it.
std::optional<std::array<std::uint32_t, 2>> find_near_contact(const Complex& complex, double tolerance);
/// The same with a tree built by the caller, as for find_self_intersections.
std::optional<std::array<std::uint32_t, 2>> find_near_contact(const Complex& complex, const kernel::AabbTree& tree,
                                                               double tolerance);

/// Both checks above from one descent of `tree` (an AabbTree over complex.vertices and
/// complex.triangles): `crossing` is find_self_intersections(complex, tree, max_pairs) and
/// `near_contact` find_near_contact(complex, tree, tolerance). max_pairs 0 skips the first,
/// a tolerance that is not positive the second. Cost as find_self_intersections, the pairs
/// found with boxes grown by the tolerance.
/// The near contacts between triangles of certified fans are found per fan instead, by angle
/// about its axis for each vertex near it; a fan whose own triangles' boxes meet many more
/// triangles than its box holds (a cap fanned from a rim point: long chords) is searched whole,
/// by angle, against the triangles of no fan. `stop` (optional) is asked every 4,096
/// box-overlapping pairs (and 4,096 vertices near fans, 4,096 triangles and sectors searched
/// across fans, and before each fan is turned towards another); when it answers true the search
/// ends there with `stopped` set and what it found so far (a cone of 20,000 rim points on a base
/// triangulated in one strip of thin triangles makes 10^8 pairs, seconds).
/// `which`: CrossingPairs::smallest keeps the max_pairs smallest crossing pairs (what a scan in
/// order would give, whatever order the descent finds them in: a caller naming pairs); with
/// CrossingPairs::first_found the search ends as soon as max_pairs crossing pairs are found, any
/// of them, for a caller that reports only how many there are up to max_pairs (that count is
/// the same either way). The smallest pairs cost every box-overlapping pair even once max_pairs
/// are found: a triangle listed 200,000 times makes 2*10^10 pairs of copies, all crossing, while
/// the first found are found at once. (With a positive tolerance the search still runs to its
/// end, for the near contact.)
enum class CrossingPairs { smallest, first_found };
struct InputDefects {
  std::vector<std::array<std::uint32_t, 2>> crossing;
  std::optional<std::array<std::uint32_t, 2>> near_contact;
  bool stopped = false;
};
InputDefects find_input_defects(const Complex& complex, const kernel::AabbTree& tree, std::size_t max_pairs,
                                double tolerance, const std::function<bool()>& stop = {},
                                CrossingPairs which = CrossingPairs::smallest);

}  // namespace delpsc::protect
