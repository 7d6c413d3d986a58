// build_complex: the steps of complex.h in order; each lives in its own file.
#include "complex.h"

#include <cmath>
#include <stdexcept>

#include "complex_build.h"

namespace delpsc::protect {

std::size_t Complex::closed_curve_count() const {
  std::size_t n = 0;
  for (const auto& c : curves) n += c.closed ? 1 : 0;
  return n;
}

std::size_t Complex::patches_without_boundary() const {
  std::size_t n = 0;
  for (const auto& p : patches) n += p.boundary_loops == 0 ? 1 : 0;
  return n;
}

Complex build_complex(const io::TriangleSoup& soup, const ComplexOptions& options) {
  if (!(options.feature_angle_degrees >= 0 && options.feature_angle_degrees <= 180))
    throw std::invalid_argument("build_complex: the feature angle must be in [0, 180] degrees");
  if (!(options.corner_angle_degrees >= 0))
    throw std::invalid_argument("build_complex: the corner angle must be >= 0 degrees");
  Complex complex;
  complex.options = options;
  const kernel::LargeVector<std::uint32_t> canonical = detail::clean_triangles(soup, complex);
  detail::build_edge_table(complex);
  complex.cleanup.t_junctions = detail::heal_t_junctions(complex);
  detail::find_duplicate_triangles(complex);
  detail::classify_feature_edges(complex, canonical);
  const detail::VertexFans fans = detail::find_patches(complex);
  detail::find_corners_and_curves(complex, fans);
  detail::link_incidences(complex, fans);
  detail::describe_pinch_fans(complex);
  return complex;
}

}  // namespace delpsc::protect
