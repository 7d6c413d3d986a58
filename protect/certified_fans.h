// Internal to the library (protect/self_intersections.cpp, refine/polygon_domain.cpp): fans of
// triangles around a vertex whose pairs need no exact test, and a search of such a fan's
// triangles by angle (for a triangle, or a segment of the mesher's dual edges).
//
// A vertex's triangles, seen along an axis through it, cover angular sectors; when those meet
// only along edges the triangles share, any two of the triangles that share only the vertex meet
// only there, and two that share an edge only along it (the proof is at certify_fans in the
// .cpp). The check for self-intersections then tests none of a fan's own pairs (d²/2 of them
// for d triangles, all boxes overlapping: a cap of a CAD cylinder, the side of a cone), and
// tests a triangle of another fan only against the sectors its own shadow along the axis
// reaches (sectors_near).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <delpsc/kernel/point.h>

#include "complex.h"

namespace delpsc::protect::detail {

/// A certified fan: its centre (a vertex of the complex) and the axis through it, and its
/// triangles in angular order around the axis. Angles are measured, exactly, by orientations
/// about the axis: direction 0 is r's, and a point off the axis lies in the half turn [0, pi) or
/// [pi, 2 pi) by its orientation against r, on the line of r by its side of a second plane
/// through the axis (through side_point, which r is off).
struct Fan {
  struct Sector {
    std::uint32_t start, end;  ///< the triangle's other two vertices, anticlockwise about the axis
    std::uint32_t triangle;    ///< index into complex.triangles
  };
  std::uint32_t centre = 0;
  Vec3 axis_point = Vec3::Zero(), side_point = Vec3::Zero();
  std::uint32_t r = 0;  ///< the vertex whose direction is angle 0
  int r_side = 0;       ///< orient3d(centre, axis_point, side_point, r), never 0
  std::vector<Sector> sectors;  ///< sorted by start's angle; disjoint
};

/// The fans of `complex`: every vertex of at least `min_degree` triangles whose sectors are
/// proven disjoint about one of two axes (see the .cpp), or, failing that, whose triangles
/// roughly parallel to most of them are (a cap fanned from a rim vertex: the side's few
/// triangles at that vertex are then left out of `sectors`, which hold a fan's triangles, at
/// least `min_degree` of them; a triangle is in the fans that hold it, not in every fan of its
/// corners). O(d log d) exact tests per such vertex of degree d. `fan_at[v]` is v's index in
/// the result, or kNoFan.
inline constexpr std::uint32_t kNoFan = 0xffffffffu;
std::vector<Fan> certify_fans(const Complex& complex, std::size_t min_degree, std::vector<std::uint32_t>& fan_at);

/// `fan` seen about the axis through its centre and `through` (any other point), if its sectors
/// are disjoint about that axis too: a search from another fan whose centre lies on it then
/// finds few sectors for that fan's triangles (sectors_near), where an axis merely close to that
/// centre leaves the triangles' shadows around the axis, each reaching many. With `left_out`,
/// the triangles whose planes hold the new axis (at most kMostLeftOut) are taken out of the
/// result's sectors into it, for the caller to test one by one. O(d log d).
inline constexpr std::size_t kMostLeftOut = 8;
std::optional<Fan> fan_about(const Complex& complex, const Fan& fan, const Vec3& through,
                             std::vector<std::uint32_t>* left_out = nullptr);

/// Where to look for the plane most of a fan's triangles lie in or near (a cap fanned from a rim
/// vertex, with the side's few triangles there): indices into `sectors` of the one of largest
/// area (the first of equals; area from its centre and its two other vertices) and of four
/// spread evenly over them in order. Precondition: `sectors` not empty. O(d).
std::array<std::size_t, 5> reference_candidates(const Complex& complex, std::uint32_t centre,
                                                std::span<const Fan::Sector> sectors);

/// Appends to `out` the indices into fan.sectors of every sector whose closed shadow along the
/// axis may meet triangle `triangle`'s (and a few more; duplicates possible), or all of them
/// when the triangle meets the axis anywhere but, perhaps, in a vertex off the fan's centre - so
/// that a triangle of the fan not listed meets `triangle` nowhere (exact). O(log d + k) for k
/// listed: few for a triangle whose shadow is narrow seen from the axis, up to half the sectors
/// for a long thin one passing near it.
void sectors_near(const Complex& complex, const Fan& fan, const std::array<std::uint32_t, 3>& triangle,
                  std::vector<std::uint32_t>& out);
/// The same for the convex hull of two or three points given by their coordinates (a segment
/// [p, q] as {p, q}), which must lie in the predicates' exact range (kernel::in_exact_range): a
/// sector not listed holds no fan triangle that meets the hull (exact).
void sectors_near(const Complex& complex, const Fan& fan, std::span<const double* const> points,
                  std::vector<std::uint32_t>& out);

/// Appends to `out` the indices into fan.sectors of every sector whose triangle may come within
/// `distance` of point `p` (and a few more; duplicates possible), or all of them when p lies
/// within a few times `distance` of the axis: the sectors meeting the wedge that a disc of that
/// radius around p's shadow spans, seen from the axis (projection along the axis shortens no
/// distance), widened for the rounding of the wedge's constructed sides. For near contacts, which
/// the caller decides by distance: not exact, but conservative. O(log d + k) for k listed.
void sectors_within(const Complex& complex, const Fan& fan, const Vec3& p, double distance,
                    std::vector<std::uint32_t>& out);

}  // namespace delpsc::protect::detail
