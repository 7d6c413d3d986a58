// A picture of a surface mesh without a viewer: an SVG file a browser (or a README) shows.
//
// Orthographic view from a fixed oblique direction (from front-right-above, so that three sides
// of a box are seen), the painter's algorithm: triangles sorted by the depth of their centroid
// and drawn back to front, each filled with the colour of its patch (a fixed palette of 12,
// patch id modulo 12; grey when unlabelled) times a two-sided Lambert factor (sheets are seen
// from both sides). Feature edges (mesh.edges) are drawn dark and thicker, and corners as dots,
// in the same depth order, just in front of the triangles around them: hidden ones stay hidden.
// The painter's algorithm is exact for meshes whose triangles do not overlap cyclically in
// depth, good enough for a preview otherwise. A title line is written at the top.
//
// Back faces of closed components are left out (hidden_faces.h). Cost: O(T log T) for T
// triangles; about 90 bytes of SVG per triangle drawn (coordinates rounded to 0.1 px), so about
// 4.5 MB for a closed 100,000-triangle mesh.
#pragma once

#include <string>

#include "surface_mesh.h"

namespace delpsc::io {

struct PreviewOptions {
  /// Picture width in pixels (>= 64); the height follows from the model's projected extent,
  /// at most twice the width.
  int width = 800;
  /// The first line of the picture and the SVG <title> (escaped for XML).
  std::string title = "delpsc";
  /// Direction from the model towards the viewer; need not be unit length, must not be zero
  /// nor vertical (the picture's up is the projection of +z).
  Vec3 toward_viewer = Vec3(0.55, -1.0, 0.75);
  /// Leave out the triangles hidden_back_faces() proves invisible (back faces of closed,
  /// consistently oriented components): about half the file for a closed model, same picture.
  bool skip_hidden_back_faces = true;
  /// Outline each triangle in a darker shade of its fill, so the triangulation shows (for
  /// meshes; the feature preview leaves it off). Applied only when the triangles drawn are
  /// 12 px² or larger on average: finer meshes would turn into dark noise.
  bool outline_triangles = false;
};

/// The SVG document. Throws io::Error when the mesh breaks the SurfaceMesh invariants, or
/// std::invalid_argument for options outside their ranges.
std::string format_preview_svg(const SurfaceMesh& mesh, const PreviewOptions& options = {});

/// Writes format_preview_svg(mesh, options) to `path`; io::Error naming the file on failure.
void write_preview_svg(const std::string& path, const SurfaceMesh& mesh, const PreviewOptions& options = {});

}  // namespace delpsc::io
