// `delpsc features`: the piecewise smooth complex found in a polygon model (issue 4).
#include <chrono>
#include <delpsc/io/mesh_writer.h>
#include <delpsc/io/preview_svg.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/complex_mesh.h>
#include <stdexcept>

#include "command.h"
#include "model_input.h"
#include "output_paths.h"
#include "stl_precision.h"

namespace delpsc::app {

namespace {

struct FeaturesOptions {
  std::string input;
  std::string output;
  std::string preview;
  double angle = 60;
  double corner_angle = 60;
};

int run(const FeaturesOptions& o, const GlobalOptions& g) {
  if (!o.output.empty() && !io::mesh_format_from_path(o.output))
    throw Failure{kBadInput, "-o " + o.output + ": unknown output format (use .vtu, .mesh, .off, .obj, .ply or .stl)"};
  if (!o.output.empty()) check_output_path(o.output, "-o");  // before the work, as mesh does
  if (!o.preview.empty()) check_preview_path(o.preview);
  const io::ReadResult model = load_model(o.input, g);
  const auto t0 = std::chrono::steady_clock::now();
  const protect::Complex complex = load_complex(model, o.input, o.angle, o.corner_angle, g);
  reject_self_intersections(complex, o.input);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  reject_empty_complex(complex, model, o.input, "mesh");

  report("triangles", complex.triangles.size());
  report("zero_area_triangles", complex.cleanup.zero_area_triangles.size());
  report("flat_caps", complex.cleanup.flat_caps.size());
  report("corners", complex.corner_vertex.size());
  report("curves", complex.curves.size());
  report("closed_curves", complex.closed_curve_count());
  report("patches", complex.patches.size());
  report("patches_without_boundary", complex.patches_without_boundary());
  report("pinched_vertices", complex.pinches.size());
  report("seconds", seconds);
  if (g.verbosity > 0) {
    for (std::size_t p = 0; p < complex.patches.size(); ++p)
      std::fprintf(stderr, "patch %zu: euler=%d boundary_loops=%u\n", p,
                   complex.patches[p].euler_characteristic, complex.patches[p].boundary_loops);
  }
  if (!o.output.empty() || !o.preview.empty()) {
    io::SurfaceMesh mesh = protect::to_surface_mesh(complex);
    move_to_file_frame(mesh.vertices);
    try {
      if (!o.output.empty()) {
        refuse_stl_that_collapses(o.output, mesh);
        io::write_mesh(o.output, mesh);
      }
      if (!o.preview.empty()) {
        io::PreviewOptions preview;
        preview.title = o.input + ": " + std::to_string(complex.corner_count()) + " corners, " +
                        std::to_string(complex.curve_count()) + " curves, " +
                        std::to_string(complex.patch_count()) + " patches (feature angle " +
                        std::to_string(static_cast<int>(o.angle)) + "°)";
        io::write_preview_svg(o.preview, mesh, preview);
      }
    } catch (const io::Error& e) {
      throw Failure{kBadInput, e.what()};
    }
  }
  return kOk;
}

}  // namespace

Runner register_features(CLI::App& app) {
  auto o = std::make_shared<FeaturesOptions>();
  add_model_input(app, o->input);
  add_feature_angles(app, o->angle, o->corner_angle);
  app.add_option("-o,--output", o->output,
                 "Write the complex (patches and curves labelled): .vtu for ParaView, .mesh (Medit), or .off, .obj, .ply, "
                 ".stl (triangles only)");
  app.add_option("--preview", o->preview,
                 "Draw the complex to an SVG picture: patches coloured and shaded, curves and corners dark");
  app.footer(
      "Prints key=value lines: triangles, zero_area_triangles, flat_caps (triangles with an angle within 1e-4 radians of 180 degrees, split away like zero-area ones), corners, curves, closed_curves, "
      "patches, patches_without_boundary, pinched_vertices (where a patch touches itself only at a vertex), seconds.\n\nExample:\n"
      "  delpsc features fandisk.off --angle 60 -o fandisk-features.vtu\n"
      "  delpsc features samples/part.off --preview part-features.svg");
  return [o](const GlobalOptions& g) { return run(*o, g); };
}

}  // namespace delpsc::app
