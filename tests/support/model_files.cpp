#include "support/model_files.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace delpsc::test {

std::string temp_path(const std::string& name) {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir ? dir : "/tmp") + "/delpsc_" + std::to_string(::getpid()) + "_" + name;
}

void write_file(const std::string& path, std::string_view bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

io::ReadResult read_bytes(std::string_view bytes, io::ModelFormat format) {
  static const char* names[] = {"mem.off", "mem.obj", "mem.stl", "mem.ply"};
  return io::read_model_from_memory(bytes, format, names[static_cast<int>(format)]);
}

namespace {

template <class Round>
std::vector<CornerTriangle> canonical(const io::TriangleSoup& soup, Round round) {
  std::vector<CornerTriangle> out;
  out.reserve(soup.triangles.size());
  for (const auto& t : soup.triangles) {
    CornerTriangle c;
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) c[k][d] = round(soup.vertices[t[k]][d]);
    const auto first = std::min_element(c.begin(), c.end()) - c.begin();
    std::rotate(c.begin(), c.begin() + first, c.end());
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

std::vector<CornerTriangle> canonical_triangles(const io::TriangleSoup& soup) {
  return canonical(soup, [](double x) { return x; });
}

std::vector<CornerTriangle> canonical_triangles_as_float(const io::TriangleSoup& soup) {
  return canonical(soup, [](double x) { return static_cast<double>(static_cast<float>(x)); });
}

}  // namespace delpsc::test
