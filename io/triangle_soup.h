// A polygon model as read from a file: vertices and triangles, nothing more. Readers produce it
// (polygons split into triangles, exactly duplicated vertices merged); protect::build_complex turns
// it into the piecewise smooth complex.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <delpsc/kernel/large_array.h>
#include <delpsc/kernel/point.h>

namespace delpsc::io {

struct TriangleSoup {
  kernel::LargeVector<Vec3> vertices;
  /// Vertex indices, counter-clockwise seen from the side the file calls outside.
  kernel::LargeVector<std::array<std::uint32_t, 3>> triangles;
};

}  // namespace delpsc::io
