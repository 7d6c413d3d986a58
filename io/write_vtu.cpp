// VTK XML UnstructuredGrid (.vtu), ASCII, for ParaView: one grid holding the triangles, the
// feature edges and the corners as cells, so "Threshold" on the cell data separates the strata
// of the complex and "patch" / "curve" colour them.
#include "mesh_formats.h"

namespace delpsc::io::detail {

namespace {

// VTK cell type codes (vtkCellType.h).
constexpr int kVtkVertex = 1;
constexpr int kVtkLine = 3;
constexpr int kVtkTriangle = 5;

void open_array(std::string& out, const char* type, const char* name, int components = 1) {
  out += "        <DataArray type=\"";
  out += type;
  out += "\" Name=\"";
  out += name;
  out += '"';
  if (components != 1) {
    out += " NumberOfComponents=\"";
    append_number(out, components);
    out += '"';
  }
  out += " format=\"ascii\">\n";
}

void close_array(std::string& out) { out += "\n        </DataArray>\n"; }

/// One value per cell: triangles, then edges, then corners.
template <class TriangleValue, class EdgeValue>
void cell_array(std::string& out, const char* name, const SurfaceMesh& m, TriangleValue tri,
                EdgeValue edge, std::int32_t corner) {
  open_array(out, "Int32", name);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    append_number(out, tri(t));
    out += ' ';
  }
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    append_number(out, edge(e));
    out += ' ';
  }
  for (std::size_t c = 0; c < m.corners.size(); ++c) {
    append_number(out, corner);
    out += ' ';
  }
  close_array(out);
}

}  // namespace

void format_vtu(const SurfaceMesh& m, std::string& out) {
  const std::size_t cells = m.triangles.size() + m.edges.size() + m.corners.size();
  out += "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"";
  append_number(out, std::int64_t(m.vertices.size()));
  out += "\" NumberOfCells=\"";
  append_number(out, std::int64_t(cells));
  out += "\">\n      <Points>\n";
  open_array(out, "Float64", "Points", 3);
  for (const Vec3& p : m.vertices)
    for (int k = 0; k < 3; ++k) {
      append_number(out, p[k]);
      out += ' ';
    }
  close_array(out);
  out += "      </Points>\n      <Cells>\n";

  open_array(out, "Int64", "connectivity");
  for (const auto& t : m.triangles)
    for (const std::uint32_t v : t) {
      append_number(out, v);
      out += ' ';
    }
  for (const auto& e : m.edges)
    for (const std::uint32_t v : e) {
      append_number(out, v);
      out += ' ';
    }
  for (const std::uint32_t v : m.corners) {
    append_number(out, v);
    out += ' ';
  }
  close_array(out);

  open_array(out, "Int64", "offsets");  // end of each cell in connectivity
  std::int64_t end = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) append_number(out, end += 3), out += ' ';
  for (std::size_t e = 0; e < m.edges.size(); ++e) append_number(out, end += 2), out += ' ';
  for (std::size_t c = 0; c < m.corners.size(); ++c) append_number(out, end += 1), out += ' ';
  close_array(out);

  open_array(out, "UInt8", "types");
  for (std::size_t t = 0; t < m.triangles.size(); ++t) append_number(out, kVtkTriangle), out += ' ';
  for (std::size_t e = 0; e < m.edges.size(); ++e) append_number(out, kVtkLine), out += ' ';
  for (std::size_t c = 0; c < m.corners.size(); ++c) append_number(out, kVtkVertex), out += ' ';
  close_array(out);
  out += "      </Cells>\n      <CellData Scalars=\"patch\">\n";

  const auto none = [](std::size_t) { return std::int32_t{-1}; };
  cell_array(
      out, "patch", m,
      [&](std::size_t t) { return m.triangle_patch.empty() ? std::int32_t{-1} : m.triangle_patch[t]; },
      none, -1);
  cell_array(
      out, "curve", m, none,
      [&](std::size_t e) { return m.edge_curve.empty() ? std::int32_t{-1} : m.edge_curve[e]; }, -1);
  cell_array(
      out, "dimension", m, [](std::size_t) { return std::int32_t{2}; },
      [](std::size_t) { return std::int32_t{1}; }, 0);
  out += "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace delpsc::io::detail
