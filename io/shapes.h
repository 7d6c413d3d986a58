// Test models generated in code, as TriangleSoups: each exercises one kind of piecewise smooth
// complex (corners of different degrees, closed curves, non-manifold curves, open sheets,
// boundary-free patches, a slit, small angles, near-touching curves, a very short curve).
//
// Every model is welded (a point shared by several faces is one vertex: all copies of it are
// computed by the same expression, so they are equal as doubles) and oriented (counter-clockwise
// seen from outside for closed models). Resolution parameters count cells per face or per unit
// of length; the generators refuse (std::invalid_argument) counts below the stated minimum, and
// the minimum keeps every smooth part's dihedral angles below 60 degrees, so that the default
// feature angle (protect::ComplexOptions) finds exactly the intended curves.
//
// The expected complex of each model with the default options (feature angle 60°, corner angle
// 60°) is given with it: corners / curves / patches.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "triangle_soup.h"

namespace delpsc::io {

/// Axis-aligned box [lo, hi] with cells[a] quads along axis a on every face (cells[a] >= 1).
/// 8 / 12 / 6, every patch a disk.
TriangleSoup make_box(const Vec3& lo, const Vec3& hi, const std::array<int, 3>& cells);

/// The cube [0, size]^3 with n x n quads per face (n >= 1). 8 / 12 / 6.
TriangleSoup make_cube(int n = 4, double size = 1);

/// A right prism over a convex polygon given counter-clockwise in the xy plane, from z = 0 to
/// z = height. Each polygon edge is cut into ceil(length / spacing) pieces, the height into
/// ceil(height / spacing); the caps are triangulated by rings around the polygon's vertex
/// centroid. Preconditions: polygon convex, counter-clockwise, >= 3 vertices, spacing > 0.
/// With m polygon vertices whose edges all meet at more than 60° (normals): 2m / 3m / m + 2.
TriangleSoup make_prism(const std::vector<Eigen::Vector2d>& polygon, double height, double spacing);

/// Cylinder of the given radius along z from 0 to height, closed by two flat discs.
/// around >= 8 segments around, along >= 1 along the axis, rings >= 1 rings on each cap.
/// 2 corners (one on each closed rim) / 2 closed curves / 3 patches: the side an annulus
/// (Euler characteristic 0, two boundary loops), the caps disks.
TriangleSoup make_capped_cylinder(double radius = 1, double height = 2, int around = 24,
                                  int along = 8, int rings = 4);

/// `sheets` (>= 1) unit squares sharing the spine {x = y = 0, 0 <= z <= 1}, the k-th one in the
/// direction at angle 360° k / sheets + 10° around z (so none is axis-aligned), n x n quads each.
/// For 3 sheets: the spine is one non-manifold curve (3 faces per edge); 8 corners (the spine's
/// ends, degree 4, and the outer corners, turning 90°) / 10 curves / 3 patches.
TriangleSoup make_book(int sheets = 3, int n = 4);

/// The unit square [0,1]^2 x {0} as an open sheet, n x n quads. With corner detection 4 / 4 / 1;
/// without (corner angle >= 180) 1 / 1 closed curve / 1.
TriangleSoup make_square_sheet(int n = 4);

/// make_square_sheet(n) (n even, >= 2) without two of the triangles at its centre that share no
/// edge and have no neighbour in common there: one patch whose triangles form two fans at the
/// centre, touching only there (a pinch, protect::Complex::pinches), its two holes' sides leaving
/// the centre, a corner, as four curves.
TriangleSoup make_pinched_sheet(int n = 4);

/// The unit disc in the plane z = 0 as an open sheet: around >= 8 boundary segments, rings >= 1.
/// 1 corner (placed on the loop) / 1 closed curve / 1 patch.
TriangleSoup make_disc_sheet(int around = 24, int rings = 4);

/// Torus with major radius R and minor radius r (R > r > 0) around z, nu >= 8 segments around
/// the axis, nv >= 8 around the tube. 0 / 0 / 1, Euler characteristic 0, no boundary.
TriangleSoup make_torus(double R = 1, double r = 0.3, int nu = 32, int nv = 16);

/// The unit sphere, from an n x n grid on each face of a cube pushed onto the sphere (n >= 2).
/// 0 / 0 / 1, Euler characteristic 2, no boundary.
TriangleSoup make_sphere(int n = 8);

/// Two unit spheres (make_sphere(n), n even, >= 2) touching at (0, 0, 1), a vertex of both: the
/// second is the first mirrored in the plane z = 1 (triangles turned to face outward). Tangent
/// sheets meeting only at a point, a corner with no curve (protect::kCornerSheets).
/// 1 / 0 / 2, one component, Euler characteristic 3, no boundary.
TriangleSoup make_touching_spheres(int n = 8);

/// A closed cone: its tip at the origin, axis +z, height 1, half-angle `half_angle_degrees` (in
/// (0, 90)), `around` >= 8 segments and `rings` >= 1 rings of its side, a base disk fanned in
/// rings too. The tip is a corner (protect::kCornerApex) below a half-angle of 30 degrees.
/// 1 or 2 corners / 1 curve / 2 patches (side and base), Euler characteristic 2.
TriangleSoup make_cone(double half_angle_degrees = 20, int around = 24, int rings = 4);

/// make_cone standing on its tip in the middle of a sheet: the unit disk in the plane z = 0
/// (`around` segments, `rings` rings), whose centre vertex is the tip. Two sheets meeting at a
/// point, the narrow side of the cone rising from it. 3 patches (side, base, disk) / 2 curves
/// (the rims) / one component, Euler characteristic 2 + 1 - 1 = 2.
TriangleSoup make_cone_on_sheet(double half_angle_degrees = 10, int around = 24, int rings = 4);

/// A unit square sheet folded back on itself: a layer at z = 0 for x in [0, 1], a half circle
/// of radius gap / 2 in `segments` pieces (180 / segments degrees a turn: with 4 or more, no
/// corner at the default 45), a layer at z = gap back to x = 0 (gap > 0, segments >= 1). Each
/// of its two boundary curves comes back within `gap` of itself. 4 corners / 4 curves / 1 patch,
/// a disk.
TriangleSoup make_hairpin_sheet(double gap = 0.03, int segments = 4);

/// The box [0,2] x [0,1] x [0,1] with an internal fin: the rectangle x = 1, 0 <= y <= 1/2,
/// 1/4 <= z <= 3/4 attached to the bottom face y = 0 along one segment (a non-manifold curve,
/// the bottom patch on both of its sides: a slit). Cells per unit length n (rounded up to a
/// multiple of 4, >= 4). 12 corners / 16 curves / 7 patches; the bottom patch has Euler
/// characteristic 0 and two boundary loops (its outline and the slit), the others are disks.
TriangleSoup make_box_with_fin(int n = 4);

/// Prism over an isosceles triangle whose apex angle is `angle_degrees` (0 < angle < 60), legs
/// of length 1, height 1/2: the edge through the apex has that dihedral angle. `spacing` as for
/// make_prism. 6 / 9 / 5.
TriangleSoup make_wedge(double angle_degrees = 10, double spacing = 0.1);

/// Two unit cubes, each turned 45° so that a ridge faces the other: the first about the x axis
/// (its top is an edge along x), the second about the z axis (its bottom is an edge along z),
/// the second above the first with the two ridges crossing at a distance of
/// gap_fraction * sqrt(3) (a fraction of one cube's diagonal). n x n quads per face.
/// 16 / 24 / 12.
TriangleSoup make_crossed_ridges(double gap_fraction = 0.01, int n = 4);

/// Prism of height 1/2 over a triangle with a 30° apex whose apex is cut off at distance
/// `cut` (0 < cut < 0.5) from it: the cut gives two curves of length 2 cut tan(15°) (one on
/// each cap), far shorter than the others when cut is small. 8 / 12 / 6.
TriangleSoup make_short_curve_prism(double cut = 1e-3, double spacing = 0.1);

/// An open sheet with a pleat, the defect of libcgal-demo's mech-holes-shark.off: a disc of
/// radius 1 in the plane z = 0 (10 boundary points, 3 rings of triangles fanned around the
/// origin O) whose boundary runs at 90°, 100°, then back to 100° - `wedge_degrees`, then on at
/// 135°, the point at 100° lifted by `rise`, the one at 100° - wedge lowered by 2 rise. So the
/// triangles from O to those two points form a strip turned over (flipped) between two folds,
/// the surface around O sweeping 360° + 2 wedge and overlapping itself in the wedge, its sheets
/// there apart by the folds (10.5° for wedge 3.3, rise 0.004), nowhere crossing. The folds are
/// feature curves. 3 corners / 4 curves / 2 patches.
TriangleSoup make_pleated_sheet(double wedge_degrees = 3.3, double rise = 0.004);

}  // namespace delpsc::io
