// The delpsc command: one program, one subcommand per job (see README and `delpsc --help`).
#include <cstdio>
#include <exception>
#include <vector>

#include "command.h"
#include "version.h"

using namespace delpsc::app;

int main(int argc, char** argv) {
  CLI::App app{"delpsc — Delaunay meshing of piecewise smooth complexes (DelPSC, Dey & Levine)"};
  app.set_version_flag("--version", std::string("delpsc ") + delpsc::kVersion);
  GlobalOptions global;
  app.add_flag("-q,--quiet", global.quiet, "Print only the key=value report and errors");
  app.add_flag("-v,--verbose", global.verbosity, "More detail on stderr (repeatable)");
  app.require_subcommand(1);
  app.fallthrough();

  std::vector<std::pair<CLI::App*, Runner>> commands;
  auto add = [&](const char* name, const char* about, Runner (*reg)(CLI::App&)) {
    CLI::App* sub = app.add_subcommand(name, about);
    commands.emplace_back(sub, reg(*sub));
  };
  add("info", "Model statistics: counts, bounding box, defects", register_info);
  add("features", "Find the corners, curves and patches of a polygon model", register_features);
  add("protect", "Protect the feature curves with balls (DelPSC Protect)", register_protect);
  add("mesh", "Mesh a polygon model with DelPSC: protecting balls, then restricted Delaunay refinement", register_mesh);
  add("triangulate", "Build the 3D regular triangulation of a weighted point set", register_triangulate);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kOk : kBadInput;  // --help and --version exit 0; usage errors exit 2
  }
  try {
    for (auto& [sub, run] : commands)
      if (sub->parsed()) return run(global);
  } catch (const Failure& f) {
    std::fprintf(stderr, "delpsc: %s\n", f.message.c_str());
    return f.code;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "delpsc: out of memory\n");
    return kCheckFailed;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "delpsc: internal error: %s\n", e.what());
    return kCheckFailed;
  }
  return kOk;
}
