// The delpsc command: one program, one subcommand per job (see README and `delpsc --help`).
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "command.h"
#include "json_writer.h"
#include "output_paths.h"
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
    // One mechanism for every subcommand: its key=value lines are recorded (report.h) and main
    // writes them as JSON at the end, whatever the exit code.
    sub->add_option("--report", global.report_path,
                    "Also write the final report as a JSON object to this file (keys as on stdout, plus "
                    "command, input, exit_code, error and structured parts)");
  };
  add("info", "Model statistics: counts, bounding box, defects", register_info);
  add("features", "Find the corners, curves and patches of a polygon model", register_features);
  add("protect", "Protect the feature curves with balls (DelPSC Protect)", register_protect);
  add("mesh", "Mesh a polygon model with DelPSC: protecting balls, then restricted Delaunay refinement", register_mesh);
  add("triangulate", "Build the 3D regular triangulation of a weighted point set", register_triangulate);

  // A usage error as every other error: "delpsc: " first, exit 2, and the JSON report when
  // --report is given. Option values are stored only once parsing succeeds, so --report is
  // looked up in argv; it is written only where check_output_path allows and where it names no
  // file given elsewhere on the line (a usage error must not overwrite the input with a report).
  const auto usage_failure = [&](const std::string& error) {
    std::fprintf(stderr, "delpsc: %s\n", error.c_str());
    int at = -1;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--report" && i + 1 < argc) global.report_path = argv[i + 1], at = i + 1;
      if (arg.starts_with("--report=")) global.report_path = arg.substr(9), at = i;
    }
    if (global.report_path.empty() || global.report_path.starts_with("-")) return kBadInput;
    try {
      check_output_path(global.report_path, "--report");
    } catch (const Failure&) {
      return kBadInput;
    }
    std::error_code ec;
    for (int i = 1; i < argc; ++i)
      if (i != at && std::filesystem::equivalent(global.report_path, argv[i], ec)) return kBadInput;
    final_report().add_json("exit_code", std::to_string(kBadInput));
    final_report().add_json("error", json_string(error));
    (void)final_report().write_json(global.report_path);
    return kBadInput;
  };
  // A first word that is no option and no command: say which commands there are (CLI11 said
  // only "A subcommand is required").
  if (argc > 1 && argv[1][0] != '-') {
    const std::string word = argv[1];
    if (std::none_of(commands.begin(), commands.end(), [&](const auto& c) { return c.first->get_name() == word; }))
      return usage_failure("unknown command '" + word +
                           "'; the commands are info, features, protect, mesh and triangulate (delpsc --help)");
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e) == 0 ? kOk : kBadInput;  // --help, --version
    return usage_failure(std::string(e.what()) + " (--help lists the options)");
  }
  int code = kOk;
  std::string error;
  try {
    if (!global.report_path.empty()) check_output_path(global.report_path, "--report");
    for (auto& [sub, run] : commands)
      if (sub->parsed()) {
        std::vector<std::pair<std::string, std::string>> files;  // --report first: see check_distinct_files
        for (const std::string name : {"--report", "--output", "--balls", "--preview", "IN"})
          if (const CLI::Option* file = sub->get_option_no_throw(name); file && file->count() > 0)
            files.emplace_back(name == "IN" ? "the input" : name == "--output" ? "-o" : name, file->as<std::string>());
        check_distinct_files(files);
        final_report().add_json("command", json_string(sub->get_name()));
        final_report().add_json("version", json_string(delpsc::kVersion));
        if (const CLI::Option* in = sub->get_option_no_throw("IN"); in && in->count() > 0)
          final_report().add_json("input", json_string(in->as<std::string>()));
        code = run(global);
      }
  } catch (const Failure& f) {
    error = f.message, code = f.code;
  } catch (const std::bad_alloc&) {
    error = "out of memory: the job needs more than this machine (or its limits) gives; a larger --size, or a "
            "--max-vertices cap, bounds a mesh's memory",
    code = kBadInput;  // the job as asked: like impossible parameters, not a run stopped early
  } catch (const std::exception& e) {
    error = std::string("internal error: ") + e.what(), code = kInternalError;
  }
  if (!error.empty()) std::fprintf(stderr, "delpsc: %s\n", error.c_str());
  // A report is written even when the job failed (exit_code and error say how), except when
  // --report itself is what is wrong.
  if (!global.report_path.empty() && !error.starts_with("--report")) {
    final_report().add_json("exit_code", std::to_string(code));
    if (!error.empty()) final_report().add_json("error", json_string(error));
    if (!final_report().write_json(global.report_path)) {
      std::fprintf(stderr, "delpsc: --report %s: write failed\n", global.report_path.c_str());
      return kBadInput;
    }
  }
  return code;
}
