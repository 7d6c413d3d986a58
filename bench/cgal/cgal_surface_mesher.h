// CGAL Mesh_3 on a polyhedral model with sharp features, as issue 6 asks for the comparison:
// Polyhedral_mesh_domain_with_features_3 on the model alone (no bounding polyhedron),
// detect_features(60), edge_size = facet_size = h, facet_distance = h/10, facet_angle = 25,
// no cell criterion, no_perturb, no_exude; the surface part of the result (the facets and
// feature edges in the complex) returned as an io::SurfaceMesh labelled with CGAL's own patch
// and curve indices.
//
// make_mesh_3 always builds a 3D triangulation; with no cell criterion (cell_radius_edge_ratio
// and cell_size left at "none") no cell is refined for its own sake, so the volume adds only
// the cost of the Delaunay triangulation of the surface points and the cell labelling, which
// any Delaunay surface mesher pays too. Single-threaded (Sequential_tag), CGAL's default
// deterministic random seed.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_polyhedron_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/make_mesh_3.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <delpsc/io/surface_mesh.h>

namespace delpsc::bench {

/// One input face of the model and the CGAL patch detect_features put it in.
struct CgalInputFace {
  std::array<Vec3, 3> corners;
  int patch = 0;
};

struct CgalSurfaceMesh {
  io::SurfaceMesh mesh;  ///< triangle_patch: CGAL's patch ids; edge_curve: CGAL's curve ids
  std::vector<CgalInputFace> input_faces;  ///< to relate CGAL's patches to ours
};

/// Reads the OFF model at `path` and meshes it with CGAL Mesh_3 at size `h` (absolute).
/// `meshed`, if given, is called once the mesh is extracted, before the input faces (which only
/// the G1 check needs) are copied: a timer stops there. Throws std::runtime_error when CGAL
/// cannot read the model as a polyhedron.
inline CgalSurfaceMesh cgal_mesh_surface(const std::string& path, double h, const std::function<void()>& meshed = {}) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Polyhedron = CGAL::Mesh_polyhedron_3<K>::type;
  using MeshDomain = CGAL::Polyhedral_mesh_domain_with_features_3<K>;
  using Tr = CGAL::Mesh_triangulation_3<MeshDomain, CGAL::Default, CGAL::Sequential_tag>::type;
  using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, MeshDomain::Corner_index, MeshDomain::Curve_index>;
  using Criteria = CGAL::Mesh_criteria_3<Tr>;
  namespace params = CGAL::parameters;

  Polyhedron polyhedron;
  std::ifstream in(path);
  if (!(in >> polyhedron) || polyhedron.empty()) throw std::runtime_error(path + ": CGAL cannot read it as a polyhedron");
  MeshDomain domain(polyhedron);
  domain.detect_features(60);
  const Criteria criteria(params::edge_size = h, params::facet_angle = 25, params::facet_size = h,
                          params::facet_distance = h / 10);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());

  CgalSurfaceMesh out;
  std::map<Tr::Vertex_handle, std::uint32_t> index;
  auto id = [&](Tr::Vertex_handle v) {
    const auto [it, fresh] = index.emplace(v, static_cast<std::uint32_t>(out.mesh.vertices.size()));
    if (fresh) {
      const auto& p = v->point().point();
      out.mesh.vertices.emplace_back(p.x(), p.y(), p.z());
    }
    return it->second;
  };
  for (auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    const auto& [cell, opposite] = *f;
    std::array<std::uint32_t, 3> t{};
    for (int k = 0, j = 0; k < 4; ++k)
      if (k != opposite) t[j++] = id(cell->vertex(k));
    out.mesh.triangles.push_back(t);
    out.mesh.triangle_patch.push_back(static_cast<std::int32_t>(c3t3.surface_patch_index(*f)));
  }
  for (auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e) {
    const auto& [cell, i, j] = *e;
    out.mesh.edges.push_back({id(cell->vertex(i)), id(cell->vertex(j))});
    out.mesh.edge_curve.push_back(static_cast<std::int32_t>(c3t3.curve_index(*e)));
  }
  for (auto v = c3t3.vertices_in_complex_begin(); v != c3t3.vertices_in_complex_end(); ++v)
    out.mesh.corners.push_back(id(v));

  if (meshed) meshed();
  const Polyhedron& stored = domain.polyhedra().front();
  const auto patch_of = get(CGAL::face_patch_id_t<int>(), stored);
  for (auto f : faces(stored)) {
    CgalInputFace face;
    auto h0 = halfedge(f, stored);
    for (int k = 0; k < 3; ++k, h0 = next(h0, stored)) {
      const auto& p = target(h0, stored)->point();
      face.corners[k] = Vec3(p.x(), p.y(), p.z());
    }
    face.patch = get(patch_of, f);
    out.input_faces.push_back(face);
  }
  return out;
}

}  // namespace delpsc::bench
