// Consistent orientation of a triangle set: triangles joined across an edge that exactly two
// triangles share are oriented alike (the shared edge traversed in opposite directions) by a
// breadth-first search; a component all of whose edges have two triangles (closed) is then
// turned so that its signed volume is positive (counter-clockwise seen from outside), unless it
// lies inside an odd number of the other closed components: it then bounds a cavity, whose side
// is its outside, and faces into it (a hollow ball's inner sphere; the winding number at
// a point inside one of its triangles, asked of the components whose box holds it). Any other
// orientable component - an open sheet, or a closed surface that meets another one along a
// non-manifold edge (two cubes sharing an edge, a box with an inner wall) - has no inside of its
// own: it takes the orientation `prefer` votes for, if given. A non-orientable component keeps
// the orientation the search gave it. O(T + V) memory; time O(T + V) plus a sort of each
// vertex's edges by their other end (O(d log d) for d triangles around the vertex), plus at most
// kOrientationVotes calls of `prefer` per open component, plus, for each closed component whose
// box holds another's test point, its triangles once per such point (nothing for one closed
// component or disjoint boxes; quadratic only for many components inside one large one).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <delpsc/kernel/point.h>

namespace delpsc::refine {

/// Triangles of an open component asked for their vote, spread over the component.
inline constexpr std::size_t kOrientationVotes = 32;

/// Reorders the vertices of triangles in place; returns the number of components found
/// non-orientable. `prefer(t)`: positive when triangle t, as currently ordered, faces the way it
/// should (the input's orientation, for the mesher), negative when opposite, 0 for no opinion;
/// an open orientable component is reversed when the sum of its votes is negative.
std::size_t orient_triangles(std::span<const Vec3> vertices, std::span<std::array<std::uint32_t, 3>> triangles,
                             const std::function<int(std::uint32_t)>& prefer = {});

}  // namespace delpsc::refine
