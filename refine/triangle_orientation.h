// Consistent orientation of a triangle set: triangles joined across an edge that exactly two
// triangles share are oriented alike (the shared edge traversed in opposite directions) by a
// breadth-first search; a component all of whose edges have two triangles (closed) is then
// turned so that its signed volume is positive (counter-clockwise seen from outside). A
// non-orientable component keeps the orientation the search gave it. O(T + V) memory; time
// O(T + V) plus a sort of each vertex's edges by their other end (O(d log d) for d triangles
// around the vertex).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <delpsc/kernel/point.h>

namespace delpsc::refine {

/// Reorders the vertices of triangles in place; returns the number of components found
/// non-orientable.
std::size_t orient_triangles(std::span<const Vec3> vertices, std::span<std::array<std::uint32_t, 3>> triangles);

}  // namespace delpsc::refine
