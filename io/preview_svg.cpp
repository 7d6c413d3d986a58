#include "preview_svg.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "error.h"
#include "hidden_faces.h"
#include "output_file.h"

namespace delpsc::io {

namespace {

// Twelve colours told apart by most viewers (the "Tableau 10" hues plus two), light enough
// that shading keeps them apart; patch id modulo 12.
constexpr std::array<std::array<int, 3>, 12> kPalette{{{78, 121, 167},
                                                       {242, 142, 43},
                                                       {225, 87, 89},
                                                       {118, 183, 178},
                                                       {89, 161, 79},
                                                       {237, 201, 72},
                                                       {176, 122, 161},
                                                       {255, 157, 167},
                                                       {156, 117, 95},
                                                       {186, 176, 172},
                                                       {134, 188, 226},
                                                       {199, 224, 120}}};
constexpr std::array<int, 3> kUnlabelled{170, 170, 170};
constexpr const char* kFeatureColour = "#1a1a1a";
constexpr double kMargin = 16, kTitleHeight = 28;
constexpr double kAmbient = 0.35;  // so faces turned away from the light keep their hue

std::string escape_xml(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

void append_format(std::string& out, const char* format, auto... args) {
  char buf[160];
  const int n = std::snprintf(buf, sizeof buf, format, args...);
  out.append(buf, static_cast<std::size_t>(std::clamp(n, 0, static_cast<int>(sizeof buf) - 1)));
}

// The camera: screen axes right and up, depth growing away from the viewer.
struct View {
  Vec3 right, up, forward;
};

View make_view(const Vec3& toward_viewer) {
  if (!(toward_viewer.norm() > 0) || !toward_viewer.allFinite())
    throw std::invalid_argument("io::format_preview_svg: toward_viewer must be a non-zero finite vector");
  const Vec3 forward = -toward_viewer.normalized();
  const Vec3 right_raw = forward.cross(Vec3::UnitZ());
  if (right_raw.norm() < 1e-9)
    throw std::invalid_argument("io::format_preview_svg: toward_viewer must not be vertical");
  const Vec3 right = right_raw.normalized();
  return {right, right.cross(forward), forward};
}

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

// One thing to draw, in painter's order.
struct Item {
  double depth;
  enum Kind : std::uint8_t { kTriangle, kEdge, kCorner } kind;
  std::uint32_t index;
};

}  // namespace

std::string format_preview_svg(const SurfaceMesh& mesh, const PreviewOptions& options) {
  if (options.width < 64) throw std::invalid_argument("io::format_preview_svg: width must be >= 64");
  const View view = make_view(options.toward_viewer);
  const std::size_t n = mesh.vertices.size();
  auto check_index = [&](std::uint32_t v, const char* what, std::size_t i) {
    if (v >= n)
      throw Error("preview: " + std::string(what) + " " + std::to_string(i) + " uses vertex " +
                  std::to_string(v) + " of " + std::to_string(n));
  };
  if (!mesh.triangle_patch.empty() && mesh.triangle_patch.size() != mesh.triangles.size())
    throw Error("preview: triangle_patch and triangles differ in size");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const auto v : mesh.triangles[t]) check_index(v, "triangle", t);
  for (std::size_t e = 0; e < mesh.edges.size(); ++e)
    for (const auto v : mesh.edges[e]) check_index(v, "edge", e);
  for (std::size_t c = 0; c < mesh.corners.size(); ++c) check_index(mesh.corners[c], "corner", c);

  // Project the vertices that are drawn; fit them into the picture.
  std::vector<bool> used(n, false);
  for (const auto& t : mesh.triangles)
    for (const auto v : t) used[v] = true;
  for (const auto& e : mesh.edges) used[e[0]] = used[e[1]] = true;
  for (const auto v : mesh.corners) used[v] = true;
  std::vector<double> sx(n), sy(n), depth(n);
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  for (std::size_t v = 0; v < n; ++v) {
    if (!used[v]) continue;
    const Vec3& p = mesh.vertices[v];
    sx[v] = p.dot(view.right), sy[v] = p.dot(view.up), depth[v] = p.dot(view.forward);
    xmin = std::min(xmin, sx[v]), xmax = std::max(xmax, sx[v]);
    ymin = std::min(ymin, sy[v]), ymax = std::max(ymax, sy[v]);
  }
  const double width = options.width, drawable = width - 2 * kMargin;
  // Fill the width; a tall model is shrunk to keep the height within twice the width.
  double scale = 1, height = kTitleHeight + 2 * kMargin;
  if (xmax >= xmin) {
    const double dx = xmax - xmin, dy = ymax - ymin;
    scale = dx > 0 ? drawable / dx : dy > 0 ? drawable / dy : 1;
    if (dy * scale > 2 * width) scale = 2 * width / dy;
    height += dy * scale;
  }
  const double x0 = kMargin + (drawable - (xmax - xmin) * scale) / 2;
  auto px = [&](std::uint32_t v) { return x0 + (sx[v] - xmin) * scale; };
  auto py = [&](std::uint32_t v) { return kTitleHeight + kMargin + (ymax - sy[v]) * scale; };

