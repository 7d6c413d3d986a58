// The sample model that ships with delpsc (samples/part.off): a machined part, generated here so
// that the file in the repository is reproducible from code (tools/make_sample_part writes it; a
// test regenerates it and compares byte for byte).
//
// The part is the block [0,4] x [0,2] x [0,1] (x, y, z) with two cylindrical through holes along
// z of radius 0.45 centred at (1, 1) and (3, 1), all edges sharp (90°), and a thin fin: the
// rectangle x = 2, 1/2 <= y <= 3/2, 1 <= z <= 8/5 standing on the top face between the holes and
// attached to it along a segment, so that three sheets meet there (a non-manifold curve, the top
// face on both of its sides).
//
// Each half of the top and bottom faces (the square around one hole) is an "O-grid": rings of
// quads from the hole's `around`-gon out to the square's outline, whose `around` points are
// evenly spaced and put the square's corners at the 45° directions. So no triangulator is
// needed, every triangle is well shaped, and the shared line x = 2 between the halves is a chain
// of mesh edges (on which the fin stands). Walls are grids of quads; all are split into two
// triangles. Vertices are welded (one index per point) and every coordinate is rounded to a
// multiple of 2^-20, so that the file does not depend on the last bit of the libm's sin and cos.
//
// Expected complex with the default options (feature angle 60°, corner angle 60°):
//  - 16 corners: 8 of the block, one on each of the 4 hole rims (closed curves), the 2 ends of
//    the fin's attachment (where the patches along the feature change) and its 2 upper corners;
//  - 20 curves: 12 block edges, 4 rims (closed), the attachment (non-manifold: 3 triangles per
//    edge), the fin's 2 sides and its top;
//  - 9 patches: the bottom (Euler characteristic -1, 3 boundary loops), the top (cut open along
//    the attachment: -2, 4 loops), 4 block sides and the fin (disks: 1, 1), 2 hole walls
//    (annuli: 0, 2).
// With around = 48 (the default): 4 368 triangles, 2 186 vertices.
#pragma once

#include "triangle_soup.h"

namespace delpsc::io {

/// The sample part described above; `around` is the number of segments of each hole's circle,
/// a multiple of 16, >= 16 (std::invalid_argument otherwise). The other resolutions follow from
/// it: around / 8 rings across each O-grid and around / 8 cells per unit of height. O(around^2) triangles.
TriangleSoup make_sample_part(int around = 48);

}  // namespace delpsc::io
