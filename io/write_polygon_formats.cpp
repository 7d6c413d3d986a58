// OFF, OBJ, binary PLY and binary STL: the triangles only (labels, edges and corners have no
// place in these formats).
#include <cmath>
#include <cstring>

#include <Eigen/Geometry>

#include "byte_order.h"
#include "error.h"
#include "mesh_formats.h"
#include "mesh_writer.h"

namespace delpsc::io::detail {

namespace {

void append_xyz(std::string& out, const Vec3& p) {
  append_number(out, p.x());
  out += ' ';
  append_number(out, p.y());
  out += ' ';
  append_number(out, p.z());
}

}  // namespace

void format_off(const SurfaceMesh& mesh, std::string& out) {
  out += "OFF\n";
  append_number(out, std::int64_t(mesh.vertices.size()));
  out += ' ';
  append_number(out, std::int64_t(mesh.triangles.size()));
  out += " 0\n";
  for (const Vec3& p : mesh.vertices) {
    append_xyz(out, p);
    out += '\n';
  }
  for (const auto& t : mesh.triangles) {
    out += '3';
    for (const std::uint32_t v : t) {
      out += ' ';
      append_number(out, v);
    }
    out += '\n';
  }
}

void format_obj(const SurfaceMesh& mesh, std::string& out) {
  out += "# written by delpsc\n";
  for (const Vec3& p : mesh.vertices) {
    out += "v ";
    append_xyz(out, p);
    out += '\n';
  }
  for (const auto& t : mesh.triangles) {
    out += 'f';
    for (const std::uint32_t v : t) {
      out += ' ';
      append_number(out, std::int64_t{v} + 1);  // OBJ counts from 1
    }
    out += '\n';
  }
}

void format_ply(const SurfaceMesh& mesh, std::string& out) {
  out += "ply\nformat binary_little_endian 1.0\ncomment written by delpsc\nelement vertex ";
  append_number(out, std::int64_t(mesh.vertices.size()));
  out += "\nproperty double x\nproperty double y\nproperty double z\nelement face ";
  append_number(out, std::int64_t(mesh.triangles.size()));
  out += "\nproperty list uchar uint vertex_indices\nend_header\n";
  out.reserve(out.size() + 24 * mesh.vertices.size() + 13 * mesh.triangles.size());
  for (const Vec3& p : mesh.vertices)
    for (int k = 0; k < 3; ++k) append_little_endian(out, p[k]);
  for (const auto& t : mesh.triangles) {
    out += char{3};
    for (const std::uint32_t v : t) append_little_endian(out, v);
  }
}

void format_stl(const SurfaceMesh& mesh, std::string& out) {
  if (mesh.triangles.size() > 0xffffffffULL)
    throw Error("binary STL holds at most 2^32 - 1 triangles");
  // The 80-byte header must not start with "solid", or naive readers take the file for ASCII.
  char header[80];
  std::memset(header, ' ', sizeof header);
  const char title[] = "binary STL written by delpsc";
  std::memcpy(header, title, sizeof title - 1);
  out.append(header, sizeof header);
  append_little_endian(out, static_cast<std::uint32_t>(mesh.triangles.size()));
  out.reserve(out.size() + 50 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3& b = mesh.vertices[t[1]];
    const Vec3& c = mesh.vertices[t[2]];
    Vec3 n = (b - a).cross(c - a);
    const double len = n.norm();
    n = len > 0 && std::isfinite(len) ? Vec3(n / len) : Vec3::Zero();
    for (int k = 0; k < 3; ++k) append_little_endian(out, static_cast<float>(n[k]));
    for (const Vec3* p : {&a, &b, &c})
      for (int k = 0; k < 3; ++k) append_little_endian(out, static_cast<float>((*p)[k]));
    append_little_endian(out, std::uint16_t{0});
  }
}

}  // namespace delpsc::io::detail

namespace delpsc::io {

std::size_t triangles_collapsed_in_float(const SurfaceMesh& mesh) {
  const auto rounded = [&](std::uint32_t v) {
    const Vec3& p = mesh.vertices[v];
    return Vec3(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()));
  };
  std::size_t collapsed = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = rounded(t[0]), b = rounded(t[1]), c = rounded(t[2]);
    // Differences of floats are exact in double as long as the two are within 2^29 of each
    // other's scale; the cross product then rounds, so a line is found up to that rounding.
    collapsed += a == b || b == c || c == a || (b - a).cross(c - a) == Vec3::Zero();
  }
  return collapsed;
}

}  // namespace delpsc::io
