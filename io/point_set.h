// Reading and writing weighted point sets (the input of `delpsc triangulate` and of the CGAL
// comparison tools).
//
// Two formats, chosen by the file name:
//  - "*.bin": binary, N records of four little-endian doubles (x, y, z, w), w = r^2, no header
//    (shared/DESIGN.md). The file size must be a multiple of 32 bytes.
//  - anything else: text, one point per line, "x y z" or "x y z w"; blank lines and lines
//    starting with '#' are skipped.
// Every coordinate and weight must be finite. Errors throw io::Error naming the file and the
// record (binary) or line (text).
#pragma once

#include <string>
#include <vector>

#include <delpsc/kernel/point.h>

namespace delpsc::io {

/// Reads a point set; format by extension (see above). O(N) time and memory.
/// Throws io::Error on a missing/unreadable file, a malformed record, or a non-finite value.
std::vector<WeightedPoint> read_point_set(const std::string& path);

/// Writes a point set; "*.bin" binary, otherwise text with 17 significant digits (round-trips).
void write_point_set(const std::string& path, const std::vector<WeightedPoint>& points);

}  // namespace delpsc::io
