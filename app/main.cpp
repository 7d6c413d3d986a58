// The delpsc command: one program, one subcommand per job (see README).
#include <CLI/CLI.hpp>

#include <cstdio>

#include "version.h"

int main(int argc, char** argv) {
  CLI::App app{"delpsc — Delaunay meshing of piecewise smooth complexes (DelPSC, Dey & Levine)"};
  app.set_version_flag("--version", std::string("delpsc ") + delpsc::kVersion);
  app.require_subcommand(0, 1);
  CLI11_PARSE(app, argc, argv);
  if (argc == 1) std::fputs(app.help().c_str(), stdout);
  return 0;
}
