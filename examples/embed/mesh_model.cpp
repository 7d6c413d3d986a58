// Meshing a model with the library, as the README shows it: read, protect, refine, write, and
// check guarantee G1 on the result. The tests build it against the installed package and compare
// its counts with `delpsc mesh` on the same model (tests/app/test_install.sh).
//
//   mesh_model IN OUT [SIZE]   SIZE: a fraction of the bounding-box diagonal (default 0.02)
#include <cstdio>
#include <cstdlib>
#include <exception>

#include <delpsc/io/mesh_writer.h>
#include <delpsc/io/read_model.h>
#include <delpsc/protect/protect.h>
#include <delpsc/refine/mesher.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/protected_balls.h>
#include <delpsc/refine/skeleton_check.h>

int main(int argc, char** argv) {
  using namespace delpsc;
  if (argc < 3) {
    std::fprintf(stderr, "usage: mesh_model IN OUT [SIZE]\n");
    return 2;
  }
  try {
    // --- the README's dozen lines ---
    const io::ReadResult model = io::read_model(argv[1]);                   // OFF, OBJ, STL or PLY
    const refine::PolygonDomain domain(model.soup);                         // its corners, curves, patches
    const kernel::Box3 box = domain.bounding_box();
    const double lambda = (argc > 3 ? std::atof(argv[3]) : 0.02) * (box.hi - box.lo).norm();
    protect::BallSet balls = protect::protect(domain.complex(), lambda);   // step 1: protecting balls
    refine::ProtectedBalls ball_source(balls);
    refine::MesherOptions options;
    options.facet_size = lambda;
    refine::Mesher mesher(domain, ball_source, options);
    mesher.run();                                                           // step 2: until the disk condition holds
    const io::SurfaceMesh mesh = mesher.output();
    io::write_mesh(argv[2], mesh);                                          // step 3: patches and curves labelled
    // --- and G1 on the result ---
    const refine::SkeletonReport g1 = refine::check_skeleton(mesh, domain, 1e-9 * (box.hi - box.lo).norm());
    std::printf("vertices=%zu\ntriangles=%zu\ng1=%s\n", mesh.vertices.size(), mesh.triangles.size(),
                g1.ok() ? "true" : "false");
    return g1.ok() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mesh_model: %s\n", e.what());
    return 2;
  }
}