  // Painter's order. A feature edge or corner is drawn just in front of the nearest vertex of
  // the triangles around it, so the triangles it bounds never paint over it, while a surface
  // in front of it (nearer than its whole neighbourhood) still does.
  std::vector<Item> items;
  items.reserve(mesh.triangles.size() + mesh.edges.size() + mesh.corners.size());
  std::unordered_map<std::uint64_t, double> edge_front;
  std::vector<double> vertex_front(depth);
  const std::vector<bool> hidden = options.skip_hidden_back_faces ? hidden_back_faces(mesh, options.toward_viewer)
                                                                  : std::vector<bool>(mesh.triangles.size(), false);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const double front = std::min({depth[tri[0]], depth[tri[1]], depth[tri[2]]});
    // A hidden triangle is not drawn; it still counts in the depths of the features it bounds.
    if (!hidden[t]) items.push_back({(depth[tri[0]] + depth[tri[1]] + depth[tri[2]]) / 3, Item::kTriangle, t});
    for (int k = 0; k < 3; ++k) {
      vertex_front[tri[k]] = std::min(vertex_front[tri[k]], front);
      const auto [it, inserted] = edge_front.try_emplace(edge_key(tri[k], tri[(k + 1) % 3]), front);
      if (!inserted) it->second = std::min(it->second, front);
    }
  }
  const double bias = 1e-6 * std::max(xmax - xmin, ymax - ymin);
  for (std::uint32_t e = 0; e < mesh.edges.size(); ++e) {
    const auto [a, b] = mesh.edges[e];
    double d = std::min(depth[a], depth[b]);
    if (const auto it = edge_front.find(edge_key(a, b)); it != edge_front.end()) d = std::min(d, it->second);
    items.push_back({d - bias, Item::kEdge, e});
  }
  for (std::uint32_t c = 0; c < mesh.corners.size(); ++c)
    items.push_back({vertex_front[mesh.corners[c]] - 2 * bias, Item::kCorner, c});
  // Far to near; ties keep input order so the output is deterministic.
  std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.depth > b.depth; });

  // Light from above-left of the viewer; two-sided Lambert.
  const Vec3 light = (-view.forward + 0.6 * view.up - 0.4 * view.right).normalized();
  std::string out;
  out.reserve(200 + 90 * items.size());
  append_format(out,
                "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
                "viewBox=\"0 0 %.0f %.0f\">\n",
                width, std::ceil(height), width, std::ceil(height));
  const std::string title = escape_xml(options.title);
  out += "<title>" + title + "</title>\n";
  out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  append_format(out, "<text x=\"%.0f\" y=\"%.0f\" font-family=\"sans-serif\" font-size=\"15\">", kMargin,
                kTitleHeight - 8);
  out += title + "</text>\n";
  // Each triangle is also stroked, in its own fill colour: it hides the hairline seams
  // anti-aliasing leaves between neighbours; or, to show the triangulation, darker.
  double drawn_area = 0;
  std::size_t drawn = 0;
  for (const Item& item : items)
    if (item.kind == Item::kTriangle) {
      const auto& tri = mesh.triangles[item.index];
      drawn_area += std::abs((px(tri[1]) - px(tri[0])) * (py(tri[2]) - py(tri[0])) -
                             (px(tri[2]) - px(tri[0])) * (py(tri[1]) - py(tri[0]))) / 2;
      ++drawn;
    }
  constexpr double kMinOutlinedArea = 12;  // px² on average
  const double outline_shade =
      options.outline_triangles && drawn > 0 && drawn_area >= kMinOutlinedArea * static_cast<double>(drawn) ? 0.8 : 1;
  out += "<g stroke-linejoin=\"round\" stroke-linecap=\"round\" stroke-width=\"0.6\">\n";
  for (const Item& item : items) {
    if (item.kind == Item::kTriangle) {
      const auto& tri = mesh.triangles[item.index];
      const Vec3 normal = (mesh.vertices[tri[1]] - mesh.vertices[tri[0]]).cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
      const double lambert = normal.norm() > 0 ? std::abs(normal.normalized().dot(light)) : 0;
      const double shade = kAmbient + (1 - kAmbient) * lambert;
      const auto& base = mesh.triangle_patch.empty()
                             ? kUnlabelled
                             : kPalette[static_cast<std::size_t>(
                                   (mesh.triangle_patch[item.index] % 12 + 12) % 12)];
      char colour[8], stroke[8];
      std::snprintf(colour, sizeof colour, "#%02x%02x%02x", static_cast<int>(base[0] * shade),
                    static_cast<int>(base[1] * shade), static_cast<int>(base[2] * shade));
      const double s = shade * outline_shade;
      std::snprintf(stroke, sizeof stroke, "#%02x%02x%02x", static_cast<int>(base[0] * s),
                    static_cast<int>(base[1] * s), static_cast<int>(base[2] * s));
      append_format(out, "<polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"%s\" stroke=\"%s\"/>\n",
                    px(tri[0]), py(tri[0]), px(tri[1]), py(tri[1]), px(tri[2]), py(tri[2]), colour, stroke);
    } else if (item.kind == Item::kEdge) {
      const auto [a, b] = mesh.edges[item.index];
      append_format(out, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"2\"/>\n",
                    px(a), py(a), px(b), py(b), kFeatureColour);
    } else {
      const std::uint32_t v = mesh.corners[item.index];
      append_format(out, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" fill=\"%s\"/>\n", px(v), py(v), kFeatureColour);
    }
  }
  out += "</g>\n</svg>\n";
  return out;
}

void write_preview_svg(const std::string& path, const SurfaceMesh& mesh, const PreviewOptions& options) {
  std::string svg;
  try {
    svg = format_preview_svg(mesh, options);
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
  write_output_file(path, svg);
}

}  // namespace delpsc::io
