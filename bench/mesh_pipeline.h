// The whole pipeline of `delpsc mesh` after reading, for the benches: the complex, its domain
// (the AABB tree), Protect's balls at λ, Mesh2Complex and the output. Returns the output's vertex
// count. λ = relative × the diagonal of the model's box (of its triangles).
#pragma once

#include <cstddef>

#include <delpsc/io/triangle_soup.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/protect.h>
#include <delpsc/refine/mesher.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/protected_balls.h>

namespace delpsc::bench {

inline std::size_t mesh_end_to_end(const io::TriangleSoup& soup, double relative) {
  const refine::PolygonDomain domain(protect::build_complex(soup));
  const double lambda = relative * domain.bounding_box().diagonal();
  protect::BallSet set = protect::protect(domain.complex(), lambda);
  refine::ProtectedBalls balls(set);
  refine::MesherOptions options;
  options.facet_size = lambda;
  refine::Mesher mesher(domain, balls, options);
  mesher.run();
  return mesher.output().vertices.size();
}

}  // namespace delpsc::bench
