// Dropping the vertices of a model that no triangle uses, before meshing.
//
// Why: the readers keep them (read_model.h), and every step that takes the model's box from its
// vertices would take them in. A stray vertex at 1e30 beside a unit cube made the near-contact
// tolerance (a fraction of the diagonal) 1e21, and the cube was refused as touching itself; a
// dummy vertex at the origin beside a model placed at 1e9 (some exporters write one) kept the
// model from being moved near the origin (model_frame.h), and its precision with it; `delpsc
// info` reported their box and diagonal as the model's.
#pragma once

#include <cstddef>
#include <cstdint>

#include <delpsc/io/triangle_soup.h>
#include <delpsc/kernel/point.h>

namespace delpsc::io {

/// What drop_unused_vertices removed: how many, and the first (its index before, and its point).
struct UnusedVertices {
  std::size_t count = 0;
  std::uint32_t first = 0;
  Vec3 first_point = Vec3::Zero();
};

/// Removes from `soup` the vertices no triangle uses and renumbers the triangles' indices; the
/// vertices kept keep their order. Precondition: every index is below vertices.size() (as the
/// readers ensure). O(vertices + triangles) time, one byte per vertex of extra memory.
UnusedVertices drop_unused_vertices(TriangleSoup& soup);

}  // namespace delpsc::io
