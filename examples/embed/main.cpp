// Embedding delpsc: reads a polygon model (the argument) or generates 1000 random points, builds
// the regular triangulation of the model's vertices (or the points) and prints its counts.
//
//   embed                  random points in the unit cube
//   embed samples/part.off the vertices of a model (OFF, OBJ, STL or PLY)
#include <cstdio>
#include <exception>
#include <vector>

#include <delpsc/delaunay/regular_triangulation.h>
#include <delpsc/io/error.h>
#include <delpsc/io/point_generators.h>
#include <delpsc/io/read_model.h>

int main(int argc, char** argv) {
  using namespace delpsc;
  std::vector<WeightedPoint> points;
  try {
    if (argc > 1) {
      const io::ReadResult model = io::read_model(argv[1]);
      std::printf("model_vertices=%zu\nmodel_triangles=%zu\n", model.soup.vertices.size(),
                  model.soup.triangles.size());
      for (const Vec3& v : model.soup.vertices) points.push_back(WeightedPoint::from(v));
    } else {
      points = io::uniform_points(1000, /*seed=*/1);
    }
  } catch (const io::Error& e) {
    std::fprintf(stderr, "embed: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "embed: %s\n", e.what());
    return 1;
  }
  delaunay::RegularTriangulation triangulation;
  triangulation.insert(points);
  std::printf("points=%zu\nvertices=%zu\nfinite_cells=%zu\nvalid=%s\n", triangulation.number_of_points(),
              triangulation.number_of_vertices(), triangulation.number_of_finite_cells(),
              triangulation.is_valid() ? "true" : "false");
  return 0;
}
