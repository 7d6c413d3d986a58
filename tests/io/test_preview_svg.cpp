// The SVG preview (io/preview_svg.h): a well-formed document with one polygon per triangle, one
// line per feature edge and one dot per corner; colours that follow the patch ids; triangles
// written back to front along the viewing direction; back faces of closed surfaces left out;
// bad meshes and options refused.
#include <doctest/doctest.h>

#include <regex>
#include <string>
#include <vector>

#include <delpsc/io/error.h>
#include <delpsc/io/preview_svg.h>
#include <delpsc/io/sample_part.h>
#include <delpsc/io/shapes.h>

#include "support/model_files.h"

using namespace delpsc;

namespace {

struct Element {
  std::string name;
  std::string fill;
};

// The elements of the document in order (name and fill), checking on the way that every tag
// is closed: a stack of open elements that must end empty.
std::vector<Element> parse_elements(const std::string& svg) {
  std::vector<Element> elements;
  std::vector<std::string> open;
  const std::regex tag(R"(<(/?)([a-zA-Z?][\w:-]*)([^>]*?)(/?)>)");
  const std::regex fill(R"re(fill="([^"]*)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), tag); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    const std::string name = m[2];
    if (name == "?xml") continue;
    if (m[1] == "/") {
      REQUIRE(!open.empty());
      CHECK(open.back() == name);
      open.pop_back();
      continue;
    }
    std::smatch f;
    const std::string attributes = m[3];
    elements.push_back({name, std::regex_search(attributes, f, fill) ? std::string(f[1]) : ""});
    if (m[4] != "/") open.push_back(name);
  }
  CHECK(open.empty());
  return elements;
}

std::vector<std::string> polygon_fills(const std::vector<Element>& elements) {
  std::vector<std::string> fills;
  for (const auto& e : elements)
    if (e.name == "polygon") fills.push_back(e.fill);
  return fills;
}

// A triangle facing the viewer, centred at c.
void add_facing_triangle(io::SurfaceMesh& mesh, const Vec3& c, const Vec3& toward_viewer, std::int32_t patch) {
  const Vec3 n = toward_viewer.normalized();
  const Vec3 u = n.cross(Vec3::UnitZ()).normalized(), v = n.cross(u);
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back(c + u);
  mesh.vertices.push_back(c + v);
  mesh.vertices.push_back(c - u - v);
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.triangle_patch.push_back(patch);
}

}  // namespace

TEST_CASE("preview: a well-formed SVG with a title, one polygon per triangle, lines and dots") {
  io::SurfaceMesh mesh = io::surface_mesh_from(io::make_sample_part(16));
  mesh.triangle_patch.assign(mesh.triangles.size(), 0);
  mesh.edges = {{0, 1}, {1, 2}};
  mesh.edge_curve = {0, 0};
  mesh.corners = {0};
  io::PreviewOptions options;
  options.title = "part <16> & co";
  const std::string svg = io::format_preview_svg(mesh, options);
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(svg.find("<title>part &lt;16&gt; &amp; co</title>") != std::string::npos);
  const auto elements = parse_elements(svg);
  REQUIRE(!elements.empty());
  CHECK(elements[0].name == "svg");
  std::size_t polygons = 0, lines = 0, circles = 0, texts = 0;
  for (const auto& e : elements) {
    polygons += e.name == "polygon";
    lines += e.name == "line";
    circles += e.name == "circle";
    texts += e.name == "text";
  }
  CHECK(polygons == mesh.triangles.size());
  CHECK(lines == 2);
  CHECK(circles == 1);
  CHECK(texts == 1);
  // Every fill is a colour.
  for (const auto& fill : polygon_fills(elements)) CHECK(std::regex_match(fill, std::regex("#[0-9a-f]{6}")));

  const std::string path = test::temp_path("preview.svg");
  io::write_preview_svg(path, mesh, options);
  CHECK(test::read_file(path) == svg);
}

TEST_CASE("preview: colours follow the patch ids") {
  // Two parallel triangles side by side (same normal, same shade, same depth).
  const io::PreviewOptions options;
  for (const bool same_patch : {true, false}) {
    io::SurfaceMesh mesh;
    add_facing_triangle(mesh, Vec3(0, 0, 0), options.toward_viewer, 3);
    add_facing_triangle(mesh, Vec3(0, 0, 5), options.toward_viewer, same_patch ? 3 : 4);
    const auto fills = polygon_fills(parse_elements(io::format_preview_svg(mesh, options)));
    REQUIRE(fills.size() == 2);
    CHECK((fills[0] == fills[1]) == same_patch);
  }
}

TEST_CASE("preview: triangles are written back to front") {
  const io::PreviewOptions options;
  const Vec3 toward = options.toward_viewer.normalized();
  // Three triangles at depths near, middle, far along the view, in a scrambled input order,
  // patches 0, 1, 2 from far to near, so the fills tell which is which.
  io::SurfaceMesh mesh;
  add_facing_triangle(mesh, 3 * toward, options.toward_viewer, 2);   // near
  add_facing_triangle(mesh, -3 * toward, options.toward_viewer, 0);  // far
  add_facing_triangle(mesh, Vec3::Zero(), options.toward_viewer, 1);
  const auto fills = polygon_fills(parse_elements(io::format_preview_svg(mesh, options)));
  REQUIRE(fills.size() == 3);
  // All three face the viewer equally: same shade, so fill k is palette colour k times it.
  io::SurfaceMesh reference;
  for (std::int32_t p = 0; p < 3; ++p) add_facing_triangle(reference, Vec3(3.0 * p, 0, 0), options.toward_viewer, p);
  const auto expected = polygon_fills(parse_elements(io::format_preview_svg(reference, options)));
  CHECK(fills == expected);
}

TEST_CASE("preview: a feature edge hidden behind a surface is drawn before it") {
  const io::PreviewOptions options;
  const Vec3 toward = options.toward_viewer.normalized();
  io::SurfaceMesh mesh;
  add_facing_triangle(mesh, 2 * toward, options.toward_viewer, 0);  // a screen in front
  mesh.vertices.push_back(-2 * toward);
  mesh.vertices.push_back(-2 * toward + Vec3(0.1, 0, 0.1));
  mesh.edges = {{3, 4}};
  const auto elements = parse_elements(io::format_preview_svg(mesh, options));
  std::vector<std::string> order;
  for (const auto& e : elements)
    if (e.name == "polygon" || e.name == "line") order.push_back(e.name);
  CHECK(order == std::vector<std::string>{"line", "polygon"});
}

TEST_CASE("preview: bad meshes and options are refused") {
  io::SurfaceMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  mesh.triangles = {{0, 1, 3}};
  CHECK_THROWS_AS(io::format_preview_svg(mesh), io::Error);
  mesh.triangles = {{0, 1, 2}};
  mesh.triangle_patch = {1, 2};
  CHECK_THROWS_AS(io::format_preview_svg(mesh), io::Error);
  mesh.triangle_patch = {1};
  io::PreviewOptions options;
  options.toward_viewer = Vec3(0, 0, 1);
  CHECK_THROWS_AS(io::format_preview_svg(mesh, options), std::invalid_argument);
  options = {};
  options.width = 10;
  CHECK_THROWS_AS(io::format_preview_svg(mesh, options), std::invalid_argument);
  CHECK(test::io_error_of([&] { io::write_preview_svg("/nonexistent-dir/x.svg", mesh); }).find("cannot open") !=
        std::string::npos);
}

TEST_CASE("preview: back faces of a closed surface are left out, those of an open one kept") {
  io::SurfaceMesh sphere = io::surface_mesh_from(io::make_sphere(8));
  auto polygons = [](const std::string& svg) {
    std::size_t n = 0;
    for (const auto& e : parse_elements(svg)) n += e.name == "polygon";
    return n;
  };
  io::PreviewOptions options;
  const std::size_t culled = polygons(io::format_preview_svg(sphere, options));
  CHECK(culled > sphere.triangles.size() / 3);
  CHECK(culled < 2 * sphere.triangles.size() / 3);
  options.skip_hidden_back_faces = false;
  CHECK(polygons(io::format_preview_svg(sphere, options)) == sphere.triangles.size());
  // The sample part (its fin makes edges of three triangles): nothing is left out.
  const io::SurfaceMesh part = io::surface_mesh_from(io::make_sample_part(16));
  CHECK(polygons(io::format_preview_svg(part, io::PreviewOptions{})) == part.triangles.size());
}
