// Points spread over a triangle so that every point of it is within a distance h of one of them
// or of a corner: the surface samples of the approximation error (approximation_error.h) and the
// net that lets the mesher prove its initial sample covers every patch (initial_sample.h).
//
// Layout: rows parallel to the longest edge, from it towards the opposite corner, at most
// (sqrt(3) / 2) h apart, each row cut into equal pieces of length <= h. A needle triangle gets
// ~area / h² points, where a barycentric grid of step longest edge / h would get
// ~(longest edge / h)².
//
// Units: lengths of the coordinates. Preconditions: none (bad input gives no points).
#pragma once

#include <cstddef>
#include <vector>

#include <delpsc/kernel/large_array.h>
#include <delpsc/kernel/point.h>

namespace delpsc::refine {

/// Pieces of length <= h a segment of `length` is cut into: ceil(length / h), at least 1.
std::size_t sample_pieces(double length, double h);

/// The samples of triangle abc other than its corners, appended to `out`: every point of the
/// triangle is within h of one of them or of a corner. O(area / h² + perimeter / h + 1) points;
/// none for a triangle reduced to a point, a coordinate or h not finite, or h <= 0.
void triangle_samples(const Vec3& a, const Vec3& b, const Vec3& c, double h, kernel::LargeVector<Vec3>& out);

/// How many points triangle_samples(a, b, c, h, ...) appends, without making them: O(1 + height
/// / h) time however long the triangle is, for a caller that must bound its memory first. The
/// count is a double because a needle may need more than 2^64 of them; 0 when it appends none.
double triangle_sample_count(const Vec3& a, const Vec3& b, const Vec3& c, double h);

}  // namespace delpsc::refine
