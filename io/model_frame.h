// Moving a model that lies far from the origin next to it, without rounding a coordinate.
//
// Why: a double carries 53 bits, and a coordinate of a model placed in world coordinates (a
// building at UTM 5e6, a part at 1e9 in its assembly) spends most of them on the offset. The
// mesher's constructions - orthocentres, dual edges met with triangles - then have absolute errors
// of ulp(offset), and where that comes near the sizes it works at, it refuses its own points as
// inaccurate again and again: libcgal-demo's elephant moved by (1e9, 2e9, -3e9) ran past a minute
// at --size 3% and made 16 times the vertices it needs; the sphere moved by 1e7 failed the G1
// check by rounding alone (a vertex 1.4e-9 off the model, one ulp there). Meshing the model in a
// frame near its own box, then adding the offset back when writing, keeps every bit for the shape.
//
// Exactness: per axis, the offset is the box's bound nearest the origin, and an axis moves only
// when that bound is at least kFarFromOriginRatio diagonals away. Every coordinate on the axis then
// lies within a factor of two of the bound (same sign), so each difference x - offset is exact
// (Sterbenz's lemma; the code checks the factor of two too): the moved model is the file's model,
// translated, with no vertex moved relative to another. Adding the offset back rounds to the
// file's own precision (the output is written in the file's frame), which no mesher can avoid.
#pragma once

#include <span>

#include <delpsc/kernel/point.h>

namespace delpsc::io {

/// An axis moves when its bound nearest the origin is at least this many times the model's
/// bounding-box diagonal away (4 bits of every coordinate spent on the offset).
inline constexpr double kFarFromOriginRatio = 16;

/// Subtracts from every point, per axis, the bound of their box nearest the origin, on the axes
/// where that is exact (see above) and the bound is at least kFarFromOriginRatio diagonals away;
/// returns what was subtracted (zero on the other axes, and for an empty or non-finite set).
/// Adding the result back restores the input exactly. O(n).
Vec3 move_near_origin(std::span<Vec3> points);

/// Adds `offset` to every point (to write what was meshed near the origin in the file's frame).
/// O(n); nothing when offset is zero.
void move_by(std::span<Vec3> points, const Vec3& offset);

}  // namespace delpsc::io
