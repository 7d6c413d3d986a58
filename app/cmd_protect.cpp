// `delpsc protect`: the protecting balls of a polygon model's feature curves (issue 5).
#include <chrono>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <unordered_map>

#include <delpsc/io/error.h>
#include <delpsc/io/output_file.h>
#include <delpsc/protect/ball_checker.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/protect.h>

#include "input_defects.h"
#include "command.h"
#include "model_input.h"
#include "output_paths.h"
#include "size_limits.h"
#include "size_option.h"
#include "time_limit.h"

namespace delpsc::app {

namespace {

struct ProtectCommandOptions {
  std::string input;
  std::string size;
  double angle = 60;
  double corner_angle = 60;
  std::string balls_path;
  std::string vtu_path;
  bool check = false;
  double max_seconds = 0;  // 0: no limit
};

bool ends_with_vtu(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".vtu";
}

void write_file(const std::string& path, const std::string& contents) {
  try {
    io::write_output_file(path, contents);
  } catch (const io::Error& e) {
    throw Failure{kBadInput, e.what()};
  }
}

void append_number(std::string& out, double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g ", x);
  out += buffer;
}

/// The balls for ParaView: one point per ball with point data "radius", "curve" (-1 for corner
/// balls) and "corner" (-1 for curve balls), a vertex cell per ball and a line cell per pair of
/// adjacent balls (cell data "curve"). Glyph the points by "radius" (scale factor 2: the sphere
/// source has diameter 1) to see the balls.
std::string balls_vtu(const protect::BallSet& balls) {
  const protect::Complex& complex = balls.complex();
  const std::vector<protect::BallId> ids = balls.live_ids();
  std::unordered_map<protect::BallId, std::size_t> index;
  for (std::size_t i = 0; i < ids.size(); ++i) index[ids[i]] = i;
  std::vector<std::array<std::size_t, 2>> lines;
  std::vector<std::uint32_t> line_curve;
  for (std::uint32_t c = 0; c < complex.curve_count(); ++c) {
    const auto seq = balls.curve_sequence(c);
    for (std::size_t i = 0; i + 1 < seq.size(); ++i) {
      lines.push_back({index.at(seq[i].id), index.at(seq[i + 1].id)});
      line_curve.push_back(c);
    }
  }
  std::string out =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" +
      std::to_string(ids.size()) + "\" NumberOfCells=\"" + std::to_string(ids.size() + lines.size()) +
      "\">\n      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const protect::BallId id : ids)
    for (int k = 0; k < 3; ++k) append_number(out, in_file_frame(balls[id].centre)[k]);
  out += "\n        </DataArray>\n      </Points>\n      <PointData Scalars=\"radius\">\n"
         "        <DataArray type=\"Float64\" Name=\"radius\" format=\"ascii\">\n";
  for (const protect::BallId id : ids) append_number(out, balls[id].radius);
  out += "\n        </DataArray>\n        <DataArray type=\"Int32\" Name=\"curve\" format=\"ascii\">\n";
  for (const protect::BallId id : ids) out += std::to_string(balls[id].is_corner() ? -1 : std::int64_t(balls[id].curve)) + " ";
  out += "\n        </DataArray>\n        <DataArray type=\"Int32\" Name=\"corner\" format=\"ascii\">\n";
  for (const protect::BallId id : ids) out += std::to_string(balls[id].is_corner() ? std::int64_t(balls[id].corner) : -1) + " ";
  out += "\n        </DataArray>\n      </PointData>\n      <Cells>\n"
         "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < ids.size(); ++i) out += std::to_string(i) + " ";
  for (const auto& l : lines) out += std::to_string(l[0]) + " " + std::to_string(l[1]) + " ";
  out += "\n        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::size_t end = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) out += std::to_string(end += 1) + " ";
  for (std::size_t i = 0; i < lines.size(); ++i) out += std::to_string(end += 2) + " ";
  out += "\n        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < ids.size(); ++i) out += "1 ";  // VTK_VERTEX
  for (std::size_t i = 0; i < lines.size(); ++i) out += "3 ";  // VTK_LINE
  out += "\n        </DataArray>\n      </Cells>\n      <CellData Scalars=\"curve\">\n"
         "        <DataArray type=\"Int32\" Name=\"curve\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < ids.size(); ++i) out += "-1 ";
  for (const std::uint32_t c : line_curve) out += std::to_string(c) + " ";
  out += "\n        </DataArray>\n      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

int run(const ProtectCommandOptions& o, const GlobalOptions& g) {
  const TimeLimit time_limit(o.max_seconds);
  if (!o.vtu_path.empty() && !ends_with_vtu(o.vtu_path))
    throw Failure{kBadInput, "-o " + o.vtu_path + ": the balls are written as .vtu (ParaView)"};
  // Before the work, as mesh does: a missing directory fails at once, not after Protect.
  if (!o.vtu_path.empty()) check_output_path(o.vtu_path, "-o");
  if (!o.balls_path.empty()) check_output_path(o.balls_path, "--balls");
  const io::ReadResult model = load_model(o.input, g, &time_limit);
  protect::Complex complex = load_complex(model, o.input, o.angle, o.corner_angle, g);
  reject_self_intersections(complex, o.input, &time_limit);
  reject_empty_complex(complex, model, o.input, "protect");

  const double diagonal = protect::BallSet(complex).diagonal();
  const double lambda = parse_size(o.size, diagonal);
  reject_size_for_balls(complex, lambda, protect::ProtectOptions{}.max_balls, o.size);
  time_limit.check_before(o.input, "protection");
  protect::ProtectStats stats;
  const auto t0 = std::chrono::steady_clock::now();
  std::optional<protect::BallSet> balls;
  protect::ProtectOptions options = protect::options_for_size(lambda, diagonal);  // as mesh
  options.stop = time_limit.poll();
  try {
    balls.emplace(protect::protect(complex, lambda, options, &stats));
  } catch (const protect::ProtectionStopped& e) {
    throw Failure{kCheckFailed, o.input + ": " + time_limit.stopped() + ": " + e.what() + "; nothing written"};
  } catch (const protect::ProtectionError& e) {
    const std::string defect = input_defect_near(complex, e.where(), lambda);
    throw Failure{kBadInput, o.input + ": " + e.what() + (defect.empty() ? "" : "; " + defect)};
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const auto [min_radius, max_radius] = balls->radius_range();
  report("corners", complex.corner_count());
  report("curves", complex.curve_count());
  report("lambda", lambda);
  report("balls", balls->size());
  report("corner_balls", balls->corner_ball_count());
  report("min_radius", min_radius);
  report("max_radius", max_radius);
  report("seconds", seconds);
  if (g.verbosity > 0)
    std::fprintf(stderr, "delpsc: covers=%zu refined=%zu vertex_shrinks=%zu separate_rounds=%zu conflicts=%zu repairs=%zu\n",
                 stats.covers, stats.refined, stats.vertex_shrinks, stats.separate_rounds, stats.conflicts, stats.repairs);
  bool valid = true;
  if (o.check) {
    const protect::BallCheck check = protect::check_balls(*balls);
    valid = check.ok();
    report("valid", valid);
    for (const auto& p : check.problems) std::fprintf(stderr, "delpsc: %s\n", p.c_str());
  }
  if (!o.balls_path.empty()) write_file(o.balls_path, protect::balls_to_text(*balls, model_offset()));
  if (!o.vtu_path.empty()) write_file(o.vtu_path, balls_vtu(*balls));
  return valid ? kOk : kCheckFailed;
}

}  // namespace

Runner register_protect(CLI::App& app) {
  auto o = std::make_shared<ProtectCommandOptions>();
  add_model_input(app, o->input);
  app.add_option("--size", o->size,
                 "λ, the largest ball radius: a length, or a percentage of the bounding-box diagonal (1%)")
      ->required();
  add_feature_angles(app, o->angle, o->corner_angle);
  app.add_option("--balls", o->balls_path,
                 "Write the balls as text: 'corner ID X Y Z R' lines, then per curve "
                 "'curve ID START END N' and its N interior balls 'X Y Z R' in order");
  app.add_option("-o,--output", o->vtu_path, "Write the balls as .vtu for ParaView (glyph by radius)");
  app.add_flag("--check", o->check, "Check C1, C2, C3.a, C3.b and coverage; exit 1 if one fails");
  add_max_seconds_option(app, o->max_seconds, "nothing is written then");
  app.footer(
      "Prints key=value lines: corners, curves, lambda, balls, corner_balls, min_radius, max_radius, "
      "seconds (protection only), valid (--check). Exit code 1 when --check fails or --max-seconds stops the run.\n\nExample:\n"
      "  delpsc protect fandisk.off --size 1% --balls fandisk-balls.txt -o fandisk-balls.vtu");
  return [o](const GlobalOptions& g) { return run(*o, g); };
}

}  // namespace delpsc::app
