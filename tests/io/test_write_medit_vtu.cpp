// Medit and VTU have no reader in io/ (nothing reads them back as input), so these tests parse
// the written text themselves: every section and array is checked against the mesh.
#include <doctest/doctest.h>

#include <map>
#include <sstream>

#include <delpsc/io/mesh_writer.h>

#include "support/model_files.h"

using namespace delpsc;

namespace {

/// A square split into two triangles of two patches, its four sides as two curves, two corners.
io::SurfaceMesh labelled_square() {
  io::SurfaceMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.125}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.triangle_patch = {4, -2};
  m.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  m.edge_curve = {0, 0, 7, 7};
  m.corners = {0, 2};
  return m;
}

/// Medit sections: keyword -> rows of numbers.
std::map<std::string, std::vector<std::vector<double>>> parse_medit(const std::string& text) {
  std::istringstream in(text);
  std::map<std::string, std::vector<std::vector<double>>> sections;
  const std::map<std::string, int> columns = {{"Vertices", 4}, {"Triangles", 4}, {"Edges", 3}, {"Corners", 1}};
  std::string word;
  while (in >> word) {
    if (word == "MeshVersionFormatted" || word == "Dimension") {
      double v;
      in >> v;
      sections[word] = {{v}};
    } else if (word == "End") {
      sections[word] = {};
    } else {
      REQUIRE_MESSAGE(columns.count(word), word);
      std::size_t n = 0;
      in >> n;
      auto& rows = sections[word];
      for (std::size_t i = 0; i < n; ++i) {
        rows.emplace_back(columns.at(word));
        for (double& x : rows.back()) in >> x;
      }
      REQUIRE(in);
    }
  }
  return sections;
}

/// The text of the DataArray named `name` in a VTU file, as numbers.
std::vector<double> vtu_array(const std::string& text, const std::string& name) {
  const std::size_t at = text.find("Name=\"" + name + "\"");
  REQUIRE_MESSAGE(at != std::string::npos, name);
  const std::size_t begin = text.find('>', at) + 1;
  const std::size_t end = text.find("</DataArray>", begin);
  std::istringstream in(text.substr(begin, end - begin));
  std::vector<double> values;
  for (double v; in >> v;) values.push_back(v);
  return values;
}

}  // namespace

TEST_CASE("Medit: vertices, triangles by patch, edges by curve, corners, 1-based") {
  const io::SurfaceMesh m = labelled_square();
  const auto s = parse_medit(io::format_mesh(m, io::MeshFormat::medit));
  CHECK(s.at("MeshVersionFormatted")[0][0] == 2);
  CHECK(s.at("Dimension")[0][0] == 3);
  CHECK(s.count("End") == 1);
  REQUIRE(s.at("Vertices").size() == 4);
  for (std::size_t i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) CHECK(s.at("Vertices")[i][k] == m.vertices[i][k]);
  REQUIRE(s.at("Triangles").size() == 2);
  for (std::size_t t = 0; t < 2; ++t) {
    for (int k = 0; k < 3; ++k) CHECK(s.at("Triangles")[t][k] == m.triangles[t][k] + 1);
    CHECK(s.at("Triangles")[t][3] == m.triangle_patch[t]);
  }
  REQUIRE(s.at("Edges").size() == 4);
  for (std::size_t e = 0; e < 4; ++e) {
    CHECK(s.at("Edges")[e][0] == m.edges[e][0] + 1);
    CHECK(s.at("Edges")[e][2] == m.edge_curve[e]);
  }
  REQUIRE(s.at("Corners").size() == 2);
  CHECK(s.at("Corners")[1][0] == 3);
}

TEST_CASE("Medit: unlabelled triangles get reference 0, empty sections are left out") {
  io::SurfaceMesh m = labelled_square();
  m.triangle_patch.clear();
  m.edges.clear();
  m.edge_curve.clear();
  m.corners.clear();
  const auto s = parse_medit(io::format_mesh(m, io::MeshFormat::medit));
  CHECK(s.at("Triangles")[1][3] == 0);
  CHECK(s.count("Edges") == 0);
  CHECK(s.count("Corners") == 0);
}

TEST_CASE("VTU: triangles, edges and corners as cells with patch / curve / dimension data") {
  const io::SurfaceMesh m = labelled_square();
  const std::string path = test::temp_path("square.vtu");
  io::write_mesh(path, m);
  const std::string text = test::read_file(path);
  std::remove(path.c_str());
  CHECK(text.find("<VTKFile type=\"UnstructuredGrid\"") != std::string::npos);
  CHECK(text.find("NumberOfPoints=\"4\" NumberOfCells=\"8\"") != std::string::npos);
  // Balanced tags: every opened DataArray is closed.
  std::size_t opened = 0, closed = 0;
  for (std::size_t p = 0; (p = text.find("<DataArray", p)) != std::string::npos; ++p) ++opened;
  for (std::size_t p = 0; (p = text.find("</DataArray>", p)) != std::string::npos; ++p) ++closed;
  CHECK(opened == 7);
  CHECK(closed == 7);
  CHECK(text.ends_with("</VTKFile>\n"));

  const auto points = vtu_array(text, "Points");
  REQUIRE(points.size() == 12);
  CHECK(points[11] == 0.125);
  CHECK(vtu_array(text, "connectivity") ==
        std::vector<double>{0, 1, 2, 0, 2, 3, 0, 1, 1, 2, 2, 3, 3, 0, 0, 2});
  CHECK(vtu_array(text, "offsets") == std::vector<double>{3, 6, 8, 10, 12, 14, 15, 16});
  CHECK(vtu_array(text, "types") == std::vector<double>{5, 5, 3, 3, 3, 3, 1, 1});
  CHECK(vtu_array(text, "patch") == std::vector<double>{4, -2, -1, -1, -1, -1, -1, -1});
  CHECK(vtu_array(text, "curve") == std::vector<double>{-1, -1, 0, 0, 7, 7, -1, -1});
  CHECK(vtu_array(text, "dimension") == std::vector<double>{2, 2, 1, 1, 1, 1, 0, 0});
}
