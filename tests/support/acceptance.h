// The acceptance run of issue 6 on one model at one size: Protect (protecting balls at λ), then
// Mesh2Complex with facet_size λ, then every guarantee the tests can check (Dey & Levine 2009,
// §4): termination with the disk condition everywhere, G1 per patch (refine/skeleton_check.h),
// G2 per patch (each patch's Euler characteristic and boundary loops, cut open along slits, equal
// the input patch's) and G2 for the whole output (refine/complex_topology.h: components, Euler
// characteristic, boundary loops, singular curves, sheets and orientability equal the input's),
// and the triangles consistently oriented, outward where closed, each patch as the input is
// when the input is wound consistently (orientation_check.h).
// doctest CHECKs, so a failure names the model and the size.
#pragma once

#include <cstddef>
#include <string>

#include <delpsc/io/triangle_soup.h>

namespace delpsc::test {

struct AcceptanceRun {
  std::size_t vertices = 0;
  std::size_t ball_refinements = 0;
};

/// CGAL Mesh_3's two other facet criteria on top of facet_size = λ (refine/facet_criteria.h);
/// zero turns one off.
struct ExtraCriteria {
  double facet_distance_of_lambda = 0;  ///< facet_distance as a fraction of λ
  double facet_angle_degrees = 0;       ///< facet_angle
};

/// Meshes `soup` at λ = size_fraction x the bounding-box diagonal (default options plus
/// `criteria`, at most `max_vertices` vertices) and CHECKs every guarantee above. `name` labels
/// the messages.
AcceptanceRun check_acceptance(const std::string& name, const io::TriangleSoup& soup, double size_fraction,
                               std::size_t max_vertices = 300000, ExtraCriteria criteria = {});

/// The soup turned by a fixed rotation (about 1.1, 0.7 and 0.3 rad around z, y and x), so that no
/// planar patch is axis-aligned and rounded coordinates make nearly flat cells.
io::TriangleSoup rotated_model(io::TriangleSoup soup);

/// data/cgal-demo/NAME.off (fetched by scripts/get-cgal-data.sh), or an empty soup when it is
/// absent, which fails the test unless DELPSC_ALLOW_MISSING_CGAL_DATA is set (cgal_demo_data.h).
io::TriangleSoup cgal_demo_model(const std::string& name);

}  // namespace delpsc::test
