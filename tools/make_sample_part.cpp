// Writes the sample part (io/sample_part.h) at its default resolution to the file named by the
// one argument: how samples/part.off is made. A ctest test (tools/CMakeLists.txt) reruns it and
// compares the output with the committed file byte for byte.
#include <cstdio>
#include <exception>

#include <delpsc/io/mesh_writer.h>
#include <delpsc/io/sample_part.h>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT.off (or any format of io::write_mesh)\n", argv[0]);
    return 2;
  }
  try {
    const delpsc::io::TriangleSoup part = delpsc::io::make_sample_part();
    delpsc::io::write_mesh(argv[1], delpsc::io::surface_mesh_from(part));
    std::printf("%s: %zu vertices, %zu triangles\n", argv[1], part.vertices.size(), part.triangles.size());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
    return 1;
  }
  return 0;
}
